#include "indoormap/cloud/ghosts.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "ghost_rays.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/core/parallel.hpp"

namespace indoormap::cloud {

void validate(const GhostParams& gh) {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw UsageError(std::string("invalid parameter ") + what);
  };
  require(gh.max_points >= 1 && gh.max_points <= 65535, "ghosts.max_points: must be in [1, 65535]");
  require(gh.min_pass_ratio > 0, "ghosts.min_pass_ratio: must be > 0");
  require(gh.min_passes >= 1, "ghosts.min_passes: must be >= 1");
  require(gh.min_layer_offset >= 0, "ghosts.min_layer_offset: must be >= 0");
  require(gh.far_end_m >= 0, "ghosts.far_end_m: must be >= 0");
  require(gh.end_skip_m >= 0, "ghosts.end_skip_m: must be >= 0");
  require(gh.max_rays >= 1 && gh.max_rays <= 1'000'000'000, "ghosts.max_rays: must be in [1, 1e9]");
}

namespace {

/// Indices of the voxels holding 1 to max_points points. Most voxels are empty: four at a time
/// are skipped with one 64-bit test (the grid can hold hundreds of millions).
std::vector<std::int64_t> few_point_voxels(const std::vector<std::uint16_t>& counts,
                                           int max_points) {
  std::vector<std::int64_t> out;
  const std::size_t n = counts.size(), n4 = n / 4 * 4;
  auto take = [&](std::size_t i) {
    if (counts[i] && counts[i] <= max_points) out.push_back(static_cast<std::int64_t>(i));
  };
  for (std::size_t i = 0; i < n4; i += 4) {
    std::uint64_t word;
    std::memcpy(&word, counts.data() + i, sizeof word);
    if (word == 0) continue;
    for (std::size_t k = i; k < i + 4; ++k) take(k);
  }
  for (std::size_t i = n4; i < n; ++i) take(i);
  return out;
}

/// The filter over sources whose every step-th point is a ray; counts scaled by stride.
GhostResult filter_ghosts(VoxelGrid& g, const std::vector<RaySource>& sources, std::size_t step,
                          std::size_t stride, const GhostParams& params) {
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
  // Only a voxel with few points can be a ghost: those are the candidates, and for each only the
  // rays whose direction falls in its footprint are tested (detail::RayFan), so the cost grows
  // with the candidates and the ray density, not with the length of the rays.
  const std::vector<std::int64_t> candidates = few_point_voxels(g.counts, params.max_points);
  std::vector<int> passes(candidates.size(), 0);
  const double scale = static_cast<double>(stride);
  // Enough passes to decide (counted up to this, like the saturating counter before).
  const int cap = static_cast<int>(std::min<double>(
      255.0,
      std::ceil(std::max<double>(params.min_passes, params.min_pass_ratio * params.max_points) /
                scale)));
  std::int64_t sources_used = 0;
  for (const auto& src : sources) sources_used += src.scanner.allFinite();
  ProgressTicker ticker(params.progress,
                        sources_used * static_cast<std::int64_t>(candidates.size()), 16384);
  const std::int64_t nxy = g.layer_size();
  const double far_end_cells = g.to_cells(params.far_end_m);
  for (const auto& src : sources) {
    if (!src.scanner.allFinite()) continue;
    const detail::RayFan fan(g, src.points, src.scanner, step, g.to_cells(params.end_skip_m));
    res.rays += fan.size();
    // Each candidate's count is its own: the candidates are split between the cores (the
    // progress ticker stays on the calling thread's part, scaled to the whole).
    const std::size_t nc = candidates.size();
    parallel_parts(nc, 4096, [&](std::size_t k0, std::size_t k1) {
      const bool first = k0 == 0;
      const std::int64_t share = k1 > k0 ? static_cast<std::int64_t>(nc / (k1 - k0)) : 1;
      for (std::size_t k = k0; k < k1; ++k) {
        if (first) ticker.tick(share);
        if (passes[k] >= cap) continue;
        const std::int64_t i = candidates[k], iz = i / nxy, iy = (i % nxy) / g.nx, ix = i % g.nx;
        passes[k] +=
            fan.passes(ix, iy, iz, params.min_layer_offset, far_end_cells, cap - passes[k]);
      }
      return 0;
    });
  }
  ticker.finish();
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const auto i = static_cast<std::size_t>(candidates[k]);
    const std::uint16_t c = g.counts[i];
    const double p = passes[k] * scale;
    if (p >= params.min_passes && p >= params.min_pass_ratio * c) {
      ++res.voxels_removed;
      res.points_removed += c;
      g.counts[i] = 0;
    }
  }
  return res;
}

}  // namespace

GhostResult remove_ghost_voxels(VoxelGrid& g, const std::vector<Eigen::Vector3f>& points,
                                const Eigen::Vector3d& scanner, const GhostParams& params) {
  return remove_ghost_voxels_by_origin(g, std::vector<RaySource>{{points, scanner}}, params);
}

std::size_t ghost_ray_stride(std::size_t total_points, const GhostParams& params) {
  validate(params);
  return std::max<std::size_t>(
      1, (total_points + params.max_rays - 1) / std::max<std::size_t>(params.max_rays, 1));
}

GhostResult remove_ghost_voxels_by_origin(VoxelGrid& g, const std::vector<RaySource>& sources,
                                          const GhostParams& params) {
  std::size_t total = 0;
  for (const auto& src : sources) total += src.points.size();
  // One stride over all sources: max_rays bounds the whole filter, whatever the number of scans.
  const std::size_t stride = ghost_ray_stride(total, params);
  return filter_ghosts(g, sources, stride, stride, params);
}

GhostResult remove_presampled_ghost_voxels(VoxelGrid& g, const std::vector<RaySource>& samples,
                                           std::size_t stride, const GhostParams& params) {
  return filter_ghosts(g, samples, 1, std::max<std::size_t>(stride, 1), params);
}

}  // namespace indoormap::cloud
