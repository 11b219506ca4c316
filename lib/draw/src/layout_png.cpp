#include "indoormap/draw/layout_png.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "font.hpp"
#include "indoormap/draw/canvas.hpp"
#include "indoormap/draw/labels.hpp"
#include "indoormap/draw/palette.hpp"

namespace indoormap::draw {

namespace {

const cv::Scalar kMarker(0, 0, 220);
constexpr double kOverlayFont = 0.45;
constexpr int kOverlayHalo = 2;  ///< white border around a label's text, in pixels

void draw_outline(cv::Mat& img, const PixelFrame& frame, const Overlay& ov) {
  std::vector<cv::Point> px;
  for (const auto& p : ov.points_m) px.push_back(frame.to_px(p));
  const cv::Scalar col(ov.rgb[2], ov.rgb[1], ov.rgb[0]);
  cv::polylines(img, std::vector<std::vector<cv::Point>>{px}, ov.closed, col, ov.thickness_px,
                cv::LINE_AA);
}

/// The pixel a label names: label_at_m, or the mean of the overlay's points.
cv::Point2d overlay_anchor(const PixelFrame& frame, const Overlay& ov) {
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  if (ov.label_at_m) {
    at = *ov.label_at_m;
  } else {
    for (const auto& p : ov.points_m) at += p;
    at /= static_cast<double>(ov.points_m.size());
  }
  const Eigen::Vector2d e = frame.exact(at);
  return {e.x(), e.y() + frame.top_px};
}

bool has_label(const Overlay& ov) {
  return !ov.label.empty() && !ov.points_m.empty();
}

/// The overlays' labels placed in area, clear of the markers (crosses of half-width arm).
std::vector<PlacedLabel> overlay_labels(const RenderOptions& opt, const PixelFrame& frame,
                                        const cv::Rect& area, int arm) {
  std::vector<LabelRequest> req;
  for (const auto& ov : opt.overlays) {
    if (!has_label(ov)) {
      req.push_back({});
      continue;
    }
    int base = 0;
    const cv::Size ts = cv::getTextSize(ov.label, kFont, kOverlayFont, 1, &base);
    req.push_back(
        {overlay_anchor(frame, ov), {ts.width + 2 * kOverlayHalo, ts.height + 2 * kOverlayHalo}});
  }
  std::vector<cv::Rect> markers;
  for (const auto& m : opt.markers_map) {
    const cv::Point p = frame.to_px(m);
    markers.emplace_back(p.x - arm - 1, p.y - arm - 1, 2 * arm + 3, 2 * arm + 3);
  }
  return place_labels(req, area, markers);
}

void draw_overlay_leader(cv::Mat& img, const PixelFrame& frame, const Overlay& ov,
                         const PlacedLabel& pl) {
  if (!pl.leader) return;
  const cv::Scalar col(ov.rgb[2], ov.rgb[1], ov.rgb[0]);
  const cv::Point2d a = overlay_anchor(frame, ov), e = nearest_on_box(pl.box_px, a);
  cv::line(img, cv::Point(e), cv::Point(a), {255, 255, 255}, 3, cv::LINE_AA);
  cv::line(img, cv::Point(e), cv::Point(a), col, 1, cv::LINE_AA);
  cv::circle(img, cv::Point(a), 2, col, cv::FILLED, cv::LINE_AA);
}

void draw_overlay_label(cv::Mat& img, const Overlay& ov, const PlacedLabel& pl) {
  const cv::Scalar col(ov.rgb[2], ov.rgb[1], ov.rgb[0]);
  const cv::Point org(pl.box_px.x + kOverlayHalo, pl.box_px.y + pl.box_px.height - kOverlayHalo);
  cv::putText(img, ov.label, org, kFont, kOverlayFont, {255, 255, 255}, 3, cv::LINE_AA);
  cv::putText(img, ov.label, org, kFont, kOverlayFont, col, 1, cv::LINE_AA);
}

/// The legend (class swatches, the marker, the overlays' entries, the 1 m scale bar), wrapped
/// onto as many rows as the width needs, as a strip width_px wide.
cv::Mat layout_legend_strip(int width_px, int k, double cell_m, const RenderOptions& opt) {
  const int max_rows = 4 + 5 + static_cast<int>(opt.legend.size());
  cv::Mat strip(10 + 24 * max_rows + 10, width_px, CV_8UC3, cv::Scalar(255, 255, 255));
  LegendStyle style;
  style.bar_ticks = true;
  style.wrap_reserve_px = 40;
  Legend legend(strip, 10, style);
  for (Cell c : {Cell::kWall, Cell::kFurniture, Cell::kFree, Cell::kUnknown})
    legend.swatch(cell_colour(c), std::string(to_string(c)));
  if (!opt.markers_map.empty())
    legend.item(opt.marker_label, [&](cv::Rect rc) {
      draw_cross(strip, {rc.x + 8, rc.y + 8}, 6, kMarker);
    });
  for (const auto& [label, rgb] : opt.legend)
    legend.stroke(cv::Scalar(rgb[2], rgb[1], rgb[0]), 3, label);
  legend.scale_bar(static_cast<int>(std::lround(k / cell_m)));
  return strip(cv::Rect(0, 0, width_px, std::min(strip.rows, legend.bottom_px() + 10))).clone();
}

}  // namespace

void write_layout_png(const std::filesystem::path& path, const Grid<Cell>& layout,
                      const GridGeometry& geo, const RenderOptions& opt) {
  const int w = std::max(layout.width, 1), h = std::max(layout.height, 1);
  const int k = pixels_per_cell(w, h, opt.min_width_px);
  const int title_h = opt.title.empty() ? 0 : 28, map_h = h * k;
  const int img_w = std::max(w * k, 560), arm = std::max(5, 2 * k);
  const PixelFrame frame{geo, k, title_h, h};
  const auto placed = overlay_labels(opt, frame, cv::Rect(0, title_h, img_w, map_h), arm);
  LegendTable table = opt.unlabelled;
  for (std::size_t i = 0; i < opt.overlays.size(); ++i) {
    const Overlay& ov = opt.overlays[i];
    if (has_label(ov) && !placed[i].placed)
      table.rows.push_back(ov.table_row.empty() ? std::vector<std::string>{ov.label}
                                                : ov.table_row);
  }
  const cv::Mat strip = layout_legend_strip(img_w, k, geo.cell_m(), opt);
  cv::Mat img(title_h + map_h + strip.rows + table.height_px(img_w), img_w, CV_8UC3,
              cv::Scalar(255, 255, 255));
  for (int r = 0; r < layout.height; ++r)
    for (int c = 0; c < layout.width; ++c)
      cv::rectangle(img, frame.cell_rect(c, r), cell_colour(layout.at(c, r)), cv::FILLED);
  if (!opt.title.empty())
    cv::putText(img, opt.title, {6, 20}, kFont, 0.55, {0, 0, 0}, 1, cv::LINE_AA);
  for (const auto& ov : opt.overlays)
    if (!ov.points_m.empty()) draw_outline(img, frame, ov);
  for (const auto& m : opt.markers_map) draw_cross(img, frame.to_px(m), arm, kMarker);
  // Leaders under every label, labels last.
  for (std::size_t i = 0; i < opt.overlays.size(); ++i)
    if (placed[i].placed) draw_overlay_leader(img, frame, opt.overlays[i], placed[i]);
  for (std::size_t i = 0; i < opt.overlays.size(); ++i)
    if (placed[i].placed) draw_overlay_label(img, opt.overlays[i], placed[i]);
  strip.copyTo(img(cv::Rect(0, title_h + map_h, img_w, strip.rows)));
  table.draw(img, title_h + map_h + strip.rows);
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
