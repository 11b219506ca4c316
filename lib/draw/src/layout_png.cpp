#include "indoormap/draw/layout_png.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "font.hpp"
#include "indoormap/draw/canvas.hpp"
#include "indoormap/draw/palette.hpp"

namespace indoormap::draw {

namespace {

const cv::Scalar kMarker(0, 0, 220);

void draw_overlay(cv::Mat& img, const PixelFrame& frame, const Overlay& ov) {
  std::vector<cv::Point> px;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : ov.points_m) {
    px.push_back(frame.to_px(p));
    mean += p;
  }
  mean /= static_cast<double>(ov.points_m.size());
  const cv::Scalar col(ov.rgb[2], ov.rgb[1], ov.rgb[0]);
  cv::polylines(img, std::vector<std::vector<cv::Point>>{px}, ov.closed, col, ov.thickness_px,
                cv::LINE_AA);
  if (!ov.label.empty()) {
    int base = 0;
    const cv::Size ts = cv::getTextSize(ov.label, kFont, 0.45, 1, &base);
    const cv::Point c = frame.to_px(mean) - cv::Point(ts.width / 2, -ts.height / 2);
    cv::putText(img, ov.label, c, kFont, 0.45, {255, 255, 255}, 3, cv::LINE_AA);
    cv::putText(img, ov.label, c, kFont, 0.45, col, 1, cv::LINE_AA);
  }
}

}  // namespace

void write_layout_png(const std::filesystem::path& path, const Grid<Cell>& layout,
                      const GridGeometry& geo, const RenderOptions& opt) {
  const int w = std::max(layout.width, 1), h = std::max(layout.height, 1);
  const int k = pixels_per_cell(w, h, opt.min_width_px);
  const int title_h = opt.title.empty() ? 0 : 28, legend_h = 44;
  const int img_w = std::max(w * k, 560);
  cv::Mat img(title_h + h * k + legend_h, img_w, CV_8UC3, cv::Scalar(255, 255, 255));
  const PixelFrame frame{geo, k, title_h, h};
  for (int r = 0; r < layout.height; ++r)
    for (int c = 0; c < layout.width; ++c)
      cv::rectangle(img, frame.cell_rect(c, r), cell_colour(layout.at(c, r)), cv::FILLED);
  if (!opt.title.empty())
    cv::putText(img, opt.title, {6, 20}, kFont, 0.55, {0, 0, 0}, 1, cv::LINE_AA);
  for (const auto& ov : opt.overlays)
    if (!ov.points_m.empty()) draw_overlay(img, frame, ov);
  const int arm = std::max(5, 2 * k);
  for (const auto& m : opt.markers_map) draw_cross(img, frame.to_px(m), arm, kMarker);

  // Legend: class swatches, the marker, the overlays' entries, and a 1 m scale bar.
  LegendStyle style;
  style.bar_ticks = true;
  Legend legend(img, title_h + h * k + 10, style);
  for (Cell c : {Cell::kWall, Cell::kFurniture, Cell::kFree, Cell::kUnknown})
    legend.swatch(cell_colour(c), std::string(to_string(c)));
  if (!opt.markers_map.empty())
    legend.item(opt.marker_label, [&](cv::Rect rc) {
      draw_cross(img, {rc.x + 8, rc.y + 8}, 6, kMarker);
    });
  for (const auto& [label, rgb] : opt.legend)
    legend.stroke(cv::Scalar(rgb[2], rgb[1], rgb[0]), 3, label);
  legend.scale_bar(static_cast<int>(std::lround(k / geo.cell_m())));
  write_png(path, img);
}

void write_truth_layout_png(const std::filesystem::path& path, const Grid<Cell>& cells,
                            const GridGeometry& geometry,
                            const std::vector<Eigen::Vector2d>& markers_m) {
  const int scale = std::clamp(900 / std::max(1, cells.width), 1, 8);
  const int legend_h = 28;
  const int W = std::max(cells.width * scale, 420), H = cells.height * scale + legend_h;
  cv::Mat img(H, W, CV_8UC3, cv::Scalar(255, 255, 255));
  const PixelFrame frame{geometry, scale, 0, cells.height};
  for (int r = 0; r < cells.height; ++r)
    for (int c = 0; c < cells.width; ++c)
      cv::rectangle(img, frame.cell_rect(c, r), cell_colour(cells.at(c, r), CellColours::kTruth),
                    cv::FILLED);
  for (const auto& m : markers_m) {
    const Eigen::Vector2d p = frame.exact(m);  // truncated, not rounded, as it always was
    cv::circle(img, cv::Point(static_cast<int>(p.x()), static_cast<int>(p.y())),
               std::max(3, scale * 2), kMarker, cv::FILLED);
  }
  // Legend: fixed 95 px per class.
  LegendStyle style;
  style.gap_px = 95;
  style.char_px = 0;
  Legend legend(img, cells.height * scale + 6, style);
  for (Cell c : {Cell::kUnknown, Cell::kWall, Cell::kFurniture, Cell::kFree})
    legend.swatch(cell_colour(c, CellColours::kTruth), std::string(to_string(c)));
  if (!markers_m.empty())
    legend.item("scanner", [&](cv::Rect rc) {
      cv::circle(img, cv::Point(rc.x + 8, rc.y + 8), 5, kMarker, cv::FILLED);
    });
  write_png(path, img);
}

}  // namespace indoormap::draw
