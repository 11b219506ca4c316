#include "border_outputs.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/io/map_io.hpp"

namespace indoormap::app {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json xy(const Eigen::Vector2d& p) {
  return {p.x(), p.y()};
}

json ring_json(const indoormap::Polygon& poly) {
  json ring = json::array();
  for (const auto& v : poly) ring.push_back(xy(v));
  if (!poly.empty()) ring.push_back(xy(poly.front()));  // GeoJSON rings repeat the first vertex
  return ring;
}

json opening_json(const border::Opening& o) {
  return {{"a_m", xy(o.a_m)},
          {"b_m", xy(o.b_m)},
          {"width_m", o.width_m},
          {"door_candidate", o.is_door_candidate},
          {"chain_first", o.chain_first},
          {"chain_last", o.chain_last}};
}

json object_json(const border::InteriorObject& o) {
  return {{"min_m", xy(o.min_m)},
          {"max_m", xy(o.max_m)},
          {"min_cell", {o.min.col, o.min.row}},
          {"max_cell", {o.max.col, o.max.row}},
          {"cells", o.cells},
          {"kind", std::string(border::to_string(o.kind))}};
}

json geojson(const border::BorderResult& r) {
  json features = json::array();
  if (r.closed) {
    features.push_back(
        {{"type", "Feature"},
         {"geometry",
          {{"type", "Polygon"}, {"coordinates", json::array({ring_json(r.polygon_m)})}}},
         {"properties",
          {{"kind", "room"}, {"area_m2", r.area_m2}, {"perimeter_m", r.perimeter_m}}}});
  }
  for (const auto& o : r.openings)
    features.push_back(
        {{"type", "Feature"},
         {"geometry", {{"type", "LineString"}, {"coordinates", {xy(o.a_m), xy(o.b_m)}}}},
         {"properties",
          {{"kind", "opening"}, {"width_m", o.width_m}, {"door_candidate", o.is_door_candidate}}}});
  for (const auto& o : r.interior_objects) {
    const indoormap::Polygon box{
        o.min_m, {o.max_m.x(), o.min_m.y()}, o.max_m, {o.min_m.x(), o.max_m.y()}};
    features.push_back(
        {{"type", "Feature"},
         {"geometry", {{"type", "Polygon"}, {"coordinates", json::array({ring_json(box)})}}},
         {"properties",
          {{"kind", "interior_object"},
           {"class", std::string(border::to_string(o.kind))},
           {"cells", o.cells}}}});
  }
  json fc = {{"type", "FeatureCollection"}, {"features", features}, {"closed", r.closed}};
  if (!r.closed) fc["reason"] = r.reason;
  return fc;
}

cv::Scalar colour_of(Cell c) {
  switch (c) {
    case Cell::kUnknown:
      return {170, 170, 170};
    case Cell::kWall:
      return {100, 40, 20};
    case Cell::kFurniture:
      return {0, 140, 255};
    case Cell::kFree:
      return {255, 255, 255};
  }
  return {255, 0, 255};
}

// The layout (north up) with the heavy border tinted, the chain, the polygon, the openings and
// the scanner; a legend and a 1 m scale bar below.
void write_border_png(const fs::path& path, const layout::MapResult& m,
                      const border::BorderResult& r) {
  const auto& lay = m.layout.layout;
  const auto& geo = m.geometry;
  const int w = std::max(lay.width, 1), h = std::max(lay.height, 1);
  int k = std::max(1, (640 + w - 1) / w);
  k = std::min(k, std::max(1, 4000 / std::max(w, h)));
  const int title_h = 28, legend_h = 70, img_w = std::max(w * k, 640);
  cv::Mat img(title_h + h * k + legend_h, img_w, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Scalar heavy_tint(200, 230, 200), chain_col(180, 0, 180), poly_col(0, 0, 0),
      door_col(0, 170, 0), gap_col(220, 160, 0), scanner_col(0, 0, 220), object_col(120, 60, 160);
  for (int row = 0; row < lay.height; ++row)
    for (int c = 0; c < lay.width; ++c) {
      cv::Scalar col = colour_of(lay.at(c, row));
      if (r.heavy.size() == lay.size() && r.heavy.at(c, row) && lay.at(c, row) == Cell::kUnknown)
        col = heavy_tint;
      cv::rectangle(img, cv::Rect(c * k, title_h + (h - 1 - row) * k, k, k), col, cv::FILLED);
    }
  auto to_px = [&](const Eigen::Vector2d& p) {
    const double cx = (p.x() - geo.origin_m().x()) / geo.cell_m();
    const double cy = (p.y() - geo.origin_m().y()) / geo.cell_m();
    return cv::Point(static_cast<int>(std::lround(cx * k)),
                     title_h + static_cast<int>(std::lround((h - cy) * k)));
  };
  for (const auto& o : r.interior_objects)
    cv::rectangle(img, to_px(o.min_m), to_px(o.max_m), object_col, 1);
  auto polyline = [&](const std::vector<Eigen::Vector2d>& pts, const cv::Scalar& col, int thick) {
    std::vector<cv::Point> px;
    for (const auto& p : pts) px.push_back(to_px(p));
    if (px.size() >= 2) cv::polylines(img, px, true, col, thick, cv::LINE_AA);
  };
  polyline(r.chain_m, chain_col, std::max(1, k / 2));
  polyline(r.polygon_m, poly_col, 1);
  for (const auto& o : r.openings)
    cv::line(img, to_px(o.a_m), to_px(o.b_m), o.is_door_candidate ? door_col : gap_col,
             std::max(3, k), cv::LINE_AA);
  const int arm = std::max(5, 2 * k);
  for (const auto& s : m.cloud_map.scanners) {
    const cv::Point p = to_px({s.x(), s.y()});
    cv::line(img, p - cv::Point(arm, arm), p + cv::Point(arm, arm), scanner_col, 2, cv::LINE_AA);
    cv::line(img, p - cv::Point(arm, -arm), p + cv::Point(arm, -arm), scanner_col, 2, cv::LINE_AA);
  }

  const auto font = cv::FONT_HERSHEY_SIMPLEX;
  char title[200];
  if (r.closed)
    std::snprintf(title, sizeof title, "room border: %.2f m2, perimeter %.2f m, %zu opening(s)",
                  r.area_m2, r.perimeter_m, r.openings.size());
  else
    std::snprintf(title, sizeof title, "no closed room border");
  cv::putText(img, title, {6, 20}, font, 0.55, {0, 0, 0}, 1, cv::LINE_AA);
  int x = 6, y0 = title_h + h * k + 8;
  auto item = [&](const std::string& label, auto&& draw) {
    if (x + 40 + static_cast<int>(label.size()) * 9 > img_w) {
      x = 6;
      y0 += 24;
    }
    draw(cv::Rect(x, y0, 16, 16));
    cv::putText(img, label, {x + 20, y0 + 13}, font, 0.45, {0, 0, 0}, 1, cv::LINE_AA);
    x += 28 + static_cast<int>(label.size()) * 9;
  };
  auto swatch = [&](const cv::Scalar& col) {
    return [&img, col](cv::Rect rc) {
      cv::rectangle(img, rc, col, cv::FILLED);
      cv::rectangle(img, rc, {0, 0, 0}, 1);
    };
  };
  auto stroke = [&](const cv::Scalar& col, int t) {
    return [&img, col, t](cv::Rect rc) {
      cv::line(img, {rc.x, rc.y + 8}, {rc.x + 16, rc.y + 8}, col, t, cv::LINE_AA);
    };
  };
  for (Cell c : {Cell::kWall, Cell::kFurniture, Cell::kFree, Cell::kUnknown})
    item(std::string(to_string(c)), swatch(colour_of(c)));
  item("heavy border", swatch(heavy_tint));
  item("chain", stroke(chain_col, 3));
  item("polygon", stroke(poly_col, 1));
  item("door candidate", stroke(door_col, 4));
  item("other opening", stroke(gap_col, 4));
  item("interior object", [&](cv::Rect rc) { cv::rectangle(img, rc, object_col, 1); });
  item("scanner", [&](cv::Rect rc) {
    const cv::Point p(rc.x + 8, rc.y + 8);
    cv::line(img, p - cv::Point(6, 6), p + cv::Point(6, 6), scanner_col, 2, cv::LINE_AA);
    cv::line(img, p - cv::Point(6, -6), p + cv::Point(6, -6), scanner_col, 2, cv::LINE_AA);
  });
  const int bar = static_cast<int>(std::lround(k / geo.cell_m()));
  if (bar > 4) {
    if (x + bar + 40 > img_w) {
      x = 6;
      y0 += 24;
    }
    cv::line(img, {x, y0 + 12}, {x + bar, y0 + 12}, {0, 0, 0}, 2);
    cv::putText(img, "1 m", {x + bar + 6, y0 + 16}, font, 0.45, {0, 0, 0}, 1, cv::LINE_AA);
  }
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", img, png)) throw OutputError(path.string(), "PNG encoding failed");
  write_file_atomic(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

}  // namespace

json write_border_outputs(const fs::path& out, const layout::MapResult& m,
                          const border::BorderResult& r, double ms) {
  json openings = json::array();
  int doors = 0;
  for (const auto& o : r.openings) {
    openings.push_back(opening_json(o));
    doors += o.is_door_candidate ? 1 : 0;
  }
  json objects = json::array();
  for (const auto& o : r.interior_objects) objects.push_back(object_json(o));
  json chain_cells = json::array(), chain_m = json::array(), polygon = json::array(),
       components = json::array();
  for (const auto& c : r.chain) chain_cells.push_back({c.col, c.row});
  for (const auto& p : r.chain_m) chain_m.push_back(xy(p));
  for (const auto& p : r.polygon_m) polygon.push_back(xy(p));
  for (const auto& c : r.components)
    components.push_back({{"label", c.label},
                          {"start_cell", {c.start.col, c.start.row}},
                          {"min_cell", {c.min.col, c.min.row}},
                          {"max_cell", {c.max.col, c.max.row}},
                          {"cells", c.cells},
                          {"switches", c.switches},
                          {"kind", std::string(border::to_string(c.kind))},
                          {"note", c.note}});
  const json room = {{"closed", r.closed},
                     {"reason", r.reason},
                     {"frame", "map"},
                     {"cell_m", m.geometry.cell_m()},
                     {"origin_m", xy(m.geometry.origin_m())},
                     {"scanner_m", xy(r.scanner_m)},
                     {"chain_cells", chain_cells},
                     {"chain_m", chain_m},
                     {"polygon_m", polygon},
                     {"area_m2", r.area_m2},
                     {"perimeter_m", r.perimeter_m},
                     {"openings", openings},
                     {"components", components},
                     {"interior_objects", objects},
                     {"warnings", r.warnings}};
  io::write_json(out / "room.json", room);
  write_file_atomic(out / "room.geojson", geojson(r).dump(2) + "\n");
  write_border_png(out / "border.png", m, r);

  if (!r.closed) std::cerr << "pcd-to-map: warning: no closed room border: " << r.reason << "\n";
  for (const auto& w : r.warnings) std::cerr << "pcd-to-map: warning: border: " << w << "\n";
  json block = {{"closed", r.closed},
                {"area_m2", r.area_m2},
                {"perimeter_m", r.perimeter_m},
                {"chain_cells", r.chain.size()},
                {"polygon_vertices", r.polygon_m.size()},
                {"openings", openings},
                {"door_candidates", doors},
                {"components", r.components.size()},
                {"interior_objects", r.interior_objects.size()},
                {"warnings", r.warnings},
                {"time_ms", ms},
                {"outputs", {"room.geojson", "room.json", "border.png"}}};
  if (!r.closed) block["reason"] = r.reason;
  return block;
}

}  // namespace indoormap::app
