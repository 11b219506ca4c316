#pragma once
// YAML configuration of laser-to-map (config/laser-to-map.yaml): sections mapping.*, himm.*,
// log_odds.*, consistency.* and log.*, mirroring laser::OccupancyGridParams, HimmParams,
// LogOddsParams, ConsistencyParams and formats::CarmenReadOptions. One visit table serves the
// file reader, --print-config and summary.json.
#include <nlohmann/json.hpp>
#include <string>

#include "indoormap/formats/carmen.hpp"
#include "indoormap/laser/mappers.hpp"
#include "indoormap/laser/pose_refine.hpp"
#include "indoormap/laser/raycast.hpp"

namespace indoormap::app {

struct LaserMapConfig {
  laser::MapperKind method = laser::MapperKind::kLogOdds;  ///< the better one on the real logs
  laser::OccupancyGridParams grid;
  laser::HimmParams himm;
  /// Unclamped: the map of the whole log weighs every beam alike (a clamped cell follows its last
  /// few observations; docs/laser-to-map.md, "Why freiburg-079's beams disagreed").
  laser::LogOddsParams log_odds{.clamp = false};
  laser::PoseRefineParams pose_refine;
  laser::ConsistencyParams consistency;
  formats::CarmenReadOptions log;
  /// Progress on stderr every this many scans (0: none; -q silences it too; docs/progress.md).
  int progress_every_scans = 1000;
};

/// Calls f(section, key, field) for every configurable field, in documentation order.
template <class C, class F>
void visit_laser_map(C& c, F&& f) {
  f("mapping", "method", c.method);
  f("mapping", "cell_m", c.grid.cell_m);
  f("mapping", "max_range_m", c.grid.max_range_m);
  f("mapping", "clear_no_return", c.grid.clear_no_return);
  f("mapping", "no_return_clear_m", c.grid.no_return_clear_m);
  f("mapping", "hit_guard_cells", c.grid.hit_guard_cells);
  f("mapping", "grow_margin_m", c.grid.grow_margin_m);
  f("mapping", "max_cells", c.grid.max_cells);
  f("himm", "initial_value", c.himm.initial_value);
  f("himm", "hit_increment", c.himm.hit_increment);
  f("himm", "miss_decrement", c.himm.miss_decrement);
  f("himm", "max_value", c.himm.max_value);
  f("himm", "occupied_above", c.himm.occupied_above);
  f("himm", "free_below", c.himm.free_below);
  f("himm", "freeze_at_max", c.himm.freeze_at_max);
  f("himm", "mask", c.himm.mask);
  f("log_odds", "p_hit", c.log_odds.p_hit);
  f("log_odds", "p_miss", c.log_odds.p_miss);
  f("log_odds", "clamp", c.log_odds.clamp);
  f("log_odds", "p_min", c.log_odds.p_min);
  f("log_odds", "p_max", c.log_odds.p_max);
  f("log_odds", "occupied_above_p", c.log_odds.occupied_above_p);
  f("log_odds", "free_below_p", c.log_odds.free_below_p);
  f("pose_refine", "passes", c.pose_refine.passes);
  f("pose_refine", "field_sigma_m", c.pose_refine.field_sigma_m);
  f("pose_refine", "iterations", c.pose_refine.iterations);
  f("pose_refine", "max_shift_m", c.pose_refine.max_shift_m);
  f("pose_refine", "max_turn_deg", c.pose_refine.max_turn_deg);
  f("pose_refine", "min_hits", c.pose_refine.min_hits);
  f("consistency", "within_cells", c.consistency.within_cells);
  f("consistency", "histogram_bin_m", c.consistency.histogram_bin_m);
  f("consistency", "histogram_max_m", c.consistency.histogram_max_m);
  f("log", "fov_rad", c.log.fov_rad);
  f("log", "default_max_range_m", c.log.default_max_range_m);
  f("log", "max_line_bytes", c.log.max_line_bytes);
  f("log", "max_beams", c.log.max_beams);
  f("log", "progress_every_scans", c.progress_every_scans);
}

/// Reads a YAML file over config (keys not in the file keep their values). Unknown sections and
/// keys are errors. Throws InputError naming the file, key and line.
void merge_laser_map_config_file(LaserMapConfig& config, const std::string& path);
/// Every parameter struct's validate(); throws UsageError naming the field.
void validate(const LaserMapConfig& config);
/// The mapping method by name ("himm", "logodds" or "log_odds"); throws UsageError otherwise.
laser::MapperKind parse_method(const std::string& name);
std::string to_yaml(const LaserMapConfig& config);
nlohmann::json to_json(const LaserMapConfig& config);

}  // namespace indoormap::app
