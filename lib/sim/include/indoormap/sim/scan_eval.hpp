#pragma once
// Scores the features scan_features found in a simulated scan against the scene's known walls,
// doors and corners. Counts (not ratios) so that many scans add up.
//
// Only what the laser could see counts as ground truth: a wall end point, door or corner within
// max_range_m of the sensor, in its field of view, in line of sight, facing it, with the walls
// next to it visible over probe_m. Matching: a wall end point is the nearest end of a detected
// wall on the same line (within line_tol_m and 10 deg); a door needs both jambs within
// door_tol_m; a corner is the nearest true corner within corner_tol_m. A detected potential corner
// is right when its true vertex is hidden from the sensor.
#include <vector>

#include "indoormap/scan_features/features.hpp"
#include "indoormap/sim/scan_scenes.hpp"

namespace indoormap::sim {

struct ScanEvalParams {
  double max_range_m = 5.0;
  double probe_m = 0.3;
  double line_tol_m = 0.1;
  double endpoint_gate_m = 0.5;  ///< farther detected ends leave the true end point missed
  double door_tol_m = 0.15;
  double corner_tol_m = 0.2;
};

struct ScanScore {
  std::vector<double> endpoint_errors_m;  ///< one per matched visible wall end point
  int endpoints_visible = 0;
  int doors_visible = 0, doors_found = 0;   ///< recall: found / visible
  int doors_detected = 0, doors_right = 0;  ///< precision: right / detected (both jambs in range)
  int corners_visible = 0, corners_found = 0;
  int corners_typed = 0, corners_type_right = 0;  ///< detected corners matched to a true one
  void add(const ScanScore& o);
};

/// The score of features (extracted from scan, a cast_scan of scene) against scene.
ScanScore score_scan(const ScanScene& scene, const laser::LaserScan& scan,
                     const scan_features::ScanFeatures& features,
                     const ScanEvalParams& params = {});

}  // namespace indoormap::sim
