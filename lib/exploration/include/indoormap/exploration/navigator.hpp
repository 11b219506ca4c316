#pragma once
// The wavefront navigator (the paper's Navigator): a breadth-first wave from the robot's cell over
// the cells it may enter, 8-connected (diagonal steps do not cut corners), until it meets the goal;
// the path descends the wave back from the goal. Obstacles are inflated by the robot radius (plus
// a margin), but not within keep_clear_m of the robot and of the goal, so that a robot or a goal
// next to a wall still has a path. Unknown cells are not entered, except the goal itself (a
// frontier point is unknown). max_expanded_cells bounds the work (the paper's time limit).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::exploration {

struct NavigatorParams {
  double robot_radius_m = 0.2;
  double inflation_margin_m = 0.1;  ///< inflation radius = robot_radius_m + inflation_margin_m
  double keep_clear_m = 0.3;        ///< no inflation within this of the robot and of the goal
  std::size_t max_expanded_cells = 8'000'000;
  /// A robot inside the inflation that reaches no frontier (boxed in near furniture) gets the
  /// inflation lifted within this instead of keep_clear_m (see choose_goal).
  double escape_clear_m = 1.0;
  void validate() const;
};

enum class PathStatus { kFound, kNoPath, kBudgetExceeded, kStartOutside };

struct PathResult {
  PathStatus status = PathStatus::kNoPath;
  std::vector<CellIndex> cells;              ///< robot cell first, goal cell last
  std::vector<Eigen::Vector2d> waypoints_m;  ///< the cell centres, map frame
  double length_m = 0.0;
  std::size_t expanded = 0;
};

/// Cells the robot's centre may enter: free, not within the inflation radius of an obstacle
/// (kWall / kFurniture), except inside the keep-clear discs. Unknown cells are not traversable.
class TraversableMap {
 public:
  TraversableMap(const Grid<Cell>& map, const GridGeometry& g, const NavigatorParams& params);
  /// Lifts the inflation (not the obstacles) within keep_clear_m of c.
  void keep_clear(CellIndex c);
  /// The same with another radius (cells).
  void keep_clear(CellIndex c, int radius_cells);
  bool traversable(CellIndex c) const { return grid_.contains(c.col, c.row) && grid_.at(c) == 1; }
  const Grid<std::uint8_t>& grid() const { return grid_; }  ///< 1 traversable, 0 not

 private:
  const Grid<Cell>* map_;
  Grid<std::uint8_t> grid_;
  int keep_clear_cells_ = 0;
};

/// The wave from a start cell: the number of steps to every cell it reached.
class Wavefront {
 public:
  static constexpr std::uint32_t kUnreached = std::numeric_limits<std::uint32_t>::max();
  /// Expands over traversable cells; goal (when inside the grid) may be entered although it is
  /// not traversable, and the wave stops there. Stops after max_expanded cells.
  Wavefront(const TraversableMap& t, CellIndex start, std::size_t max_expanded,
            CellIndex goal = {-1, -1});
  std::uint32_t steps(CellIndex c) const;
  bool budget_exceeded() const { return budget_exceeded_; }
  std::size_t expanded() const { return expanded_; }
  /// Steps to enter c from its best reached neighbour (c itself need not be traversable): for
  /// frontier points, which are unknown. kUnreached when no neighbour was reached.
  std::uint32_t steps_to_enter(CellIndex c) const;
  /// Descends the wave from a reached cell (or a cell entered from one) back to the start.
  std::vector<CellIndex> path_to(CellIndex c) const;

 private:
  Grid<std::uint32_t> steps_;
  bool budget_exceeded_ = false;
  std::size_t expanded_ = 0;
};

/// Cells within radius_cells (centre to centre) of an obstacle cell (kWall / kFurniture), the
/// obstacles included, as 1.
Grid<std::uint8_t> inflate_obstacles(const Grid<Cell>& map, double radius_cells);

/// The navigator: inflates, keeps the robot and goal clear, runs the wave, extracts the path.
PathResult plan_path(const Grid<Cell>& map, const GridGeometry& g, CellIndex start, CellIndex goal,
                     const NavigatorParams& params);

/// The same on a prepared traversable map (copied, then kept clear around start and goal): for
/// callers that plan several times on one map.
PathResult plan_path(const TraversableMap& base, const GridGeometry& g, CellIndex start,
                     CellIndex goal, const NavigatorParams& params);

/// Path length in metres along the cell centres.
double path_length_m(const std::vector<CellIndex>& cells, const GridGeometry& g);

}  // namespace indoormap::exploration
