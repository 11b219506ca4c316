#include "indoormap/core/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace indoormap {

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

double point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                              const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  double t = len2 > 0 ? (p - a).dot(ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (a + t * ab - p).norm();
}

namespace {

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

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

std::vector<Eigen::Vector2d> sample_boundary(const Polygon& poly, double step) {
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

double directed_hausdorff(const std::vector<Eigen::Vector2d>& samples, const Polygon& poly) {
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

bool is_convex_ccw(const Polygon& poly) {
  const std::size_t n = poly.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % n];
    const auto& c = poly[(i + 2) % n];
    if (cross2(b - a, c - b) < -1e-12) return false;
  }
  return signed_area(poly) > 0;
}

Polygon clip_halfplane(const Polygon& poly, const Eigen::Vector2d& nrm, double offset) {
  Polygon out;
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

std::pair<Eigen::Vector2d, Eigen::Vector2d> bounds(const Polygon& poly) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const auto& p : poly) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {lo, hi};
}

Polygon rectangle(const Eigen::Vector2d& c, const Eigen::Vector2d& size, double yaw_rad) {
  const Eigen::Vector2d u(std::cos(yaw_rad), std::sin(yaw_rad));
  const Eigen::Vector2d v(-u.y(), u.x());
  const Eigen::Vector2d hx = u * (0.5 * size.x()), hy = v * (0.5 * size.y());
  return {c - hx - hy, c + hx - hy, c + hx + hy, c - hx + hy};
}

Polygon circle_polygon(const Eigen::Vector2d& c, double r, int n) {
  const double pi = std::numbers::pi;
  const double scale = std::sqrt(2.0 * pi / (n * std::sin(2.0 * pi / n)));
  Polygon out;
  out.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * pi * i / n;
    out.emplace_back(c + r * scale * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return out;
}

double boundary_hausdorff(const Polygon& a, const Polygon& b, double step_m) {
  return std::max(directed_hausdorff(sample_boundary(a, step_m), b),
                  directed_hausdorff(sample_boundary(b, step_m), a));
}

namespace {

// The cells [c0, c1) of one raster row whose centres contains(poly, centre) accepts, as sorted
// disjoint intervals: the crossings of the row with the edges are computed with contains()'s own
// expression, and a centre is inside when an odd number of crossings lie at or left of it. So the
// counts equal those of testing every cell centre with contains() (the loop this replaces), at
// O(edges log edges) per row instead of O(cells x edges).
struct RowRaster {
  double x0, cell;
  int width;
  double centre_x(int c) const { return x0 + (c + 0.5) * cell; }
  // Smallest c in [0, width] with centre_x(c) >= x (width if none).
  int first_at_or_right_of(double x) const {
    double g = std::ceil((x - x0) / cell - 0.5);
    int c = !(g > 0) ? 0 : g > width ? width : static_cast<int>(g);
    while (c > 0 && centre_x(c - 1) >= x) --c;
    while (c < width && centre_x(c) < x) ++c;
    return c;
  }
  void intervals(const Polygon& p, double y, std::vector<double>& xs,
                 std::vector<std::pair<int, int>>& out) const {
    xs.clear();
    out.clear();
    for (std::size_t i = 0, n = p.size(), j = n - 1; i < n; j = i++) {
      const auto& a = p[i];
      const auto& b = p[j];
      if ((a.y() > y) != (b.y() > y))
        xs.push_back((b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()) + a.x());
    }
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      const int c0 = first_at_or_right_of(xs[k]), c1 = first_at_or_right_of(xs[k + 1]);
      if (c1 > c0) out.emplace_back(c0, c1);
    }
  }
};

std::int64_t cells_in(const std::vector<std::pair<int, int>>& v) {
  std::int64_t n = 0;
  for (const auto& [c0, c1] : v) n += c1 - c0;
  return n;
}

std::int64_t cells_in_both(const std::vector<std::pair<int, int>>& a,
                           const std::vector<std::pair<int, int>>& b) {
  std::int64_t n = 0;
  for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    n += std::max(0, std::min(a[i].second, b[j].second) - std::max(a[i].first, b[j].first));
    if (a[i].second < b[j].second)
      ++i;
    else
      ++j;
  }
  return n;
}

}  // namespace

double polygon_iou(const Polygon& a, const Polygon& b, double cell_m) {
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
  const RowRaster row{lo.x(), cell, w};
  std::vector<double> xs;
  std::vector<std::pair<int, int>> ia, ib;
  std::int64_t inter = 0, uni = 0;
  for (int r = 0; r < h; ++r) {
    const double y = lo.y() + (r + 0.5) * cell;
    row.intervals(a, y, xs, ia);
    row.intervals(b, y, xs, ib);
    const std::int64_t both = cells_in_both(ia, ib);
    inter += both;
    uni += cells_in(ia) + cells_in(ib) - both;
  }
  return uni > 0 ? static_cast<double>(inter) / static_cast<double>(uni) : 0.0;
}

Polygon box_polygon(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  return {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}};
}

}  // namespace indoormap
