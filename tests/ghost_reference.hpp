#pragma once
// The ghost filter as it was first written, kept as the reference of lib/cloud's faster one
// (tests/test_cloud.cpp compares them voxel for voxel; bench/bench_pipeline.cpp times both): every
// ray walked voxel by voxel (Amanatides-Woo), a saturating pass counter per voxel. Its cost grows
// with the length of the rays.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "indoormap/cloud/ghosts.hpp"

namespace indoormap::cloud {

inline GhostResult reference_remove_ghost_voxels(VoxelGrid& g,
                                                 const std::vector<RaySource>& sources,
                                                 const GhostParams& params) {
  validate(params);
  GhostResult res;
  std::size_t total = 0;
  bool usable = false;
  for (const auto& src : sources) {
    total += src.points.size();
    usable = usable || src.scanner.allFinite();
  }
  if (!params.enabled || !usable) return res;
  res.applied = true;
  if (g.counts.empty() || total == 0) return res;
  const std::int64_t n[3] = {g.nx, g.ny, g.nz};
  const std::int64_t nxy = g.layer_size();
  std::vector<std::uint8_t> passes(g.counts.size(), 0);  // saturating
  // One stride over all sources: max_rays bounds the whole filter, whatever the number of scans.
  const std::size_t stride = std::max<std::size_t>(
      1, (total + params.max_rays - 1) / std::max<std::size_t>(params.max_rays, 1));
  const double skip = g.to_cells(params.end_skip_m);
  const double far = g.to_cells(params.far_end_m);  // a ray ending this far counts at any layer
  const std::uint16_t* counts = g.counts.data();
  for (const auto& src : sources) {
    if (!src.scanner.allFinite()) continue;
    const auto& points = src.points;
    const Eigen::Vector3d s = g.to_voxel_coords(src.scanner);  // voxel units
    for (std::size_t i = 0; i < points.size(); i += stride) {
      const Eigen::Vector3d e = g.to_voxel_coords(points[i].cast<double>());
      if (!e.allFinite()) continue;
      const double end_layer = std::floor(e.z());
      if (e.x() < 0 || e.y() < 0 || e.z() < 0 || e.x() >= n[0] || e.y() >= n[1] || e.z() >= n[2])
        continue;
      const Eigen::Vector3d d = e - s;
      const double len = d.norm();
      if (!(len > skip)) continue;
      ++res.rays;
      // The ray s + t d, t in [t0, t1]: clipped to the grid box, its last `skip` left out.
      double t0 = 0.0, t1 = 1.0 - skip / len;
      for (int a = 0; a < 3; ++a) {
        if (std::abs(d[a]) < 1e-12) {
          if (s[a] < 0 || s[a] >= n[a]) t1 = -1.0;
          continue;
        }
        double ta = (0.0 - s[a]) / d[a], tb = (static_cast<double>(n[a]) - s[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
      }
      if (t0 >= t1) continue;
      // Amanatides-Woo traversal from the entry point.
      const Eigen::Vector3d p0 = s + (t0 + 1e-9) * d;
      std::int64_t v[3], step[3];
      double t_max[3], t_delta[3];
      for (int a = 0; a < 3; ++a) {
        v[a] = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor(p0[a])), 0, n[a] - 1);
        if (d[a] > 0) {
          step[a] = 1;
          t_max[a] = (static_cast<double>(v[a] + 1) - s[a]) / d[a];
          t_delta[a] = 1.0 / d[a];
        } else if (d[a] < 0) {
          step[a] = -1;
          t_max[a] = (static_cast<double>(v[a]) - s[a]) / d[a];
          t_delta[a] = -1.0 / d[a];
        } else {
          step[a] = 0;
          t_max[a] = t_delta[a] = std::numeric_limits<double>::infinity();
        }
      }
      // Hot loop: the voxel index moves by a fixed offset per axis step; most voxels are empty.
      const std::int64_t offset[3] = {step[0], step[1] * g.nx, step[2] * nxy};
      const std::int64_t lo_layer = static_cast<std::int64_t>(end_layer) - params.min_layer_offset,
                         hi_layer = static_cast<std::int64_t>(end_layer) + params.min_layer_offset;
      std::int64_t idx = g.index(v[0], v[1], v[2]);
      double t = t0;
      while (t < t1) {
        if (counts[idx] && passes[idx] != 0xFF &&
            (v[2] <= lo_layer || v[2] >= hi_layer ||
             (far > 0 && (e - Eigen::Vector3d(v[0] + 0.5, v[1] + 0.5, v[2] + 0.5)).norm() >= far)))
          ++passes[idx];
        const int a =
            t_max[0] < t_max[1] ? (t_max[0] < t_max[2] ? 0 : 2) : (t_max[1] < t_max[2] ? 1 : 2);
        t = t_max[a];
        t_max[a] += t_delta[a];
        v[a] += step[a];
        idx += offset[a];
        if (v[a] < 0 || v[a] >= n[a]) break;
      }
    }
  }
  const double scale = static_cast<double>(stride);
  for (std::size_t i = 0; i < g.counts.size(); ++i) {
    const std::uint16_t c = g.counts[i];
    if (!c || c > params.max_points) continue;
    const double p = passes[i] * scale;
    if (p >= params.min_passes && p >= params.min_pass_ratio * c) {
      ++res.voxels_removed;
      res.points_removed += c;
      g.counts[i] = 0;
    }
  }
  return res;
}

}  // namespace indoormap::cloud
