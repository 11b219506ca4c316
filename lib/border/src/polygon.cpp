#include "indoormap/border/polygon.hpp"

#include <opencv2/imgproc.hpp>
#include <vector>

namespace indoormap::border {

Polygon simplify_closed(const Polygon& poly, double tol) {
  if (poly.size() <= 3 || tol <= 0) return poly;
  // OpenCV takes float points: shift to the first vertex to keep the precision of large values.
  const Eigen::Vector2d o = poly.front();
  std::vector<cv::Point2f> in, out;
  in.reserve(poly.size());
  for (const auto& v : poly)
    in.emplace_back(static_cast<float>(v.x() - o.x()), static_cast<float>(v.y() - o.y()));
  cv::approxPolyDP(in, out, tol, true);
  if (out.size() < 3) return poly;
  Polygon r;
  r.reserve(out.size());
  for (const auto& v : out) r.emplace_back(o.x() + v.x, o.y() + v.y);
  return r;
}

double min_area_rect_area(const Polygon& poly) {
  if (poly.size() < 3) return 0.0;
  std::vector<cv::Point2f> pts;
  pts.reserve(poly.size());
  for (const auto& v : poly) pts.emplace_back(static_cast<float>(v.x()), static_cast<float>(v.y()));
  const cv::RotatedRect r = cv::minAreaRect(pts);
  return static_cast<double>(r.size.width) * r.size.height;
}

}  // namespace indoormap::border
