#include "ghost_rays.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace indoormap::cloud::detail {
namespace {

/// Pseudo-angle of (x, y) in [0, 4), monotone in atan2(y, x) taken from 0 to 2 pi.
double diamond_angle(double x, double y) {
  const double s = std::abs(x) + std::abs(y);
  if (s == 0.0) return 0.0;
  if (y >= 0) return x >= 0 ? y / s : 1.0 - x / s;
  return x < 0 ? 2.0 - y / s : 3.0 + x / s;
}

/// Pseudo-elevation of slope t = dz / r in [-1, 1], monotone in t (t may be infinite).
double pseudo_elevation(double t) {
  if (std::isinf(t)) return t > 0 ? 1.0 : -1.0;
  return t / (1.0 + std::abs(t));
}

/// Whether the segment t d, t in [0, 1] (from the origin) meets the box [lo, hi).
bool meets(const Eigen::Vector3f& d, const Eigen::Vector3f& lo, const Eigen::Vector3f& hi) {
  float t_in = 0.0f, t_out = 1.0f;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-9f) {
      if (lo[a] > 0.0f || hi[a] <= 0.0f) return false;
      continue;
    }
    float ta = lo[a] / d[a], tb = hi[a] / d[a];
    if (ta > tb) std::swap(ta, tb);
    t_in = std::max(t_in, ta);
    t_out = std::min(t_out, tb);
    if (t_in >= t_out) return false;
  }
  return true;
}

/// The n - 1 inner edges of n bins holding about equal shares of `values` (from a sample of at
/// most 16384 of them).
std::vector<double> quantile_edges(const std::vector<double>& values, int n) {
  std::vector<double> sample;
  const std::size_t step = std::max<std::size_t>(1, values.size() / 16384);
  for (std::size_t i = 0; i < values.size(); i += step) sample.push_back(values[i]);
  std::sort(sample.begin(), sample.end());
  std::vector<double> edges;
  for (int k = 1; k < n && !sample.empty(); ++k)
    edges.push_back(sample[sample.size() * static_cast<std::size_t>(k) / n]);
  return edges;
}

}  // namespace

RayFan::RayFan(const VoxelGrid& g, std::span<const Eigen::Vector3f> points,
               const Eigen::Vector3d& scanner, std::size_t stride, double skip_cells)
    : s_(g.to_voxel_coords(scanner)), skip_(skip_cells) {
  const double n[3] = {static_cast<double>(g.nx), static_cast<double>(g.ny),
                       static_cast<double>(g.nz)};
  std::vector<Ray> rays;
  rays.reserve(points.size() / stride + 1);
  for (std::size_t i = 0; i < points.size(); i += stride) {
    const Eigen::Vector3d e = g.to_voxel_coords(points[i].cast<double>());
    if (!e.allFinite() || e.x() < 0 || e.y() < 0 || e.z() < 0 || e.x() >= n[0] || e.y() >= n[1] ||
        e.z() >= n[2])
      continue;
    const Eigen::Vector3d d = e - s_;
    const double len = d.norm();
    if (!(len > skip_cells)) continue;
    rays.push_back({(d * (1.0 - skip_cells / len)).cast<float>(),
                    static_cast<std::int32_t>(std::floor(e.z()))});
  }
  // About two rays per bin, twice as many azimuth bins as elevation bins.
  nq_ = std::max(4, static_cast<int>(std::sqrt(static_cast<double>(rays.size()) / 4.0)));
  na_ = 2 * nq_;
  std::vector<double> a(rays.size()), q(rays.size());
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const auto& d = rays[i].d;
    const double r = std::sqrt(d.x() * d.x() + d.y() * d.y());
    a[i] = diamond_angle(d.x(), d.y());
    q[i] = pseudo_elevation(r > 0 ? d.z() / r : (d.z() > 0 ? kInf : -kInf));
  }
  a_bins_ = Bins(quantile_edges(a, na_), 0.0, 4.0);
  q_bins_ = Bins(quantile_edges(q, nq_), -1.0, 1.0);
  std::vector<std::uint32_t> bin(rays.size());
  offsets_.assign(static_cast<std::size_t>(na_) * nq_ + 1, 0);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    bin[i] = static_cast<std::uint32_t>(bin_q(q[i]) * na_ + bin_a(a[i]));
    ++offsets_[bin[i] + 1];
  }
  for (std::size_t b = 1; b < offsets_.size(); ++b) offsets_[b] += offsets_[b - 1];
  rays_.resize(rays.size());
  std::vector<std::uint32_t> next(offsets_.begin(), offsets_.end() - 1);
  for (std::size_t i = 0; i < rays.size(); ++i) rays_[next[bin[i]]++] = rays[i];
}

RayFan::Bins::Bins(std::vector<double> edges, double lo, double hi)
    : edges_(std::move(edges)), lo_(lo) {
  const std::size_t cells = 4 * edges_.size() + 1;
  inv_width_ = static_cast<double>(cells) / (hi - lo);  // hi > lo: the callers' fixed ranges
  table_.resize(cells + 1);
  std::size_t b = 0;
  for (std::size_t j = 0; j <= cells; ++j) {  // the edges <= each cell's lower end
    const double v = lo + static_cast<double>(j) / inv_width_;
    while (b < edges_.size() && edges_[b] <= v) ++b;
    table_[j] = static_cast<std::uint32_t>(b);
  }
}

int RayFan::Bins::of(double v) const {
  // The count of edges <= v, searched only among the edges inside v's table cell.
  double x = (v - lo_) * inv_width_;
  if (!(x >= 0.0)) x = 0.0;  // below the range, or NaN
  const auto j = static_cast<std::size_t>(std::min(x, static_cast<double>(table_.size() - 2)));
  const auto first = edges_.begin() + table_[j], last = edges_.begin() + table_[j + 1];
  return static_cast<int>(std::upper_bound(first, last, v) - edges_.begin());
}

int RayFan::passes(std::int64_t ix, std::int64_t iy, std::int64_t iz, int min_layer_offset,
                   double far_end_cells, int cap) const {
  const Eigen::Vector3d lo = Eigen::Vector3d(ix, iy, iz) - s_, hi = lo + Eigen::Vector3d::Ones();
  // Horizontal distances from the scanner to the box's footprint: nearest and farthest.
  const double nx = std::max({lo.x(), 0.0, -hi.x()}), ny = std::max({lo.y(), 0.0, -hi.y()});
  const double r_min = std::sqrt(nx * nx + ny * ny);
  const double fx = std::max(-lo.x(), hi.x()), fy = std::max(-lo.y(), hi.y());
  const double r_max = std::sqrt(fx * fx + fy * fy);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double t_lo = lo.z() >= 0 ? lo.z() / r_max : (r_min > 0 ? lo.z() / r_min : -kInf);
  const double t_hi = hi.z() <= 0 ? hi.z() / r_max : (r_min > 0 ? hi.z() / r_min : kInf);
  const int q0 = bin_q(pseudo_elevation(t_lo)), q1 = bin_q(pseudo_elevation(t_hi));
  // Azimuth: every bin when the footprint holds the scanner, else the arc over the four corners
  // (less than half a turn, since the rectangle does not hold the origin).
  int a0 = 0, a_count = na_;
  if (r_min > 0) {
    std::array<double, 4> c = {diamond_angle(lo.x(), lo.y()), diamond_angle(hi.x(), lo.y()),
                               diamond_angle(lo.x(), hi.y()), diamond_angle(hi.x(), hi.y())};
    std::sort(c.begin(), c.end());
    int gap = 3;  // the largest gap, circularly: between c[k] and c[k + 1]; 3 wraps around
    double best = c[0] + 4.0 - c[3];
    for (int k = 0; k < 3; ++k)
      if (c[k + 1] - c[k] > best) best = c[k + 1] - c[k], gap = k;
    const double from = c[(gap + 1) % 4], to = c[gap];
    a0 = bin_a(from);
    const int a1 = bin_a(to);
    a_count = (a1 - a0 + na_) % na_ + 1;
  }
  const Eigen::Vector3f lo_f = lo.cast<float>(), hi_f = hi.cast<float>();
  const Eigen::Vector3f centre = (lo_f + hi_f) * 0.5f;
  const float far2 = static_cast<float>(far_end_cells * far_end_cells);
  // A ray ending near the voxel's layer counts only when its end (the point, skip included) lies
  // at least far_end_cells from the voxel's centre.
  auto far_end = [&](const Ray& r) {
    const float len = r.d.norm();
    const Eigen::Vector3f e = r.d * (1.0f + static_cast<float>(skip_) / len) - centre;
    return e.squaredNorm() >= far2;
  };
  int count = 0;
  // The bins of one row are consecutive in rays_: the arc is one run of rays per row, or two
  // when it wraps past the last azimuth bin.
  auto scan = [&](std::size_t first_bin, std::size_t last_bin) {
    for (std::uint32_t i = offsets_[first_bin]; i < offsets_[last_bin + 1]; ++i) {
      const Ray& r = rays_[i];
      const bool near_layer =
          iz > r.end_layer - min_layer_offset && iz < r.end_layer + min_layer_offset;
      if (near_layer && !(far2 > 0.0f && far_end(r))) continue;
      if (meets(r.d, lo_f, hi_f) && ++count >= cap) return true;
    }
    return false;
  };
  const int a_last = a0 + a_count - 1;
  for (int q = q0; q <= q1; ++q) {
    const std::size_t row = static_cast<std::size_t>(q) * na_;
    if (a_last < na_) {
      if (scan(row + a0, row + a_last)) break;
    } else if (scan(row + a0, row + na_ - 1) || scan(row, row + (a_last - na_))) {
      break;
    }
  }
  return count;
}

}  // namespace indoormap::cloud::detail
