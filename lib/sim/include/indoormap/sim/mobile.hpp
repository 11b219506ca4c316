#pragma once
// The mobile-scanner mode (docs/scene-sim.md, "Mobile scanner"): a robot- or backpack-mounted
// lidar driven along a path through every room, casting at every position a sparse, rotating
// 16-beam-like share of the terrestrial scanner's rays. The path is planned on the truth free
// space, kept clearance_m from walls and furniture: from the corridor's west end into every room
// (nearest first, through its door) and back to the start.
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "indoormap/sim/ground_truth.hpp"
#include "indoormap/sim/scene.hpp"
#include "indoormap/sim/simulate.hpp"

namespace indoormap::sim {

struct MobileParams {
  double step_m = 0.5;  ///< distance between positions along the path
  /// Rays per position as a share of the terrestrial pattern (scene.scanner: 1440 x 401 rays at
  /// 0.25 deg). 0.06 with the default scanner: 16 beams x 2166 columns (0.17 deg), ~35 k rays.
  double ray_share = 0.06;
  int beams = 16;  ///< rows of one column, spread over the elevation fan
  double elevation_min_deg = -30.0;
  double elevation_max_deg = 30.0;
  double sensor_height_m = 1.0;  ///< above the storey floor
  double clearance_m = 0.4;      ///< wanted distance of the path from walls and furniture
  double speed_m_s = 1.0;        ///< for the trajectory's timestamps
};

/// Throws UsageError for out-of-range values (step in [0.05, 10] m, share in (0, 1], beams in
/// [1, 128], fan within [-90, 90] deg, sensor height in [0.1, 3] m, clearance in [0, 2] m).
void validate(const MobileParams& params);

/// The planned path: sensor poses (storey frame; heading = direction of travel, degrees), every
/// step_m, skipping the samples that lie in no room polygon (inside a door opening). Where a room
/// cannot be reached with clearance_m the planner tries 0.3, 0.2 and 0.1 m; rooms it still
/// cannot reach are left out (unreached counts them). layout: truth_layout of the scene.
struct MobilePath {
  std::vector<ScannerPose> poses;
  double length_m = 0.0;
  int rooms_visited = 0, unreached = 0;
};
MobilePath plan_mobile_path(const Scene& scene, const TruthLayout& layout,
                            const MobileParams& params = {});

/// Rays simulate_mobile casts for the scene's scanners.
std::uint64_t mobile_ray_count(const Scene& scene, const MobileParams& params);

/// Simulates the scene's scanners (set them to plan_mobile_path's poses) as mobile positions:
/// at position k, `beams` rows spread over the fan with a phase rotating with k (golden ratio),
/// and ray_share * (terrestrial rays) / beams columns from the heading, also phase-rotated.
/// One ScanBlock per position. Deterministic for a scene (and its seed).
SimResult simulate_mobile(const Scene& scene, const MobileParams& params = {},
                          const SimOptions& options = {});

/// One pose of a trajectory, in the cloud's (tilted) frame.
struct TrajectoryPose {
  double t_s = 0.0;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< sensor -> cloud frame
};

/// The sensor poses of scanners (scene frame, z already including floor_z_m) in the tilted frame:
/// position R * p, orientation Rz(heading) (the sensor's axes are the tilted frame's, turned to
/// the heading, as its ray pattern is regular in that frame); timestamps from the path length at
/// speed_m_s, starting at t0_s.
std::vector<TrajectoryPose> trajectory(const std::vector<ScannerPose>& scanners, const Tilt& tilt,
                                       double speed_m_s = 1.0, double t0_s = 0.0);

}  // namespace indoormap::sim
