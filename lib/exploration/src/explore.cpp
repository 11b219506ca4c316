#include "indoormap/exploration/explore.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "indoormap/core/errors.hpp"
#include "indoormap/exploration/coverage.hpp"

namespace indoormap::exploration {

void ExploreParams::validate() const {
  robot.validate();
  laser.validate();
  navigator.validate();
  pursuit.validate();
  reactive.validate();
  goal.validate();
  himm.validate();
  log_odds.validate();
  auto positive = [](double v, const char* key) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw UsageError(std::string("explore: ") + key + " must be positive");
  };
  positive(control_period_s, "control_period_s");
  positive(scan_period_s, "scan_period_s");
  positive(replan_period_s, "replan_period_s");
  positive(coverage_period_s, "coverage_period_s");
  positive(snapshot_period_s, "snapshot_period_s");
  positive(max_time_s, "max_time_s");
  positive(max_stall_s, "max_stall_s");
  if (!(map_cell_m >= 0.0) || !std::isfinite(map_cell_m))
    throw UsageError("explore: map_cell_m must be >= 0");
  if (!(min_replan_interval_s >= 0.0)) throw UsageError("explore: min_replan_interval_s >= 0");
  if (path_sample_every == 0) throw UsageError("explore: path_sample_every must be positive");
  if (max_time_s / control_period_s > 1e9)
    throw UsageError("explore: max_time_s / control_period_s above 1e9 steps");
}

std::optional<double> ExploreResult::distance_to_share(double share) const {
  for (const auto& c : coverage)
    if (c.explored_share >= share) return c.distance_m;
  return std::nullopt;
}

std::optional<double> ExploreResult::time_to_share(double share) const {
  for (const auto& c : coverage)
    if (c.explored_share >= share) return c.time_s;
  return std::nullopt;
}

namespace {

enum class Mode { kNeedGoal, kFollowing, kBackingOff };

// The loop's state, so that its steps can be small functions.
struct Run {
  const ExploreParams& p;
  const GridGeometry& truth_g;
  GridGeometry g;  ///< the robot's map
  SimWorld world;
  ReachableSpace reach;
  std::vector<std::uint32_t> reach_in_map;  ///< the robot-map cell of each reachable true cell
  NavigatorParams nav;
  PurePursuitParams pursuit_params;
  std::unique_ptr<laser::OccupancyMapper> mapper;
  std::mt19937 rng;
  ExploreResult out;
  laser::Pose2d pose;
  laser::LaserScan last_scan;
  Grid<Cell> built;
  Blacklist blacklist;
  PurePursuit pursuit;
  CellIndex goal{-1, -1};
  Mode mode = Mode::kNeedGoal;
  double t = 0.0, backoff_left_m = 0.0;
  double next_scan = 0.0, next_coverage = 0.0, next_snapshot = 0.0;
  double goal_chosen_at = -1e9;
  bool retried_blacklist = false;
  double best_share = -1.0, best_share_at = 0.0;

  Run(const Grid<Cell>& truth, const GridGeometry& geom, const laser::Pose2d& start,
      const ExploreParams& params)
      : p(params),
        truth_g(geom),
        world(truth, geom, params.robot.radius_m),
        rng(params.seed),
        pose(start) {
    const double cell = p.map_cell_m > 0.0 ? p.map_cell_m : geom.cell_m();
    const Eigen::Vector2d extent = geom.corner_of({geom.width(), geom.height()}) - geom.origin_m();
    g = GridGeometry(geom.origin_m(), cell,
                     std::max(1, static_cast<int>(std::ceil(extent.x() / cell - 1e-9))),
                     std::max(1, static_cast<int>(std::ceil(extent.y() / cell - 1e-9))));
    nav = p.navigator;
    nav.robot_radius_m = p.robot.radius_m;
    pursuit_params = p.pursuit;
    pursuit_params.speed_mps = p.robot.speed_mps;
    pursuit_params.max_turn_rate_radps = p.robot.max_turn_rate_radps;
    reach = reachable_free_space(truth, truth_g, truth_g.cell_of(start.position_m()),
                                 nav.robot_radius_m + nav.inflation_margin_m);
    out.reachable_cells = reach.cells.size();
    for (std::uint32_t i : reach.cells) {
      const CellIndex tc{static_cast<int>(i % truth.width), static_cast<int>(i / truth.width)};
      const CellIndex mc = g.cell_of(truth_g.center_of(tc));
      reach_in_map.push_back(static_cast<std::uint32_t>(mc.row) * g.width() + mc.col);
    }
    laser::OccupancyGridParams grid;
    grid.cell_m = g.cell_m();
    grid.fixed_geometry = g;
    grid.max_range_m = p.laser.max_range_m;
    grid.clear_no_return = true;  // the simulated laser has no spurious maxima
    grid.no_return_clear_m = p.laser.max_range_m;
    grid.max_cells = std::max<std::int64_t>(grid.max_cells, g.cell_count());
    mapper = laser::make_mapper(p.mapper, grid, p.himm, p.log_odds);
  }

  void scan() {
    last_scan = world.scan(pose, p.laser, rng, t);
    mapper->integrate(last_scan);
    next_scan = t + p.scan_period_s;
  }

  void sample_coverage() {
    mapper->classify(built);
    std::size_t known = 0;
    for (std::uint32_t i : reach_in_map) known += built.data[i] != Cell::kUnknown;
    const double share =
        reach_in_map.empty() ? 0.0 : static_cast<double>(known) / reach_in_map.size();
    out.coverage.push_back({t, out.distance_m, share});
    if (p.progress) p.progress(out.coverage.back());
    if (share > best_share + 0.001) {
      best_share = share;
      best_share_at = t;
    }
  }

  void snapshot() {
    if (out.snapshots.size() >= p.max_snapshots) return;
    mapper->classify(built);
    out.snapshots.push_back({t, built, pose});
  }

  // Chooses a goal; false when nothing reachable is left (after one retry without blacklist).
  bool choose() {
    mapper->classify(built);
    const CellIndex here = g.cell_of(pose.position_m());
    GoalChoice c = choose_goal(built, g, here, blacklist, p.goal, nav);
    out.navigator_runs += c.navigator_runs;
    out.blacklisted_frontiers += c.blacklisted_frontiers;
    goal_chosen_at = t;
    if (!c.goal) {
      // Frontiers blacklisted earlier may have become reachable since: one retry without them.
      const bool any = std::any_of(blacklist.data.begin(), blacklist.data.end(),
                                   [](std::uint8_t v) { return v != 0; });
      if (any && !retried_blacklist) {
        retried_blacklist = true;
        std::fill(blacklist.data.begin(), blacklist.data.end(), 0);
        return choose();
      }
      return false;
    }
    retried_blacklist = false;
    ++out.goals;
    goal = *c.goal;
    pursuit = PurePursuit(std::move(c.path.waypoints_m), pursuit_params);
    mode = Mode::kFollowing;
    return true;
  }

  // A goal the robot could not get to is not chosen again (nor its neighbours).
  void forbid_goal() {
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc)
        if (blacklist.contains(goal.col + dc, goal.row + dr))
          blacklist.at(goal.col + dc, goal.row + dr) = 1;
  }

  // The command for this control step (may change the mode).
  void command(double& v, double& w) {
    v = w = 0.0;
    if (mode == Mode::kBackingOff) {
      v = -p.reactive.backoff_speed_mps;
      return;
    }
    const PursuitCommand cmd = pursuit.step(pose);
    if (cmd.finished) {
      // Reached: a goal still unknown cannot be seen from here; never choose it again.
      if (mapper->cell_at(goal) == Cell::kUnknown) blacklist.at(goal) = 1;
      mode = Mode::kNeedGoal;
      return;
    }
    if (cmd.v_mps > 0.0 && obstacle_ahead(last_scan, p.robot.radius_m, p.reactive,
                                          pursuit.target_distance_m(pose.position_m()))) {
      ++out.obstacle_stops;  // the paper: stop, back off a bit, then a new goal
      forbid_goal();
      mode = Mode::kBackingOff;
      backoff_left_m = p.reactive.backoff_m;
      return;
    }
    v = cmd.v_mps;
    w = cmd.omega_radps;
  }

  void move(double v, double w) {
    const double dt = p.control_period_s;
    const laser::Pose2d next = integrate_motion(pose, v, w, dt);
    if (v != 0.0 && world.collides(next.position_m())) {
      ++out.collisions;
      forbid_goal();
      if (mode == Mode::kFollowing) {
        mode = Mode::kBackingOff;
        backoff_left_m = p.reactive.backoff_m;
      } else {
        mode = Mode::kNeedGoal;
      }
      return;
    }
    const double moved = (next.position_m() - pose.position_m()).norm();
    out.distance_m += moved;
    pose = next;
    if (mode == Mode::kBackingOff) {
      backoff_left_m -= moved;
      if (backoff_left_m <= 0.0) mode = Mode::kNeedGoal;
    }
  }

  void loop() {
    scan();
    sample_coverage();
    next_coverage = p.coverage_period_s;
    snapshot();
    next_snapshot = p.snapshot_period_s;
    std::size_t step = 0;
    out.status = ExploreStatus::kTimeLimit;
    while (t < p.max_time_s) {
      if (mode == Mode::kNeedGoal && !choose()) {
        out.status = ExploreStatus::kComplete;
        break;
      }
      double v = 0.0, w = 0.0;
      command(v, w);
      if (mode == Mode::kNeedGoal) continue;  // reached or stopped: choose again at once
      move(v, w);
      t += p.control_period_s;
      if (++step % p.path_sample_every == 0) out.path.push_back(pose);
      if (t >= next_scan) scan();
      if (mode == Mode::kFollowing) {
        const bool revealed = mapper->cell_at(goal) != Cell::kUnknown &&
                              t - goal_chosen_at >= p.min_replan_interval_s;
        if (revealed || t - goal_chosen_at >= p.replan_period_s) mode = Mode::kNeedGoal;
      }
      if (t >= next_coverage) {
        sample_coverage();
        next_coverage += p.coverage_period_s;
        if (t - best_share_at > p.max_stall_s) {
          out.status = ExploreStatus::kStalled;
          break;
        }
      }
      if (t >= next_snapshot) {
        snapshot();
        next_snapshot += p.snapshot_period_s;
      }
    }
    out.path.push_back(pose);
    out.time_s = t;
    sample_coverage();
    out.explored_share = out.coverage.back().explored_share;
    if (out.snapshots.size() >= p.max_snapshots) out.snapshots.pop_back();
    snapshot();
    out.map = mapper->snapshot();
  }
};

}  // namespace

ExploreResult explore(const Grid<Cell>& truth, const GridGeometry& g, const laser::Pose2d& start,
                      const ExploreParams& params) {
  params.validate();
  Run run(truth, g, start, params);
  if (!run.reach.start_free || run.world.collides(start.position_m())) {
    run.out.status = ExploreStatus::kStartBlocked;
    run.out.path.push_back(start);
    return run.out;
  }
  run.loop();
  return std::move(run.out);
}

}  // namespace indoormap::exploration
