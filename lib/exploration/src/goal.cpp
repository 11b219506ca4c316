#include "indoormap/exploration/goal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "indoormap/core/errors.hpp"

namespace indoormap::exploration {

void GoalParams::validate() const {
  if (!(size_weight >= 0.0) || !std::isfinite(size_weight))
    throw UsageError("goal: size_weight must be >= 0");
  if (!(size_cap_m >= 0.0) || !std::isfinite(size_cap_m))
    throw UsageError("goal: size_cap_m must be >= 0");
  if (!(min_size_m >= 0.0) || !std::isfinite(min_size_m))
    throw UsageError("goal: min_size_m must be >= 0");
  if (max_attempts == 0) throw UsageError("goal: max_attempts must be positive");
}

namespace {

void blacklist_cells(Blacklist& bl, const Frontier& f) {
  for (const CellIndex& c : f.cells) bl.at(c) = 1;
}

PathResult path_from_wave(const Wavefront& wave, CellIndex goal, const GridGeometry& g) {
  PathResult out;
  out.expanded = wave.expanded();
  out.cells = wave.path_to(goal);
  if (out.cells.empty()) return out;
  out.status = PathStatus::kFound;
  out.length_m = path_length_m(out.cells, g);
  for (const CellIndex& c : out.cells) out.waypoints_m.push_back(g.center_of(c));
  return out;
}

// The traversable map of this choice, kept clear around the robot; widened when the robot is
// boxed in (its wave ends within the keep-clear disc), so that it can get out.
TraversableMap robot_map(const Grid<Cell>& map, const GridGeometry& g, CellIndex robot,
                         const NavigatorParams& nav) {
  TraversableMap t(map, g, nav);
  t.keep_clear(robot);
  return t;
}

// The paper: the first frontier of WFD, its cell nearest the robot; blacklist and retry on a
// navigator failure.
GoalChoice nearest_frontier(const Grid<Cell>& map, const GridGeometry& g, CellIndex robot,
                            Blacklist& bl, const GoalParams& p, const NavigatorParams& nav) {
  GoalChoice out;
  const TraversableMap base = robot_map(map, g, robot, nav);
  WfdParams wp;
  wp.stop_at_first = true;
  for (std::size_t attempt = 0; attempt < p.max_attempts; ++attempt) {
    const WfdResult wfd = detect_frontiers(map, g, robot, wp, bl);
    if (wfd.frontiers.empty()) return out;
    ++out.frontiers_seen;
    const Frontier& f = wfd.frontiers.front();
    PathResult path = plan_path(base, g, robot, f.closest_to_robot, nav);
    ++out.navigator_runs;
    if (path.status == PathStatus::kFound) {
      out.goal = f.closest_to_robot;
      out.path = std::move(path);
      return out;
    }
    blacklist_cells(bl, f);  // the paper's "value 10": never a frontier point again
    ++out.blacklisted_frontiers;
  }
  return out;
}

// Every frontier, costed by one wave from the robot; the best of gain against path cost.
GoalChoice gain_per_cost(const Grid<Cell>& map, const GridGeometry& g, CellIndex robot,
                         Blacklist& bl, const GoalParams& p, const NavigatorParams& nav) {
  GoalChoice out;
  const WfdResult wfd = detect_frontiers(map, g, robot, {}, bl);
  out.frontiers_seen = wfd.frontiers.size();
  if (wfd.frontiers.empty()) return out;
  const TraversableMap t = robot_map(map, g, robot, nav);
  const Wavefront wave(t, robot, nav.max_expanded_cells);
  ++out.navigator_runs;
  struct Candidate {
    double score = std::numeric_limits<double>::infinity();
    CellIndex cell{-1, -1};
  } large, small;
  for (const Frontier& f : wfd.frontiers) {
    std::uint32_t best = Wavefront::kUnreached;
    CellIndex best_cell{-1, -1};
    for (const CellIndex& c : f.cells) {
      const std::uint32_t s = wave.steps_to_enter(c);
      if (s < best) {
        best = s;
        best_cell = c;
      }
    }
    if (best == Wavefront::kUnreached) {
      if (!wave.budget_exceeded()) {  // truly unreachable in the map as known
        blacklist_cells(bl, f);
        ++out.blacklisted_frontiers;
      }
      continue;
    }
    const double size_m = static_cast<double>(f.size()) * g.cell_m();
    const double cost_m = static_cast<double>(best) * g.cell_m();
    const double score = cost_m - p.size_weight * std::min(size_m, p.size_cap_m);
    Candidate& slot = size_m >= p.min_size_m ? large : small;
    if (score < slot.score) slot = {score, best_cell};
  }
  const Candidate& pick = large.cell.col >= 0 ? large : small;
  if (pick.cell.col < 0) return out;
  out.path = path_from_wave(wave, pick.cell, g);
  if (out.path.status == PathStatus::kFound) out.goal = pick.cell;
  return out;
}

}  // namespace

GoalChoice choose_goal(const Grid<Cell>& map, const GridGeometry& g, CellIndex robot,
                       Blacklist& blacklist, const GoalParams& goal, const NavigatorParams& nav) {
  goal.validate();
  nav.validate();
  if (blacklist.width != map.width || blacklist.height != map.height)
    blacklist = Blacklist(map.width, map.height, 0);
  auto run = [&](const NavigatorParams& n) {
    return goal.rule == GoalRule::kNearestFrontier
               ? nearest_frontier(map, g, robot, blacklist, goal, n)
               : gain_per_cost(map, g, robot, blacklist, goal, n);
  };
  const Blacklist before = blacklist;
  GoalChoice c = run(nav);
  if (c.goal || c.frontiers_seen == 0 || nav.escape_clear_m <= nav.keep_clear_m) return c;
  // Frontiers, but none reachable, and the robot's region of the traversable map is the smaller
  // part of it: it went into a pocket past a narrow spot (near a goal the inflation is lifted)
  // and is boxed in. Again with the inflation lifted within escape_clear_m, then twice that, so
  // that it can leave the way it came.
  const TraversableMap t = robot_map(map, g, robot, nav);
  const std::size_t traversable = static_cast<std::size_t>(
      std::count(t.grid().data.begin(), t.grid().data.end(), std::uint8_t{1}));
  const Wavefront region(t, robot, nav.max_expanded_cells);
  if (2 * region.expanded() >= traversable) return c;
  std::size_t runs = c.navigator_runs;
  for (double scale : {1.0, 2.0}) {
    blacklist = before;
    NavigatorParams escape = nav;
    escape.keep_clear_m = nav.escape_clear_m * scale;
    c = run(escape);
    runs += c.navigator_runs;
    if (c.goal) break;
  }
  c.navigator_runs = runs;
  return c;
}

}  // namespace indoormap::exploration
