#include "indoormap/draw/scan_features_png.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "font.hpp"
#include "indoormap/draw/canvas.hpp"

namespace indoormap::draw {

namespace {

namespace sf = scan_features;
using V = Eigen::Vector2d;
// BGR
const cv::Scalar kPoint(110, 110, 110), kWall(160, 60, 0), kDoor(40, 170, 0), kInner(0, 0, 220),
    kOuter(0, 140, 255), kPotential(200, 0, 200), kCorridor(190, 245, 250), kSensor(0, 0, 0);

void draw_corridors(cv::Mat& img, const PixelFrame& fr, const sf::ScanFeatures& f) {
  for (const sf::Corridor& c : f.corridors) {
    if (c.side_a.empty() || c.side_b.empty()) continue;
    const sf::Wall& a = f.walls[static_cast<std::size_t>(c.side_a.front())];
    const sf::Wall& b = f.walls[static_cast<std::size_t>(c.side_b.front())];
    const std::vector<cv::Point> quad{fr.to_px(a.start_map), fr.to_px(a.end_map),
                                      fr.to_px(b.start_map), fr.to_px(b.end_map)};
    cv::fillConvexPoly(img, quad, kCorridor, cv::LINE_AA);
  }
}

void draw_features(cv::Mat& img, const PixelFrame& fr, const sf::ScanFeatures& f) {
  for (const sf::Wall& w : f.walls)
    cv::arrowedLine(img, fr.to_px(w.start_map), fr.to_px(w.end_map), kWall, 2, cv::LINE_AA, 0,
                    std::min(0.3, 0.15 / std::max(w.length_m(), 0.1)));
  for (const sf::Door& d : f.doors)
    cv::line(img, fr.to_px(d.a_map), fr.to_px(d.b_map), kDoor, 4, cv::LINE_AA);
  for (const sf::Corner& c : f.corners) {
    const cv::Point p = fr.to_px(c.p_map);
    if (c.type == sf::CornerType::kInner)
      cv::circle(img, p, 5, kInner, cv::FILLED, cv::LINE_AA);
    else if (c.type == sf::CornerType::kOuter)
      cv::rectangle(img, p - cv::Point(5, 5), p + cv::Point(5, 5), kOuter, cv::FILLED);
    else
      cv::circle(img, p, 6, kPotential, 2, cv::LINE_AA);
  }
}

}  // namespace

void write_scan_features_png(const std::filesystem::path& path, const laser::LaserScan& scan,
                             const sf::ScanFeatures& f, const std::string& title,
                             int target_width_px) {
  const std::vector<V> hits = laser::hit_points_map(scan);
  const V sensor = scan.laser_pose_map().position_m();
  V lo = sensor, hi = sensor;
  for (const V& p : hits) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  lo -= V(0.5, 0.5);
  hi += V(0.5, 0.5);
  const V size = hi - lo;
  const double px_per_m = std::clamp(target_width_px / std::max(size.x(), size.y()), 10.0, 400.0);
  const int w = std::max(200, static_cast<int>(std::ceil(size.x() * px_per_m)));
  const int h = std::max(50, static_cast<int>(std::ceil(size.y() * px_per_m)));
  const int title_h = 30, legend_h = 60;
  cv::Mat img(title_h + h + legend_h, w, CV_8UC3, cv::Scalar(255, 255, 255));
  const PixelFrame fr{GridGeometry(lo, 1.0 / px_per_m, w, h), 1, title_h, h};
  draw_corridors(img, fr, f);
  for (const V& p : hits) cv::circle(img, fr.to_px(p), 2, kPoint, cv::FILLED);
  draw_features(img, fr, f);
  draw_cross(img, fr.to_px(sensor), 6, kSensor);
  cv::putText(img, title, {6, 20}, kFont, 0.5, {0, 0, 0}, 1, cv::LINE_AA);
  LegendStyle style;
  style.wrap_reserve_px = 60;
  Legend legend(img, title_h + h + 8, style);
  legend.swatch(kPoint, "returns");
  legend.stroke(kWall, 2, "wall (free side left)");
  legend.stroke(kDoor, 4, "door");
  legend.swatch(kInner, "inner corner");
  legend.swatch(kOuter, "outer corner");
  legend.swatch(kPotential, "potential corner");
  legend.swatch(kCorridor, "corridor");
  legend.item("laser", [&](cv::Rect r) { draw_cross(img, (r.tl() + r.br()) / 2, 6, kSensor); });
  legend.scale_bar(static_cast<int>(std::lround(px_per_m)));
  write_png(path, img, 9);
}

}  // namespace indoormap::draw
