#pragma once
// YAML configuration of explore-sim (config/explore-sim.yaml): the simulated robot and laser, the
// robot's own map, the goal rule, the navigator, path following, timing, limits and outputs,
// mirroring exploration::ExploreParams. One visit table serves reading, --print-config and
// summary.json (apps/common/config_reader.hpp).
#include <nlohmann/json.hpp>
#include <string>

#include "indoormap/exploration/explore.hpp"

namespace indoormap::app {

struct ExploreSimConfig {
  exploration::ExploreParams explore;
  double laser_fov_deg = 270.0;  ///< becomes explore.laser.fov_rad
  int strip_panels = 5;          ///< panels of explore_strip.png
  /// Unknown cells of the input map are walls (the robot cannot drive or see into them); false:
  /// free space that the laser sees through.
  bool unknown_is_obstacle = true;
  ExploreSimConfig() {
    explore.snapshot_period_s = 15.0;
    explore.max_snapshots = 400;
  }
};

/// Calls f(section, key, field) for every configurable field, in documentation order.
template <class C, class F>
void visit_explore(C& c, F&& f) {
  auto& e = c.explore;
  f("input", "unknown_is_obstacle", c.unknown_is_obstacle);
  f("robot", "radius_m", e.robot.radius_m);
  f("robot", "speed_mps", e.robot.speed_mps);
  f("robot", "max_turn_rate_radps", e.robot.max_turn_rate_radps);
  f("laser", "beam_count", e.laser.beam_count);
  f("laser", "fov_deg", c.laser_fov_deg);
  f("laser", "max_range_m", e.laser.max_range_m);
  f("laser", "range_noise_sd_m", e.laser.range_noise_sd_m);
  f("mapping", "method", e.mapper);
  f("mapping", "cell_m", e.map_cell_m);
  f("goal", "rule", e.goal.rule);
  f("goal", "size_weight", e.goal.size_weight);
  f("goal", "size_cap_m", e.goal.size_cap_m);
  f("goal", "min_size_m", e.goal.min_size_m);
  f("goal", "max_attempts", e.goal.max_attempts);
  f("navigator", "inflation_margin_m", e.navigator.inflation_margin_m);
  f("navigator", "keep_clear_m", e.navigator.keep_clear_m);
  f("navigator", "escape_clear_m", e.navigator.escape_clear_m);
  f("navigator", "max_expanded_cells", e.navigator.max_expanded_cells);
  f("pursuit", "lookahead_m", e.pursuit.lookahead_m);
  f("pursuit", "turn_in_place_above_rad", e.pursuit.turn_in_place_above_rad);
  f("pursuit", "goal_tolerance_m", e.pursuit.goal_tolerance_m);
  f("reactive", "stop_distance_m", e.reactive.stop_distance_m);
  f("reactive", "corridor_half_width_m", e.reactive.corridor_half_width_m);
  f("reactive", "backoff_m", e.reactive.backoff_m);
  f("timing", "control_period_s", e.control_period_s);
  f("timing", "scan_period_s", e.scan_period_s);
  f("timing", "replan_period_s", e.replan_period_s);
  f("timing", "min_replan_interval_s", e.min_replan_interval_s);
  f("timing", "coverage_period_s", e.coverage_period_s);
  f("limits", "max_time_s", e.max_time_s);
  f("limits", "max_stall_s", e.max_stall_s);
  f("output", "snapshot_period_s", e.snapshot_period_s);
  f("output", "max_snapshots", e.max_snapshots);
  f("output", "strip_panels", c.strip_panels);
  f("output", "path_sample_every", e.path_sample_every);
  f("run", "seed", e.seed);
}

/// Reads a YAML file over config; unknown sections and keys are errors. Throws InputError naming
/// the file, key and line.
void merge_explore_config_file(ExploreSimConfig& config, const std::string& path);
/// Copies laser_fov_deg into the explore parameters and validates them. Throws UsageError naming
/// the key.
void resolve(ExploreSimConfig& config);
std::string to_yaml(const ExploreSimConfig& config);
nlohmann::json to_json(const ExploreSimConfig& config);

}  // namespace indoormap::app
