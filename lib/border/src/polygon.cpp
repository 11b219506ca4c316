#include "indoormap/border/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace indoormap::border {

double signed_area(const Polygon& p) {
  double a = 0.0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const auto& u = p[i];
    const auto& v = p[(i + 1) % n];
    a += u.x() * v.y() - v.x() * u.y();
  }
  return 0.5 * a;
}

double perimeter(const Polygon& p) {
  double s = 0.0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) s += (p[(i + 1) % n] - p[i]).norm();
  return s;
}

bool contains(const Polygon& p, const Eigen::Vector2d& q) {
  bool in = false;
  for (std::size_t i = 0, n = p.size(), j = n - 1; i < n; j = i++) {
    const auto& a = p[i];
    const auto& b = p[j];
    if ((a.y() > q.y()) != (b.y() > q.y()) &&
        q.x() < (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

bool on_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& q) {
  return std::min(a.x(), b.x()) <= q.x() && q.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= q.y() && q.y() <= std::max(a.y(), b.y());
}

// Closed segments [a, b] and [c, d] share a point (exact for the integer-valued cell centres
// used here; a tiny epsilon guards metric inputs).
bool segments_touch(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                    const Eigen::Vector2d& d) {
  constexpr double eps = 1e-12;
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  if (((d1 > eps && d2 < -eps) || (d1 < -eps && d2 > eps)) &&
      ((d3 > eps && d4 < -eps) || (d3 < -eps && d4 > eps)))
    return true;
  if (std::abs(d1) <= eps && on_segment(c, d, a)) return true;
  if (std::abs(d2) <= eps && on_segment(c, d, b)) return true;
  if (std::abs(d3) <= eps && on_segment(a, b, c)) return true;
  if (std::abs(d4) <= eps && on_segment(a, b, d)) return true;
  return false;
}

}  // namespace

bool is_simple(const Polygon& p) {
  const std::size_t n = p.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i)
    if ((p[(i + 1) % n] - p[i]).squaredNorm() == 0.0) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const auto& c = p[j];
      const auto& d = p[(j + 1) % n];
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) {
        // Consecutive edges share one vertex; they must not fold back onto each other.
        const Eigen::Vector2d& shared = j == i + 1 ? b : a;
        const Eigen::Vector2d& u = j == i + 1 ? a : b;
        const Eigen::Vector2d& v = j == i + 1 ? d : c;
        if (std::abs(cross(shared, u, v)) <= 1e-12 && (u - shared).dot(v - shared) > 0)
          return false;
        continue;
      }
      if (segments_touch(a, b, c, d)) return false;
    }
  }
  return true;
}

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
