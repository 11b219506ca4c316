#include "indoormap/io/render.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::io {

namespace {

cv::Scalar colour_of(Cell c) {
  switch (c) {
    case Cell::kUnknown: return {170, 170, 170};
    case Cell::kWall: return {100, 40, 20};
    case Cell::kFurniture: return {0, 140, 255};
    case Cell::kFree: return {255, 255, 255};
  }
  return {255, 0, 255};
}

}  // namespace

void write_layout_png(const std::filesystem::path& path, const Grid<Cell>& layout,
                      const GridGeometry& geo, const RenderOptions& opt) {
  const int w = std::max(layout.width, 1), h = std::max(layout.height, 1);
  int k = std::max(1, (opt.min_width_px + w - 1) / w);
  k = std::min(k, std::max(1, 4000 / std::max(w, h)));
  const int title_h = opt.title.empty() ? 0 : 28, legend_h = 44;
  const int img_w = std::max(w * k, 560);
  cv::Mat img(title_h + h * k + legend_h, img_w, CV_8UC3, cv::Scalar(255, 255, 255));
  for (int r = 0; r < layout.height; ++r)
    for (int c = 0; c < layout.width; ++c)
      cv::rectangle(img, cv::Rect(c * k, title_h + (h - 1 - r) * k, k, k),
                    colour_of(layout.at(c, r)), cv::FILLED);
  const auto font = cv::FONT_HERSHEY_SIMPLEX;
  if (!opt.title.empty())
    cv::putText(img, opt.title, {6, 20}, font, 0.55, {0, 0, 0}, 1, cv::LINE_AA);

  auto to_px = [&](const Eigen::Vector2d& p) {
    const double cx = (p.x() - geo.origin_m().x()) / geo.cell_m();
    const double cy = (p.y() - geo.origin_m().y()) / geo.cell_m();
    return cv::Point(static_cast<int>(std::lround(cx * k)),
                     title_h + static_cast<int>(std::lround((h - cy) * k)));
  };
  for (const auto& ov : opt.overlays) {
    if (ov.points_m.empty()) continue;
    std::vector<cv::Point> px;
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const auto& p : ov.points_m) {
      px.push_back(to_px(p));
      mean += p;
    }
    mean /= static_cast<double>(ov.points_m.size());
    const cv::Scalar col(ov.rgb[2], ov.rgb[1], ov.rgb[0]);
    cv::polylines(img, std::vector<std::vector<cv::Point>>{px}, ov.closed, col, ov.thickness_px, cv::LINE_AA);
    if (!ov.label.empty()) {
      int base = 0;
      const cv::Size ts = cv::getTextSize(ov.label, font, 0.45, 1, &base);
      const cv::Point c = to_px(mean) - cv::Point(ts.width / 2, -ts.height / 2);
      cv::putText(img, ov.label, c, font, 0.45, {255, 255, 255}, 3, cv::LINE_AA);
      cv::putText(img, ov.label, c, font, 0.45, col, 1, cv::LINE_AA);
    }
  }
  const int arm = std::max(5, 2 * k);
  for (const auto& m : opt.markers_map) {
    const cv::Point p = to_px(m);
    cv::line(img, p - cv::Point(arm, arm), p + cv::Point(arm, arm), {0, 0, 220}, 2, cv::LINE_AA);
    cv::line(img, p - cv::Point(arm, -arm), p + cv::Point(arm, -arm), {0, 0, 220}, 2, cv::LINE_AA);
  }

  // Legend: class swatches, the marker, and a 1 m scale bar.
  int x = 6;
  const int y0 = title_h + h * k + 10;
  auto swatch = [&](const cv::Scalar& col, const std::string& label) {
    cv::rectangle(img, cv::Rect(x, y0, 16, 16), col, cv::FILLED);
    cv::rectangle(img, cv::Rect(x, y0, 16, 16), {0, 0, 0}, 1);
    cv::putText(img, label, {x + 20, y0 + 13}, font, 0.45, {0, 0, 0}, 1, cv::LINE_AA);
    x += 26 + static_cast<int>(label.size()) * 9;
  };
  for (Cell c : {Cell::kWall, Cell::kFurniture, Cell::kFree, Cell::kUnknown})
    swatch(colour_of(c), std::string(to_string(c)));
  if (!opt.markers_map.empty()) {
    const cv::Point p(x + 8, y0 + 8);
    cv::line(img, p - cv::Point(6, 6), p + cv::Point(6, 6), {0, 0, 220}, 2, cv::LINE_AA);
    cv::line(img, p - cv::Point(6, -6), p + cv::Point(6, -6), {0, 0, 220}, 2, cv::LINE_AA);
    cv::putText(img, opt.marker_label, {x + 20, y0 + 13}, font, 0.45, {0, 0, 0}, 1, cv::LINE_AA);
    x += 26 + static_cast<int>(opt.marker_label.size()) * 9;
  }
  for (const auto& [label, rgb] : opt.legend) {
    const cv::Scalar col(rgb[2], rgb[1], rgb[0]);
    cv::line(img, {x, y0 + 8}, {x + 16, y0 + 8}, col, 3, cv::LINE_AA);
    cv::putText(img, label, {x + 20, y0 + 13}, font, 0.45, {0, 0, 0}, 1, cv::LINE_AA);
    x += 26 + static_cast<int>(label.size()) * 9;
  }
  const int bar = static_cast<int>(std::lround(k / geo.cell_m()));
  if (bar > 4 && x + bar + 40 < img_w) {
    cv::line(img, {x, y0 + 12}, {x + bar, y0 + 12}, {0, 0, 0}, 2);
    cv::line(img, {x, y0 + 6}, {x, y0 + 16}, {0, 0, 0}, 1);
    cv::line(img, {x + bar, y0 + 6}, {x + bar, y0 + 16}, {0, 0, 0}, 1);
    cv::putText(img, "1 m", {x + bar + 6, y0 + 16}, font, 0.45, {0, 0, 0}, 1, cv::LINE_AA);
  }
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", img, png)) throw OutputError(path.string(), "PNG encoding failed");
  write_file_atomic(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

}  // namespace indoormap::io
