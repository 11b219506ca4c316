#include "indoormap/io/route_io.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/io/map_io.hpp"

namespace indoormap::io {

using nlohmann::json;
using planning::SafeCell;

namespace {

json pose_json(const planning::Pose2& p, CellIndex cell) {
  return {{"x_m", p.position_map.x()},
          {"y_m", p.position_map.y()},
          {"heading_deg", p.heading_deg ? json(*p.heading_deg) : json(nullptr)},
          {"cell", {cell.col, cell.row}}};
}

}  // namespace

json route_json(const RouteReport& rep) {
  const auto& res = *rep.result;
  json routes = json::array();
  int rank = 1;
  for (const auto& r : res.routes) {
    json cmds = json::array(), wps = json::array();
    for (const auto& c : r.commands)
      cmds.push_back({{"turn_deg", c.turn_deg}, {"move_m", c.move_m}});
    for (const auto& p : r.waypoints_map) wps.push_back({p.x(), p.y()});
    routes.push_back({{"rank", rank++},
                      {"source", r.source},
                      {"moves", r.moves},
                      {"turns", r.turns},
                      {"length_m", r.length_m},
                      {"commands", cmds},
                      {"waypoints_map", wps}});
  }
  return {
      {"found", !res.routes.empty()},
      {"message", res.message},
      {"frame", "map (metres); headings in degrees counter-clockwise from +x; turn_deg > 0 = left"},
      {"start", pose_json(rep.start, res.start_cell)},
      {"goal", pose_json(rep.goal, res.goal_cell)},
      {"routes", routes},
      {"search",
       {{"paper_best_moves", res.paper_best_moves},
        {"exact_best_moves", res.exact_best_moves},
        {"exact_complete", res.exact_complete},
        {"paper_nodes", res.paper_nodes},
        {"exact_nodes", res.exact_nodes}}},
      {"parameters",
       {{"robot",
         {{"width_m", rep.robot.width_m},
          {"length_m", rep.robot.length_m},
          {"extra_m", rep.robot.extra_m}}},
        {"d_save_m", planning::d_save_m(rep.robot)},
        {"d_min_m", rep.params.d_min_m},
        {"d_max_m", rep.params.d_max_m},
        {"cell_m", rep.geometry.cell_m()},
        {"paper_rules", rep.params.paper_rules},
        {"exact_search", rep.params.exact_search},
        {"max_routes", rep.params.max_routes},
        {"extra_moves", rep.params.extra_moves},
        {"max_nodes", rep.params.max_nodes}}},
  };
}

void write_route_png(const std::filesystem::path& path, const RouteReport& rep) {
  const auto& safe = *rep.safe;
  const auto& res = *rep.result;
  const auto& geo = rep.geometry;
  const int w = std::max(safe.width, 1), h = std::max(safe.height, 1);
  int k = std::max(1, (640 + w - 1) / w);
  k = std::min(k, std::max(1, 4000 / std::max(w, h)));
  const int title_h = 28, legend_h = 70;
  const int img_w = std::max(w * k, 640);
  cv::Mat img(title_h + h * k + legend_h, img_w, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Scalar c_out(170, 170, 170), c_obst(100, 40, 20), c_unsafe(150, 150, 235),
      c_safe(255, 255, 255), c_region(170, 235, 170), c_route(0, 0, 200), c_alt(200, 120, 0);
  const bool has_region = res.region.width == safe.width && res.region.height == safe.height;
  for (int r = 0; r < safe.height; ++r)
    for (int c = 0; c < safe.width; ++c) {
      cv::Scalar col;
      switch (safe.at(c, r)) {
        case SafeCell::kOutside:
          col = c_out;
          break;
        case SafeCell::kObstacle:
          col = c_obst;
          break;
        case SafeCell::kUnsafe:
          col = c_unsafe;
          break;
        case SafeCell::kSafe:
          col = c_safe;
          break;
      }
      if (has_region && res.region.at(c, r)) col = c_region;
      cv::rectangle(img, cv::Rect(c * k, title_h + (h - 1 - r) * k, k, k), col, cv::FILLED);
    }
  auto to_px = [&](const Eigen::Vector2d& p) {
    const double cx = (p.x() - geo.origin_m().x()) / geo.cell_m();
    const double cy = (p.y() - geo.origin_m().y()) / geo.cell_m();
    return cv::Point(static_cast<int>(std::lround(cx * k)),
                     title_h + static_cast<int>(std::lround((h - cy) * k)));
  };
  const auto font = cv::FONT_HERSHEY_SIMPLEX;
  for (std::size_t i = res.routes.size(); i-- > 1;) {
    const auto& wp = res.routes[i].waypoints_map;
    for (std::size_t j = 1; j < wp.size(); ++j)
      cv::line(img, to_px(wp[j - 1]), to_px(wp[j]), c_alt, 1, cv::LINE_AA);
  }
  if (!res.routes.empty()) {
    const auto& wp = res.routes.front().waypoints_map;
    for (std::size_t j = 1; j < wp.size(); ++j)
      cv::line(img, to_px(wp[j - 1]), to_px(wp[j]), c_route, 2, cv::LINE_AA);
    // Turn points 1..n (the start is turn point 0 when the robot turns there).
    for (std::size_t j = 1; j + 1 < wp.size(); ++j) {
      const cv::Point p = to_px(wp[j]);
      cv::circle(img, p, 9, c_route, cv::FILLED, cv::LINE_AA);
      const std::string s = std::to_string(j);
      cv::putText(img, s, p + cv::Point(s.size() > 1 ? -8 : -4, 4), font, 0.38, {255, 255, 255}, 1,
                  cv::LINE_AA);
    }
  }
  auto marker = [&](const planning::Pose2& pose, const cv::Scalar& col) {
    const cv::Point p = to_px(pose.position_map);
    cv::circle(img, p, 6, col, 2, cv::LINE_AA);
    if (pose.heading_deg) {
      const double a = *pose.heading_deg * CV_PI / 180.0;
      cv::arrowedLine(img, p,
                      p + cv::Point(static_cast<int>(std::lround(18 * std::cos(a))),
                                    -static_cast<int>(std::lround(18 * std::sin(a)))),
                      col, 2, cv::LINE_AA, 0, 0.35);
    }
  };
  marker(rep.start, {0, 150, 0});
  marker(rep.goal, {160, 0, 160});

  std::string title = "route: ";
  if (res.routes.empty()) {
    title += "none (" + res.message + ")";
  } else {
    const auto& b = res.routes.front();
    char buf[160];
    std::snprintf(buf, sizeof buf, "%d moves, %d turns, %.2f m; d_save %.2f m, D %.2f-%.2f m",
                  b.moves, b.turns, b.length_m, planning::d_save_m(rep.robot), rep.params.d_min_m,
                  rep.params.d_max_m);
    title += buf;
  }
  cv::putText(img, title, {6, 20}, font, 0.5, {0, 0, 0}, 1, cv::LINE_AA);

  int x = 6, y0 = title_h + h * k + 10;
  auto swatch = [&](const cv::Scalar& col, const std::string& label) {
    if (x + 30 + static_cast<int>(label.size()) * 8 > img_w) x = 6, y0 += 26;
    cv::rectangle(img, cv::Rect(x, y0, 16, 16), col, cv::FILLED);
    cv::rectangle(img, cv::Rect(x, y0, 16, 16), {0, 0, 0}, 1);
    cv::putText(img, label, {x + 20, y0 + 13}, font, 0.42, {0, 0, 0}, 1, cv::LINE_AA);
    x += 28 + static_cast<int>(label.size()) * 8;
  };
  swatch(c_safe, "safe");
  swatch(c_unsafe, "unsafe");
  swatch(c_obst, "obstacle");
  swatch(c_out, "outside");
  swatch(c_region, "trajectory region");
  swatch(c_route, "best route, turns 1..n");
  swatch(c_alt, "other routes");
  swatch({0, 150, 0}, "start");
  swatch({160, 0, 160}, "goal");
  const int bar = static_cast<int>(std::lround(k / geo.cell_m()));
  if (x + bar + 40 > img_w) x = 6, y0 += 26;
  if (bar > 4 && x + bar + 40 < img_w) {
    cv::line(img, {x, y0 + 12}, {x + bar, y0 + 12}, {0, 0, 0}, 2);
    cv::putText(img, "1 m", {x + bar + 6, y0 + 16}, font, 0.42, {0, 0, 0}, 1, cv::LINE_AA);
  }
  std::vector<uchar> png;
  if (!cv::imencode(".png", img, png, {cv::IMWRITE_PNG_COMPRESSION, 9}))
    throw OutputError(path.string(), "PNG encoding failed");
  write_file_atomic(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

void write_safe_map(const std::filesystem::path& dir, const Grid<SafeCell>& safe,
                    const GridGeometry& geometry) {
  Grid<Cell> cells(safe.width, safe.height, Cell::kUnknown);
  for (std::size_t i = 0; i < safe.size(); ++i)
    cells.data[i] = safe.data[i] == SafeCell::kSafe      ? Cell::kFree
                    : safe.data[i] == SafeCell::kOutside ? Cell::kUnknown
                                                         : Cell::kWall;
  write_ros_map(dir, "safe", cells, geometry);
}

std::vector<std::string> write_route_outputs(const std::filesystem::path& dir,
                                             const RouteReport& rep) {
  if (!rep.safe || !rep.result) throw Error("write_route_outputs: incomplete report");
  write_json(dir / "route.json", route_json(rep));
  write_route_png(dir / "route.png", rep);
  write_safe_map(dir, *rep.safe, rep.geometry);
  return {"route.json", "route.png", "safe.pgm", "safe.yaml"};
}

}  // namespace indoormap::io
