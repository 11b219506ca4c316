#pragma once
// Scan-to-map pose refinement: moves each scan's pose so that its hits fall on the walls of a map
// built from all scans, then the map is built again from the moved poses.
//
// Why: the "corrected" CARMEN logs still carry a residual pose error of a few centimetres and a
// fraction of a degree; every scan then draws its walls a little off the others, walls grow thick
// and speckled, and later beams see the map block them early (docs/laser-to-map.md). This is the
// scan matcher of Hector-style mappers (Kohlbrecher et al. 2011): Gauss-Newton on a smooth field
// of the map's obstacles, one scan at a time, against the map of the whole log (not only of the
// scans before it), repeated `passes` times. The field is the map's occupied cells blurred by a
// Gaussian, so that a wall spread over several cells pulls each hit to the middle of its band;
// hits far from any wall (people, moved chairs) sit where the field is flat and do not pull.
#include <Eigen/Core>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/laser/scan.hpp"

namespace indoormap::laser {

struct PoseRefineParams {
  /// Map, align every scan to it, map again: this many times (0: the log's poses as they are).
  int passes = 2;
  /// Standard deviation of the Gaussian that smooths the obstacle cells into the matching field.
  double field_sigma_m = 0.05;
  /// Gauss-Newton steps per scan and pass (each step is one sweep over the scan's hits).
  int iterations = 10;
  /// A correction beyond either bound is not applied (the scan keeps its pose): the matcher is for
  /// residual error, not for a lost robot.
  double max_shift_m = 0.3;
  double max_turn_deg = 3.0;
  /// Scans with fewer hits inside the field keep their pose (too little to fix three unknowns).
  int min_hits = 30;
  void validate() const;  ///< throws UsageError naming the field
};

/// The smooth obstacle field: 1 on a lone occupied cell's centre, falling off by a Gaussian,
/// 0 outside the grid. Sampled by bilinear interpolation, with its gradient.
class MatchField {
 public:
  /// Occupied cells (is_obstacle) of `cells` on `geometry`, blurred with sigma_m.
  MatchField(const Grid<Cell>& cells, const GridGeometry& geometry, double sigma_m);
  /// Field value at a map-frame point; grad_m (per metre) when not null.
  double sample(const Eigen::Vector2d& p_map, Eigen::Vector2d* grad_m = nullptr) const;
  const GridGeometry& geometry() const { return geometry_; }

 private:
  GridGeometry geometry_;
  Grid<float> value_;
};

struct PoseCorrection {
  Pose2d robot_pose_map;  ///< the refined pose (the input pose when not applied)
  bool applied = false;
  double shift_m = 0.0;  ///< how far the refined pose moved the robot, when applied
  double turn_rad = 0.0;
};

/// The robot pose (scan.robot_pose_map as the start) that best lays the scan's hits (within
/// max_range_m) on the field's obstacles.
PoseCorrection refine_pose(const LaserScan& scan, const MatchField& field, double max_range_m,
                           const PoseRefineParams& params);

}  // namespace indoormap::laser
