#include "indoormap/draw/rooms_png.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "indoormap/draw/canvas.hpp"
#include "indoormap/draw/palette.hpp"

namespace indoormap::draw {
namespace {

const cv::Scalar kRoomsDoor(40, 170, 40);    // BGR: green
const cv::Scalar kRoomsOutline(90, 40, 40);  // dark blue

/// A pastel tint per room id (golden-angle hues).
cv::Vec3b rooms_tint(int id) {
  const double hue = std::fmod(id * 137.508, 360.0);
  cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(hue / 2.0, 80, 245)), bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  return bgr.at<cv::Vec3b>(0, 0);
}

std::vector<cv::Point> rooms_px(const PixelFrame& f, const Polygon& poly) {
  std::vector<cv::Point> pts;
  for (const auto& v : poly) pts.push_back(f.to_px(v));
  return pts;
}

}  // namespace

void write_rooms_png(const std::filesystem::path& path, const rooms::RoomsResult& r,
                     const Grid<Cell>& nav, const std::vector<Polygon>& objects,
                     const std::string& title, const std::vector<ObjectKind>& kinds) {
  const GridGeometry& g = r.geometry;
  const int w = std::max(nav.width, 1), h = std::max(nav.height, 1);
  const int k = pixels_per_cell(w, h, 640, 2400);
  const int title_h = 28, legend_h = 52;
  cv::Mat base(h, w, CV_8UC3, cv::Scalar(255, 255, 255));
  for (int y = 0; y < nav.height; ++y)
    for (int x = 0; x < nav.width; ++x) {
      const int id = r.labels.contains(x, y) ? r.labels.at(x, y) : 0;
      const cv::Scalar c = cell_colour(nav.at(x, y));
      cv::Vec3b col(static_cast<uchar>(c[0]), static_cast<uchar>(c[1]), static_cast<uchar>(c[2]));
      base.at<cv::Vec3b>(nav.height - 1 - y, x) = id ? rooms_tint(id) : col;
    }
  cv::Mat img(title_h + h * k + legend_h, std::max(w * k, 640), CV_8UC3, cv::Scalar(255, 255, 255));
  cv::Mat scaled;
  cv::resize(base, scaled, cv::Size(w * k, h * k), 0, 0, cv::INTER_NEAREST);
  scaled.copyTo(img(cv::Rect(0, title_h, w * k, h * k)));
  const PixelFrame frame{g, k, title_h, h};
  const bool by_kind = kinds.size() == objects.size();
  std::array<bool, kObjectKinds.size()> used{};
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const ObjectKind kind = by_kind ? kinds[i] : ObjectKind::kFurniture;
    used[static_cast<std::size_t>(kind)] = true;
    const std::vector<std::vector<cv::Point>> poly{rooms_px(frame, objects[i])};
    cv::polylines(img, poly, true, kind_colour(kind), std::max(1, k / 2), cv::LINE_AA);
  }
  for (const auto& room : r.rooms) {
    if (room.polygon_m.size() < 3) continue;
    const std::vector<std::vector<cv::Point>> poly{rooms_px(frame, room.polygon_m)};
    cv::polylines(img, poly, true, kRoomsOutline, std::max(1, k / 2), cv::LINE_AA);
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (const auto& v : room.polygon_m) c += v;
    c /= static_cast<double>(room.polygon_m.size());
    const std::string label = std::to_string(room.id);
    const cv::Point at = frame.to_px(c) - cv::Point(6 * static_cast<int>(label.size()), -7);
    cv::putText(img, label, at, cv::FONT_HERSHEY_SIMPLEX, 0.7, {0, 0, 0}, 2, cv::LINE_AA);
  }
  for (const auto& d : r.doors)
    cv::line(img, frame.to_px(d.end0_m), frame.to_px(d.end1_m), kRoomsDoor, std::max(3, k),
             cv::LINE_AA);
  const std::string caption = title + "  (" + std::to_string(r.rooms.size()) + " rooms, " +
                              std::to_string(r.doors.size()) + " doors)";
  cv::putText(img, caption, {6, 20}, cv::FONT_HERSHEY_SIMPLEX, 0.5, {0, 0, 0}, 1, cv::LINE_AA);
  LegendStyle style;
  style.bar_ticks = true;
  style.wrap_reserve_px = 40;
  Legend legend(img, title_h + h * k + 8, style);
  legend.item("room (id)", [&](cv::Rect rc) {
    cv::rectangle(img, rc, cv::Scalar(rooms_tint(1)), cv::FILLED);
    cv::rectangle(img, rc, kRoomsOutline);
  });
  legend.stroke(kRoomsDoor, 3, "door");
  for (const ObjectKind kind : kObjectKinds)
    if (used[static_cast<std::size_t>(kind)] || (objects.empty() && kind == ObjectKind::kFurniture))
      legend.stroke(kind_colour(kind), 2, std::string(to_string(kind)));
  legend.swatch(cell_colour(Cell::kWall), "occupied");
  legend.swatch(cell_colour(Cell::kUnknown), "unknown");
  legend.scale_bar(static_cast<int>(std::lround(k / g.cell_m())));
  write_png(path, img);
}

}  // namespace indoormap::draw
