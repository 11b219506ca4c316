#pragma once
// Wall alignment (issue 19, --align-walls): the dominant wall direction of a levelled cloud, so
// that the map frame can be turned about the vertical until the walls run along the axes. The
// wall points are the points of plan cells whose points stand over min_wall_height_m of height
// slices (a wall, a cupboard side; not floor, not a table top); the direction is the angle, modulo
// 90 degrees, at which their projections onto the two axes are sharpest (sum of squared histogram
// counts: a coarse scan over [0, 90) degrees, then a fine one round its best). docs/pipeline.md,
// "Wall alignment".
#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

namespace indoormap::cloud {

struct WallAlignParams {
  bool enabled = false;  ///< off by default: the map stays in the scan's frame (docs/pcd-to-map.md)
  double cell_m = 0.05;  ///< plan cells of the wall test (grown to keep the grid <= 4 M cells)
  /// A cell is wall when its points occupy 0.2 m height slices spanning at least this much.
  double min_wall_height_m = 1.0;
  std::size_t sample_points = 200000;  ///< points looked at (evenly strided)
  std::size_t min_wall_points = 500;   ///< fewer wall points: no alignment (a note says why)
  /// Sharpness contrast (best - median) / best of the coarse scan below this: no dominant
  /// direction (a round room, clutter only), no alignment.
  double min_confidence = 0.1;
};

/// Throws UsageError naming the key (align_walls.cell_m, ...) for a parameter out of its range.
void validate(const WallAlignParams& params);

struct WallAlignResult {
  bool applied = false;        ///< false: rotation is the identity (disabled or not found)
  double direction_deg = 0.0;  ///< dominant wall direction in the levelled frame, (-45, 45]
  double yaw_deg = 0.0;        ///< rotation about +z applied (counter-clockwise): -direction_deg
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< aligned_from_levelled, Rz(yaw)
  double confidence = 0.0;      ///< (best - median) / best of the coarse sharpness scan, [0, 1]
  std::size_t wall_points = 0;  ///< sampled points in wall cells the estimate rests on
  std::string note;             ///< what was found, or why nothing was applied
};

/// Estimates the wall direction of `points` after `levelled_from_input` (the levelling rotation;
/// the points themselves are not changed). Deterministic. Never throws on data it cannot align:
/// the result says so (applied = false) and why. Throws UsageError for invalid params.
WallAlignResult estimate_wall_alignment(
    const std::vector<Eigen::Vector3f>& points, const WallAlignParams& params,
    const Eigen::Matrix3d& levelled_from_input = Eigen::Matrix3d::Identity());

/// The rotation about +z by yaw_deg (counter-clockwise seen from above).
Eigen::Matrix3d yaw_rotation(double yaw_deg);

/// The yaw about +z of a rotation's x axis projected on the plane, degrees in (-180, 180].
double yaw_of(const Eigen::Matrix3d& rotation);

}  // namespace indoormap::cloud
