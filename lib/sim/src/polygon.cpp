#include "indoormap/sim/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace indoormap::sim {

double signed_area(const Polygon2& poly) {
  double a = 0.0;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = poly[i];
    const auto& q = poly[(i + 1) % n];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

bool contains(const Polygon2& poly, const Eigen::Vector2d& p) {
  bool inside = false;
  const std::size_t n = poly.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const auto& a = poly[i];
    const auto& b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

namespace {
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

bool segments_intersect(const Eigen::Vector2d& p1, const Eigen::Vector2d& p2, const Eigen::Vector2d& q1,
                        const Eigen::Vector2d& q2) {
  const double d1 = cross(q2 - q1, p1 - q1), d2 = cross(q2 - q1, p2 - q1);
  const double d3 = cross(p2 - p1, q1 - p1), d4 = cross(p2 - p1, q2 - p1);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  auto on_segment = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
    return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
           std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
  };
  if (d1 == 0 && on_segment(q1, q2, p1)) return true;
  if (d2 == 0 && on_segment(q1, q2, p2)) return true;
  if (d3 == 0 && on_segment(p1, p2, q1)) return true;
  if (d4 == 0 && on_segment(p1, p2, q2)) return true;
  return false;
}

double point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  double t = len2 > 0 ? (p - a).dot(ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (a + t * ab - p).norm();
}

std::vector<Eigen::Vector2d> sample_boundary(const Polygon2& poly, double step) {
  std::vector<Eigen::Vector2d> out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % n];
    const double len = (b - a).norm();
    const int k = std::max(1, static_cast<int>(std::ceil(len / step)));
    for (int j = 0; j < k; ++j) out.push_back(a + (b - a) * (static_cast<double>(j) / k));
  }
  return out;
}

double directed_hausdorff(const std::vector<Eigen::Vector2d>& samples, const Polygon2& poly) {
  double worst = 0.0;
  const std::size_t n = poly.size();
  for (const auto& p : samples) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i)
      best = std::min(best, point_segment_distance(p, poly[i], poly[(i + 1) % n]));
    worst = std::max(worst, best);
  }
  return worst;
}
}  // namespace

bool is_simple(const Polygon2& poly) {
  const std::size_t n = poly.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i)
    if ((poly[(i + 1) % n] - poly[i]).norm() <= 1e-9) return false;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // adjacent edges share a vertex
      if (segments_intersect(poly[i], poly[(i + 1) % n], poly[j], poly[(j + 1) % n])) return false;
    }
  }
  return true;
}

bool is_convex_ccw(const Polygon2& poly) {
  const std::size_t n = poly.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % n];
    const auto& c = poly[(i + 2) % n];
    if (cross(b - a, c - b) < -1e-12) return false;
  }
  return signed_area(poly) > 0;
}

Polygon2 clip_halfplane(const Polygon2& poly, const Eigen::Vector2d& nrm, double offset) {
  Polygon2 out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % n];
    const double da = nrm.dot(a) - offset, db = nrm.dot(b) - offset;
    if (da <= 0) out.push_back(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

std::pair<Eigen::Vector2d, Eigen::Vector2d> bounds(const Polygon2& poly) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const auto& p : poly) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {lo, hi};
}

Polygon2 rectangle(const Eigen::Vector2d& c, const Eigen::Vector2d& size, double yaw_rad) {
  const Eigen::Vector2d u(std::cos(yaw_rad), std::sin(yaw_rad));
  const Eigen::Vector2d v(-u.y(), u.x());
  const Eigen::Vector2d hx = u * (0.5 * size.x()), hy = v * (0.5 * size.y());
  return {c - hx - hy, c + hx - hy, c + hx + hy, c - hx + hy};
}

Polygon2 circle_polygon(const Eigen::Vector2d& c, double r, int n) {
  const double pi = std::numbers::pi;
  const double scale = std::sqrt(2.0 * pi / (n * std::sin(2.0 * pi / n)));
  Polygon2 out;
  out.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * pi * i / n;
    out.emplace_back(c + r * scale * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return out;
}

double boundary_hausdorff(const Polygon2& a, const Polygon2& b, double step_m) {
  return std::max(directed_hausdorff(sample_boundary(a, step_m), b),
                  directed_hausdorff(sample_boundary(b, step_m), a));
}

double polygon_iou(const Polygon2& a, const Polygon2& b, double cell_m) {
  const auto [alo, ahi] = bounds(a);
  const auto [blo, bhi] = bounds(b);
  const Eigen::Vector2d lo = alo.cwiseMin(blo), hi = ahi.cwiseMax(bhi);
  // Disjoint boxes: no intersection, no need to rasterise.
  if (alo.x() > bhi.x() || blo.x() > ahi.x() || alo.y() > bhi.y() || blo.y() > ahi.y()) return 0.0;
  // Keep the raster below ~4 M cells whatever the polygons' size.
  const double area = (hi - lo).prod();
  const double cell = std::max(cell_m, std::sqrt(area / 4e6));
  const int w = static_cast<int>(std::ceil((hi.x() - lo.x()) / cell));
  const int h = static_cast<int>(std::ceil((hi.y() - lo.y()) / cell));
  std::int64_t inter = 0, uni = 0;
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const Eigen::Vector2d p(lo.x() + (c + 0.5) * cell, lo.y() + (r + 0.5) * cell);
      const bool ia = contains(a, p), ib = contains(b, p);
      inter += ia && ib;
      uni += ia || ib;
    }
  }
  return uni > 0 ? static_cast<double>(inter) / static_cast<double>(uni) : 0.0;
}

}  // namespace indoormap::sim
