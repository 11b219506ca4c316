#pragma once
// Ghost voxels: mixed pixels (a return between a depth edge and the surface behind it) and other
// stray returns that float in space the scanner saw through. Not in the paper. The points behind an
// object's silhouette edge form a sparse veil that the projection turns into a wall of obstacles:
// it fences off the shadow behind a bin and gives a pillar a tail reaching to the wall.
//
// The test is free-space evidence along the rays: every point's ray from the scanner to it crossed
// empty space. A voxel that holds a few points but that many rays passed through is not a surface.
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "indoormap/cloud/voxel.hpp"
#include "indoormap/core/progress.hpp"

namespace indoormap::cloud {

struct GhostParams {
  bool enabled = true;
  int max_points = 2;         ///< only voxels with at most this many points can be ghosts
  double min_pass_ratio = 4;  ///< rays through the voxel per point in it, at least
  int min_passes = 4;         ///< and at least this many rays through it
  /// A ray counts for a voxel only when it ends this many layers above or below it: a ray that
  /// grazes a horizontal surface (a table top seen from afar) runs through the surface's own
  /// layer before it lands, and would take the top for a ghost.
  int min_layer_offset = 4;
  /// ... unless its end lies at least this far from the voxel (0: never): the grazing stretch
  /// of a ray is the last few decimetres before it lands on the surface, while a ray that
  /// crossed a doorway's veil at the height where it ends on a far wall saw the voxel empty.
  double far_end_m = 1.0;
  double end_skip_m = 0.1;         ///< the last stretch of every ray (its own surface) counts not
  std::size_t max_rays = 500'000;  ///< at most this many rays are used (every k-th point)
  /// Candidate voxels tested of those to test (per scanner position), every 16384 (empty:
  /// none). Not a config key.
  ProgressFn progress;
};

/// Throws UsageError naming the key (ghosts.min_passes, ...) for a parameter out of its range.
void validate(const GhostParams& params);

struct GhostResult {
  bool applied = false;  ///< the filter ran (enabled, one scanner known)
  std::int64_t voxels_removed = 0;
  std::uint64_t points_removed = 0;  ///< points in the removed voxels
  std::size_t rays = 0;              ///< rays used
};

/// Clears the ghost voxels of `grid` (their counts become 0). `points` and `scanner` are in the
/// grid's frame; every point is taken as a return of that one scanner. Points outside the grid
/// are ignored. Does nothing when !params.enabled. Throws UsageError for invalid params.
GhostResult remove_ghost_voxels(VoxelGrid& grid, const std::vector<Eigen::Vector3f>& points,
                                const Eigen::Vector3d& scanner, const GhostParams& params = {});

/// The points one scanner position saw (grid frame).
struct RaySource {
  std::span<const Eigen::Vector3f> points;
  Eigen::Vector3d scanner = Eigen::Vector3d::Zero();
};

/// The same over several positions, each ray from the position its point came from; the pass
/// counts add up over all sources and one stride (max_rays over all points) subsamples them.
/// Sources with a non-finite scanner are skipped; none usable: nothing done (applied false).
GhostResult remove_ghost_voxels_by_origin(VoxelGrid& grid, const std::vector<RaySource>& sources,
                                          const GhostParams& params = {});

/// The filter's subsampling of `total_points` points: every stride-th (max_rays over all).
std::size_t ghost_ray_stride(std::size_t total_points, const GhostParams& params);

/// The same with sources already subsampled: each holds every stride-th point of what its
/// position saw, stride = ghost_ray_stride of the whole cloud (pass counts scaled by it). For
/// origins estimated per point, where sampling first spares reordering the whole cloud.
GhostResult remove_presampled_ghost_voxels(VoxelGrid& grid, const std::vector<RaySource>& samples,
                                           std::size_t stride, const GhostParams& params = {});

}  // namespace indoormap::cloud
