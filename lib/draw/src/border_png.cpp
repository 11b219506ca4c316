#include "indoormap/draw/border_png.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <string>

#include "font.hpp"
#include "indoormap/draw/canvas.hpp"
#include "indoormap/draw/palette.hpp"

namespace indoormap::draw {

namespace {

const cv::Scalar heavy_tint(200, 230, 200), chain_col(180, 0, 180), poly_col(0, 0, 0),
    door_col(0, 170, 0), gap_col(220, 160, 0), scanner_col(0, 0, 220), object_col(120, 60, 160);

void draw_border(cv::Mat& img, const PixelFrame& frame, const layout::MapResult& m,
                 const border::BorderResult& r) {
  const int k = frame.scale_px;
  for (const auto& o : r.interior_objects)
    cv::rectangle(img, frame.to_px(o.min_m), frame.to_px(o.max_m), object_col, 1);
  auto polyline = [&](const std::vector<Eigen::Vector2d>& pts, const cv::Scalar& col, int thick) {
    std::vector<cv::Point> px;
    for (const auto& p : pts) px.push_back(frame.to_px(p));
    if (px.size() >= 2) cv::polylines(img, px, true, col, thick, cv::LINE_AA);
  };
  polyline(r.chain_m, chain_col, std::max(1, k / 2));
  polyline(r.polygon_m, poly_col, 1);
  for (const auto& o : r.openings)
    cv::line(img, frame.to_px(o.a_m), frame.to_px(o.b_m), o.is_door_candidate ? door_col : gap_col,
             std::max(3, k), cv::LINE_AA);
  const int arm = std::max(5, 2 * k);
  for (const auto& s : m.cloud_map.scanners)
    draw_cross(img, frame.to_px({s.x(), s.y()}), arm, scanner_col);
}

}  // namespace

void write_border_png(const std::filesystem::path& path, const layout::MapResult& m,
                      const border::BorderResult& r) {
  const auto& lay = m.layout.layout;
  const auto& geo = m.geometry;
  const int w = std::max(lay.width, 1), h = std::max(lay.height, 1);
  const int k = pixels_per_cell(w, h, 640);
  const int title_h = 28, legend_h = 70, img_w = std::max(w * k, 640);
  cv::Mat img(title_h + h * k + legend_h, img_w, CV_8UC3, cv::Scalar(255, 255, 255));
  const PixelFrame frame{geo, k, title_h, h};
  for (int row = 0; row < lay.height; ++row)
    for (int c = 0; c < lay.width; ++c) {
      cv::Scalar col = cell_colour(lay.at(c, row));
      if (r.heavy.size() == lay.size() && r.heavy.at(c, row) && lay.at(c, row) == Cell::kUnknown)
        col = heavy_tint;
      cv::rectangle(img, frame.cell_rect(c, row), col, cv::FILLED);
    }
  draw_border(img, frame, m, r);

  char title[200];
  if (r.closed)
    std::snprintf(title, sizeof title, "room border: %.2f m2, perimeter %.2f m, %zu opening(s)",
                  r.area_m2, r.perimeter_m, r.openings.size());
  else
    std::snprintf(title, sizeof title, "no closed room border");
  cv::putText(img, title, {6, 20}, kFont, 0.55, {0, 0, 0}, 1, cv::LINE_AA);
  LegendStyle style;
  style.gap_px = 28;
  style.wrap_reserve_px = 40;
  style.row_px = 24;
  style.bar_must_fit = false;
  Legend legend(img, title_h + h * k + 8, style);
  for (Cell c : {Cell::kWall, Cell::kFurniture, Cell::kFree, Cell::kUnknown})
    legend.swatch(cell_colour(c), std::string(to_string(c)));
  legend.swatch(heavy_tint, "heavy border");
  legend.stroke(chain_col, 3, "chain");
  legend.stroke(poly_col, 1, "polygon");
  legend.stroke(door_col, 4, "door candidate");
  legend.stroke(gap_col, 4, "other opening");
  legend.item("interior object", [&](cv::Rect rc) { cv::rectangle(img, rc, object_col, 1); });
  legend.item("scanner", [&](cv::Rect rc) {
    draw_cross(img, {rc.x + 8, rc.y + 8}, 6, scanner_col);
  });
  legend.scale_bar(static_cast<int>(std::lround(k / geo.cell_m())));
  write_png(path, img);
}

}  // namespace indoormap::draw
