#pragma once
// Origins of a merged cloud: which position saw which point, estimated where the input does not
// say (one merged PCD with --scanner per position, a mobile scanner's cloud and trajectory).
// docs/pipeline.md, "Ghost filter per origin".
#include <cstddef>
#include <vector>

#include "indoormap/cloud/voxel.hpp"
#include "indoormap/core/cloud.hpp"

namespace indoormap::layout {

struct NearestOriginSamples {
  bool applied = false;  ///< at least 2 positions, points, and few enough positions
  /// Per position (index in cloud.scanners): the sampled points taken as seen from it.
  std::vector<std::vector<Eigen::Vector3f>> points;
  std::size_t positions_used = 0;  ///< positions that got points
  double lookup_cell_m = 0.0;
};

/// Takes every stride-th point of the cloud (the ghost filter's sample, ghost_ray_stride) as seen
/// from the position nearest to it in the plane (per cell of a lookup grid of about 0.25 m,
/// coarser for very many positions) and returns the sample grouped by position; the cloud is left
/// as it is (sampling first spares reordering millions of points). The ghost filter's evidence is
/// the rays that pass through a voxel: a room's own scanner, its nearest, passes through the veil
/// of mixed pixels another position left there through the door. A point its nearest position
/// could not see gives a ray through a wall; the filter counts a ray only for voxels 4 layers
/// above or below its end (GhostParams), and a wall voxel holds more points than a ghost may.
/// Does nothing with fewer than 2 positions, no points, or more than 65535 positions.
NearestOriginSamples sample_by_nearest_origin(const PointCloud& cloud, std::size_t stride);

/// Whether one scanner position can be the origin of a whole cloud (a PCD's VIEWPOINT is; a
/// mobile scanner's merged cloud's is not: it is one position of the trajectory, or nothing).
struct ViewpointCheckParams {
  bool enabled = true;
  std::size_t samples = 20000;  ///< points sampled (evenly over the cloud)
  /// Occupied voxels nearer than this to a point do not block it (grazing floor, its own surface).
  double end_margin_m = 0.3;
  int min_points = 2;  ///< a voxel with this many points blocks a ray
  /// More than this share of the sampled points behind an occupied voxel: not the origin.
  double max_occluded_share = 0.15;
};

/// Throws UsageError naming the key (viewpoint_check.*) for a parameter out of its range.
void validate(const ViewpointCheckParams& p);

struct ViewpointCheck {
  std::size_t sampled = 0;
  /// sampled points whose ray from the position crosses an occupied voxel
  std::size_t occluded = 0;
  double share() const { return sampled ? static_cast<double>(occluded) / sampled : 0.0; }
};

/// Casts rays from `scanner` (map frame) to a sample of the points through the voxel grid and
/// counts those that pass an occupied voxel (min_points) more than end_margin_m before their end
/// and 2 or more layers from it: a point the position could not have seen.
ViewpointCheck check_viewpoint(const cloud::VoxelGrid& g,
                               const std::vector<Eigen::Vector3f>& points,
                               const Eigen::Vector3d& scanner, const ViewpointCheckParams& p);

}  // namespace indoormap::layout
