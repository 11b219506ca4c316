#pragma once
// The exploration loop: a simulated robot in a known map builds its own map (HIMM or log-odds)
// from its simulated laser, chooses frontier goals, plans with the wavefront navigator, follows
// the path with pure pursuit, stops for obstacles and backs off, blacklists unreachable
// frontiers, and ends when no reachable frontier is left. Deterministic for a fixed seed.
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "indoormap/exploration/goal.hpp"
#include "indoormap/exploration/pure_pursuit.hpp"
#include "indoormap/exploration/sim_robot.hpp"
#include "indoormap/laser/mappers.hpp"

namespace indoormap::exploration {

struct CoverageSample;

struct ExploreParams {
  RobotParams robot;
  SimLaserParams laser;
  NavigatorParams navigator;  ///< robot_radius_m is taken from robot.radius_m
  PurePursuitParams pursuit;  ///< speed_mps / max_turn_rate_radps from robot
  ReactiveParams reactive;
  GoalParams goal;
  laser::MapperKind mapper = laser::MapperKind::kHimm;
  laser::HimmParams himm;
  laser::LogOddsParams log_odds;
  /// Cell size of the robot's own map (the paper: 0.4 - 0.5 m); 0: the true map's cell size.
  /// Its extent is the true map's (the paper's xmin .. ymax).
  double map_cell_m = 0.1;
  double control_period_s = 0.1;
  double scan_period_s = 0.2;
  double replan_period_s = 3.0;  ///< re-choose the goal this often even if it is still valid
  /// A goal that the map has revealed (no longer unknown) is given up, but goals are not chosen
  /// more often than this.
  double min_replan_interval_s = 0.5;
  double coverage_period_s = 2.0;
  double snapshot_period_s = 60.0;
  std::size_t max_snapshots = 64;
  double max_time_s = 4.0 * 3600.0;
  /// Stop (kStalled) when the explored share has not grown by 0.1 % for this long: frontiers
  /// that stay reachable on the map but cannot be seen (under furniture, in pockets).
  double max_stall_s = 300.0;
  std::size_t path_sample_every = 5;  ///< keep every n-th control step's pose in the path
  std::uint32_t seed = 1;
  /// Called with every coverage sample (optional; e.g. progress messages). Does not change the
  /// run.
  std::function<void(const CoverageSample&)> progress;
  void validate() const;
};

struct CoverageSample {
  double time_s = 0.0;
  double distance_m = 0.0;
  double explored_share = 0.0;
};

struct MapSnapshot {
  double time_s = 0.0;
  Grid<Cell> cells;
  laser::Pose2d robot;
};

enum class ExploreStatus { kComplete, kTimeLimit, kStalled, kStartBlocked };

inline constexpr std::string_view to_string(ExploreStatus s) {
  switch (s) {
    case ExploreStatus::kComplete:
      return "complete";
    case ExploreStatus::kTimeLimit:
      return "time_limit";
    case ExploreStatus::kStalled:
      return "stalled";
    case ExploreStatus::kStartBlocked:
      return "start_blocked";
  }
  return "invalid";
}

struct ExploreResult {
  ExploreStatus status = ExploreStatus::kComplete;
  double explored_share = 0.0;  ///< of the reachable free space, at the end
  double distance_m = 0.0;
  double time_s = 0.0;
  std::size_t goals = 0;
  std::size_t blacklisted_frontiers = 0;
  std::size_t obstacle_stops = 0;
  std::size_t collisions = 0;  ///< motions refused by the world (should stay near 0)
  std::size_t navigator_runs = 0;
  std::size_t reachable_cells = 0;
  std::vector<laser::Pose2d> path;
  std::vector<CoverageSample> coverage;  ///< every coverage_period_s, and at the end
  std::vector<MapSnapshot> snapshots;    ///< every snapshot_period_s, and at the end
  laser::OccupancyMap map;               ///< the built map
  /// Distance travelled when the explored share first reached `share` (nullopt: never).
  std::optional<double> distance_to_share(double share) const;
  std::optional<double> time_to_share(double share) const;
};

ExploreResult explore(const Grid<Cell>& truth, const GridGeometry& g, const laser::Pose2d& start,
                      const ExploreParams& params);

}  // namespace indoormap::exploration
