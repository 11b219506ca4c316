#pragma once
// Goal choice among the frontiers, with blacklisting of frontiers found unreachable.
//
// kNearestFrontier (the paper): WFD stopped at the first frontier (the nearest in the outer BFS's
// order), the goal is its cell nearest the robot; when the navigator finds no path there, that
// frontier's cells are blacklisted and the next nearest is tried.
// kGainPerCost (the better rule): every frontier, its path cost from one wave of the navigator;
// frontiers no wave reaches are blacklisted at once; the goal is the reachable frontier with the
// best score path_cost_m - size_weight * min(size_m, size_cap_m), at its nearest cell by path.
// It never walks into a frontier behind a wall, prefers the large openings that reveal rooms, and
// ignores specks smaller than min_size_m while larger frontiers remain.
#include <cstddef>
#include <optional>
#include <string_view>

#include "indoormap/exploration/frontier.hpp"
#include "indoormap/exploration/navigator.hpp"

namespace indoormap::exploration {

enum class GoalRule { kNearestFrontier, kGainPerCost };

inline constexpr std::string_view to_string(GoalRule r) {
  return r == GoalRule::kNearestFrontier ? "nearest_frontier" : "gain_per_cost";
}

struct GoalParams {
  GoalRule rule = GoalRule::kGainPerCost;
  double size_weight = 1.0;       ///< metres of path a metre of frontier is worth (gain rule)
  double size_cap_m = 3.0;        ///< frontier length counted at most (gain rule)
  double min_size_m = 0.3;        ///< smaller frontiers only when no larger one is reachable
  std::size_t max_attempts = 64;  ///< navigator runs per choice (nearest rule)
  void validate() const;
};

struct GoalChoice {
  std::optional<CellIndex> goal;
  PathResult path;  ///< to the goal (status kFound when goal is set)
  std::size_t frontiers_seen = 0;
  std::size_t blacklisted_frontiers = 0;  ///< frontiers blacklisted during this choice
  std::size_t navigator_runs = 0;
};

/// Chooses the next goal and plans the path there. Marks unreachable frontiers in blacklist
/// (resized to the map when empty). When frontiers exist but none is reachable and the robot's
/// region of the traversable map is less than half of it, it is boxed in (a pocket entered past
/// a narrow spot): the choice is repeated with the inflation lifted within nav.escape_clear_m of
/// the robot, then twice that.
GoalChoice choose_goal(const Grid<Cell>& map, const GridGeometry& g, CellIndex robot,
                       Blacklist& blacklist, const GoalParams& goal, const NavigatorParams& nav);

}  // namespace indoormap::exploration
