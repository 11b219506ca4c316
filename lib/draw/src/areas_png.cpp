#include "indoormap/draw/areas_png.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "font.hpp"
#include "indoormap/draw/canvas.hpp"
#include "indoormap/draw/palette.hpp"

namespace indoormap::draw {
namespace {

const cv::Scalar kCorridor(230, 170, 90);  // BGR: blue
const cv::Scalar kCrossing(40, 140, 255);  // orange
const cv::Scalar kNarrow(200, 200, 200);   // light grey
const cv::Scalar kDoor(40, 170, 40);       // green
const cv::Scalar kBorder(70, 70, 70);

/// A pastel tint per room id (golden-angle hues), never blue or orange.
cv::Vec3b room_tint(int id) {
  const double hue = std::fmod(id * 137.508, 360.0);
  // Skip the corridor / crossing hues: 20-45 (orange) and 200-240 (blue).
  const double h = hue < 20.0 ? hue
                              : (hue < 200.0 ? 45.0 + (hue - 20.0) * 155.0 / 180.0
                                             : 240.0 + (hue - 200.0) * 120.0 / 160.0);
  cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(h / 2.0, 70, 245)), bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  return bgr.at<cv::Vec3b>(0, 0);
}

cv::Vec3b vec(const cv::Scalar& s) {
  return {static_cast<uchar>(s[0]), static_cast<uchar>(s[1]), static_cast<uchar>(s[2])};
}

}  // namespace

void write_areas_png(const std::filesystem::path& path, const areas::AreasResult& r,
                     const Grid<Cell>& cells, const GridGeometry& g, const std::string& title) {
  const int w = std::max(cells.width, 1), h = std::max(cells.height, 1);
  const int k = pixels_per_cell(w, h, 640, 2400);
  const int title_h = 28, legend_h = 52;
  cv::Mat base(h, w, CV_8UC3, cv::Scalar(255, 255, 255));
  for (int y = 0; y < cells.height; ++y)
    for (int x = 0; x < cells.width; ++x) {
      const int id = r.labels.contains(x, y) ? r.labels.at(x, y) : 0;
      cv::Vec3b col = vec(cell_colour(cells.at(x, y)));
      if (id) {
        const areas::AreaKind kind = r.areas[id - 1].kind;
        col = kind == areas::AreaKind::kRoom       ? room_tint(id)
              : kind == areas::AreaKind::kCorridor ? vec(kCorridor)
                                                   : vec(kCrossing);
      } else if (r.too_narrow.contains(x, y) && r.too_narrow.at(x, y)) {
        col = vec(kNarrow);
      }
      base.at<cv::Vec3b>(cells.height - 1 - y, x) = col;
    }
  cv::Mat scaled;
  cv::resize(base, scaled, cv::Size(w * k, h * k), 0, 0, cv::INTER_NEAREST);
  // Borders between areas: a pixel whose right or upper neighbour has another label.
  for (int y = 0; y < r.labels.height; ++y)
    for (int x = 0; x < r.labels.width; ++x) {
      const int a = r.labels.at(x, y);
      if (!a) continue;
      const bool edge =
          (x + 1 < r.labels.width && r.labels.at(x + 1, y) && r.labels.at(x + 1, y) != a) ||
          (y + 1 < r.labels.height && r.labels.at(x, y + 1) && r.labels.at(x, y + 1) != a);
      if (edge) cv::rectangle(scaled, cv::Rect(x * k, (h - 1 - y) * k, k, k), kBorder, cv::FILLED);
    }
  cv::Mat img(title_h + h * k + legend_h, std::max(w * k, 640), CV_8UC3, cv::Scalar(255, 255, 255));
  scaled.copyTo(img(cv::Rect(0, title_h, w * k, h * k)));
  PixelFrame frame{g, k, title_h, h};
  for (const areas::Door& d : r.doors)
    cv::line(img, frame.to_px(d.end0_m), frame.to_px(d.end1_m), kDoor, std::max(2, k), cv::LINE_AA);
  int rooms = 0, corridors = 0, crossings = 0;
  for (const auto& a : r.areas)
    (a.kind == areas::AreaKind::kRoom       ? rooms
     : a.kind == areas::AreaKind::kCorridor ? corridors
                                            : crossings)++;
  const std::string caption = title + "  (" + std::to_string(rooms) + " rooms, " +
                              std::to_string(corridors) + " corridors, " +
                              std::to_string(crossings) + " crossings)";
  cv::putText(img, caption, {6, 20}, kFont, 0.5, {0, 0, 0}, 1, cv::LINE_AA);
  LegendStyle style;
  style.bar_ticks = true;
  style.wrap_reserve_px = 40;
  Legend legend(img, title_h + h * k + 8, style);
  legend.item("room", [&](cv::Rect rc) {
    cv::rectangle(img, rc, cv::Scalar(room_tint(1)), cv::FILLED);
    cv::rectangle(img, rc, {0, 0, 0});
  });
  legend.swatch(kCorridor, "corridor");
  legend.swatch(kCrossing, "crossing");
  legend.swatch(kNarrow, "too narrow");
  legend.swatch(cell_colour(Cell::kWall), "obstacle");
  legend.stroke(kDoor, 3, "door");
  legend.scale_bar(static_cast<int>(std::lround(k / g.cell_m())));
  write_png(path, img);
}

}  // namespace indoormap::draw
