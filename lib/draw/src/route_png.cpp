#include "indoormap/draw/route_png.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <string>

#include "font.hpp"
#include "indoormap/draw/canvas.hpp"
#include "indoormap/draw/palette.hpp"

namespace indoormap::draw {

using planning::SafeCell;

namespace {

// Outside the map and obstacles take the palette's unknown and wall colours.
const cv::Scalar c_out = cell_colour(Cell::kUnknown), c_obst = cell_colour(Cell::kWall),
                 c_unsafe(150, 150, 235), c_safe(255, 255, 255), c_region(170, 235, 170),
                 c_route(0, 0, 200), c_alt(200, 120, 0), c_start(0, 150, 0), c_goal(160, 0, 160);

void draw_cells(cv::Mat& img, const PixelFrame& frame, const Grid<SafeCell>& safe,
                const planning::PlanResult& res) {
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
      cv::rectangle(img, frame.cell_rect(c, r), col, cv::FILLED);
    }
}

void draw_routes(cv::Mat& img, const PixelFrame& frame, const planning::PlanResult& res) {
  for (std::size_t i = res.routes.size(); i-- > 1;) {
    const auto& wp = res.routes[i].waypoints_map;
    for (std::size_t j = 1; j < wp.size(); ++j)
      cv::line(img, frame.to_px(wp[j - 1]), frame.to_px(wp[j]), c_alt, 1, cv::LINE_AA);
  }
  if (res.routes.empty()) return;
  const auto& wp = res.routes.front().waypoints_map;
  for (std::size_t j = 1; j < wp.size(); ++j)
    cv::line(img, frame.to_px(wp[j - 1]), frame.to_px(wp[j]), c_route, 2, cv::LINE_AA);
  // Turn points 1..n (the start is turn point 0 when the robot turns there).
  for (std::size_t j = 1; j + 1 < wp.size(); ++j) {
    const cv::Point p = frame.to_px(wp[j]);
    cv::circle(img, p, 9, c_route, cv::FILLED, cv::LINE_AA);
    const std::string s = std::to_string(j);
    cv::putText(img, s, p + cv::Point(s.size() > 1 ? -8 : -4, 4), kFont, 0.38, {255, 255, 255}, 1,
                cv::LINE_AA);
  }
}

void draw_pose(cv::Mat& img, const PixelFrame& frame, const planning::Pose2& pose,
               const cv::Scalar& col) {
  const cv::Point p = frame.to_px(pose.position_map);
  cv::circle(img, p, 6, col, 2, cv::LINE_AA);
  if (pose.heading_deg) {
    const double a = *pose.heading_deg * CV_PI / 180.0;
    cv::arrowedLine(img, p,
                    p + cv::Point(static_cast<int>(std::lround(18 * std::cos(a))),
                                  -static_cast<int>(std::lround(18 * std::sin(a)))),
                    col, 2, cv::LINE_AA, 0, 0.35);
  }
}

std::string route_title(const formats::RouteReport& rep) {
  const auto& res = *rep.result;
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
  return title;
}

}  // namespace

void write_route_png(const std::filesystem::path& path, const formats::RouteReport& rep) {
  const auto& safe = *rep.safe;
  const auto& res = *rep.result;
  const auto& geo = rep.geometry;
  const int w = std::max(safe.width, 1), h = std::max(safe.height, 1);
  const int k = pixels_per_cell(w, h, 640);
  const int title_h = 28, legend_h = 70;
  const int img_w = std::max(w * k, 640);
  cv::Mat img(title_h + h * k + legend_h, img_w, CV_8UC3, cv::Scalar(255, 255, 255));
  const PixelFrame frame{geo, k, title_h, h};
  draw_cells(img, frame, safe, res);
  draw_routes(img, frame, res);
  draw_pose(img, frame, rep.start, c_start);
  draw_pose(img, frame, rep.goal, c_goal);
  cv::putText(img, route_title(rep), {6, 20}, kFont, 0.5, {0, 0, 0}, 1, cv::LINE_AA);

  LegendStyle style;
  style.font_scale = 0.42;
  style.char_px = 8;
  style.gap_px = 28;
  style.wrap_reserve_px = 30;
  style.row_px = 26;
  Legend legend(img, title_h + h * k + 10, style);
  legend.swatch(c_safe, "safe");
  legend.swatch(c_unsafe, "unsafe");
  legend.swatch(c_obst, "obstacle");
  legend.swatch(c_out, "outside");
  legend.swatch(c_region, "trajectory region");
  legend.swatch(c_route, "best route, turns 1..n");
  legend.swatch(c_alt, "other routes");
  legend.swatch(c_start, "start");
  legend.swatch(c_goal, "goal");
  legend.scale_bar(static_cast<int>(std::lround(k / geo.cell_m())));
  write_png(path, img, 9);
}

}  // namespace indoormap::draw
