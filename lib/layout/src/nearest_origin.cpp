#include "indoormap/layout/nearest_origin.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "indoormap/core/errors.hpp"

namespace indoormap::layout {

NearestOriginSamples sample_by_nearest_origin(const PointCloud& cloud, std::size_t stride) {
  NearestOriginSamples r;
  const std::size_t ns = cloud.scanners.size();
  stride = std::max<std::size_t>(stride, 1);
  if (ns < 2 || ns > 65535 || cloud.points.empty()) return r;
  const std::size_t n = cloud.points.size();
  float x0 = std::numeric_limits<float>::max(), y0 = x0, x1 = -x0, y1 = -x0;
  for (std::size_t i = 0; i < n; i += stride) {
    const auto& p = cloud.points[i];
    if (!p.allFinite()) continue;
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  }
  if (x0 > x1) return r;
  // Lookup cells of 0.25 m, coarser while cells x positions exceed 2e8 distance tests.
  double cell = 0.25;
  auto cells_of = [&](double c) {
    return std::make_pair(static_cast<std::int64_t>((x1 - x0) / c) + 1,
                          static_cast<std::int64_t>((y1 - y0) / c) + 1);
  };
  while (true) {
    const auto [w, h] = cells_of(cell);
    if (static_cast<double>(w) * static_cast<double>(h) * static_cast<double>(ns) <= 2e8) break;
    cell *= 2.0;
  }
  const auto [w, h] = cells_of(cell);
  // Per cell, the candidates: the positions within kMarginM of the nearest one (at most
  // kMaxCandidates, nearest first). Terrestrial positions metres apart leave one; a trajectory
  // leaves those around the point, on both sides of a door when it lies near one.
  constexpr double kMarginM = 1.5;
  constexpr std::size_t kMaxCandidates = 16;
  std::vector<std::uint32_t> first(static_cast<std::size_t>(w * h) + 1, 0);
  std::vector<std::uint16_t> cand;
  std::vector<std::pair<double, std::uint16_t>> d2(ns);
  for (std::int64_t row = 0; row < h; ++row)
    for (std::int64_t col = 0; col < w; ++col) {
      const double cx = x0 + (col + 0.5) * cell, cy = y0 + (row + 0.5) * cell;
      for (std::size_t k = 0; k < ns; ++k)
        d2[k] = {std::hypot(cloud.scanners[k].x() - cx, cloud.scanners[k].y() - cy),
                 static_cast<std::uint16_t>(k)};
      const std::size_t m = std::min(kMaxCandidates, ns);
      std::partial_sort(d2.begin(), d2.begin() + static_cast<std::ptrdiff_t>(m), d2.end());
      for (std::size_t k = 0; k < m && d2[k].first <= d2[0].first + kMarginM; ++k)
        cand.push_back(d2[k].second);
      first[static_cast<std::size_t>(row * w + col) + 1] = static_cast<std::uint32_t>(cand.size());
    }
  r.points.resize(ns);
  for (std::size_t i = 0; i < n; i += stride) {
    const auto& p = cloud.points[i];
    if (!p.allFinite()) continue;  // the voxel grid ignores it too
    const auto col =
        std::clamp<std::int64_t>(static_cast<std::int64_t>((p.x() - x0) / cell), 0, w - 1);
    const auto row =
        std::clamp<std::int64_t>(static_cast<std::int64_t>((p.y() - y0) / cell), 0, h - 1);
    const std::size_t c = static_cast<std::size_t>(row * w + col);
    const std::uint32_t k = first[c + 1] - first[c];
    // A fixed scramble of the point index picks among the candidates: deterministic.
    const std::uint64_t pick = (static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ULL) >> 40;
    r.points[cand[first[c] + static_cast<std::uint32_t>(pick % k)]].push_back(p);
  }
  for (const auto& v : r.points) r.positions_used += !v.empty();
  r.applied = true;
  r.lookup_cell_m = cell;
  return r;
}

void validate(const ViewpointCheckParams& p) {
  if (p.samples < 1) throw UsageError("invalid parameter viewpoint_check.samples: must be >= 1");
  if (!(p.end_margin_m >= 0.0 && std::isfinite(p.end_margin_m)))
    throw UsageError("invalid parameter viewpoint_check.end_margin_m: must be >= 0");
  if (p.min_points < 1)
    throw UsageError("invalid parameter viewpoint_check.min_points: must be >= 1");
  if (!(p.max_occluded_share >= 0.0 && p.max_occluded_share <= 1.0))
    throw UsageError("invalid parameter viewpoint_check.max_occluded_share: must be in [0, 1]");
}

ViewpointCheck check_viewpoint(const cloud::VoxelGrid& g,
                               const std::vector<Eigen::Vector3f>& points,
                               const Eigen::Vector3d& scanner, const ViewpointCheckParams& p) {
  ViewpointCheck r;
  if (points.empty() || g.voxel_count() == 0) return r;
  const Eigen::Vector3d s = g.to_voxel_coords(scanner);
  if (!s.allFinite()) return r;
  const std::size_t stride = std::max<std::size_t>(1, points.size() / p.samples);
  const double margin = g.to_cells(p.end_margin_m);
  for (std::size_t i = 0; i < points.size(); i += stride) {
    const Eigen::Vector3d e = g.to_voxel_coords(points[i].cast<double>());
    const Eigen::Vector3d d = e - s;
    const double len = d.norm();
    if (!(len > margin + 1.0)) continue;
    ++r.sampled;
    const auto end_layer = static_cast<std::int64_t>(std::floor(e.z()));
    const Eigen::Vector3d step = d / len * 0.5;  // half-voxel steps
    const auto n = static_cast<std::int64_t>((len - margin) / 0.5);
    for (std::int64_t k = 2; k < n; ++k) {
      const Eigen::Vector3d q = s + step * static_cast<double>(k);
      const auto x = static_cast<std::int64_t>(std::floor(q.x()));
      const auto y = static_cast<std::int64_t>(std::floor(q.y()));
      const auto z = static_cast<std::int64_t>(std::floor(q.z()));
      if (!g.contains(x, y, z) || std::abs(z - end_layer) < 2) continue;
      if (g.count(x, y, z) >= p.min_points) {
        ++r.occluded;
        break;
      }
    }
  }
  return r;
}

}  // namespace indoormap::layout
