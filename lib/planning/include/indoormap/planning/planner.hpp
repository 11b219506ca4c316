#pragma once
// Route planning of paper section 3.2.D for a robot that turns on the spot and goes straight:
// Lee wave from the start, trajectory region (cells on minimal-index paths), straight-line moves
// from a neighbourhood template, and a ranked list of "turn, then go straight" routes.
//
// Moves run between cell centres. A move from cell a to cell b is valid iff every cell of the
// supercover of the segment a-b (every cell whose closed square the segment touches) is kSafe,
// its length is at most D_max and, unless it is the route's last move, at least D_min.
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "indoormap/core/errors.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/planning/safe_zone.hpp"

namespace indoormap::planning {

/// The search that finds the fewest-moves route (planner.search): both optimal searches return
/// the same number of moves and the same (shortest) length among the fewest-moves routes.
enum class RouteSearch {
  kMinLink,  ///< minimum-link search: bidirectional link-distance layers (docs/route-planning.md)
  kExact,    ///< A* on (moves, length) with a straight-line bound: the reference, slow on buildings
  kPaper,    ///< none: the paper's rules alone (they can miss the fewest-moves route)
};
const char* to_string(RouteSearch s);
/// "min_link" / "exact" / "paper"; nullopt for anything else.
std::optional<RouteSearch> route_search_from(const std::string& name);

struct PlannerParams {
  double d_min_m = 0.3;  ///< shortest move except the last one
  double d_max_m = 3.0;  ///< longest move (radius of the neighbourhood template)
  /// Follow the paper's rules (region-restricted moves, Node_Max / Node_Opt terminal points).
  bool paper_rules = true;
  /// Also search the whole safe zone for the fewest-moves route and rank it with the paper's (the
  /// paper's rules can miss it: docs/plan-route.md). kPaper: the paper's rules only.
  RouteSearch search = RouteSearch::kMinLink;
  int max_routes = 5;  ///< routes kept in the ranked list
  /// Paper: nodes on paths "significantly" longer than the best found are dropped; this many
  /// moves more than the best route are still explored (alternatives).
  int extra_moves = 1;
  std::int64_t max_nodes = 200000;  ///< budget of expanded nodes for each search (bounds time)
  /// Budget of wall-clock seconds of plan_routes (Lee wave, region and both searches; checked
  /// in the searches) (a 6000 x 6000 map with a far goal
  /// can otherwise run for minutes). Reaching it is a result: no route, budget_reached set.
  double max_seconds = 30.0;
  /// Called about once a second during the searches (not part of the config): the search
  /// ("paper", "exact" or "min_link"), the nodes it expanded so far and the seconds since
  /// plan_routes began.
  std::function<void(const char* search, std::int64_t nodes, double seconds)> progress;
};

/// Offsets of every cell whose closed square the segment from (0,0) to (dx,dy) touches (cell
/// centres at integer coordinates), in the order the segment enters them, starting with (0,0).
/// Where the segment passes exactly through a cell corner both side cells are included.
std::vector<CellIndex> supercover(int dx, int dy);

/// The neighbourhood template: every cell offset within D_max as a move end point, the prefix
/// tree of their supercover lines (so one pass over the tree from a cell finds every visible end
/// point, pruning a whole bundle of lines at its first blocked cell), and the paper's rays (end
/// points along each turning angle, by distance). Built once per (D_max, cell_m) and reused.
struct NeighbourhoodTemplate {
  double cell_m = 0.05;
  double d_max_m = 0.0;
  int radius_cells = 0;
  struct EndPoint {
    CellIndex offset;
    double length_m = 0.0;
    double heading_rad = 0.0;  ///< atan2(dy, dx)
  };
  std::vector<EndPoint> end_points;
  /// Prefix tree in depth-first order: node i covers cell offset (dx[i], dy[i]); its subtree
  /// ends before skip[i]; end_point[i] >= 0 when node i is the last cell of that end point's line.
  std::vector<std::int16_t> dx, dy;
  std::vector<std::int32_t> skip, end_point;
  std::vector<std::vector<std::int32_t>> rays;  ///< end point ids along each angle, nearest first
};
NeighbourhoodTemplate make_neighbourhood_template(double d_max_m, double cell_m);

/// The templates a planner reuses between calls.
struct Templates {
  DiskTemplate disk;
  NeighbourhoodTemplate neighbourhood;
};
Templates make_templates(const RobotParams& robot, const PlannerParams& params, double cell_m);

/// Lee wave (8-connected breadth-first; a diagonal step needs both side cells safe) over kSafe
/// cells from start: wave index = number of cells passed, -1 where not reached. Stops after the
/// layer that contains goal (cells with a higher index stay -1), or covers the whole component when
/// goal is nullopt.
Grid<std::int32_t> lee_wave(const Grid<SafeCell>& safe, CellIndex start,
                            std::optional<CellIndex> goal = std::nullopt);

/// Trajectory region M_tb: the cells on 8-connected paths of strictly increasing wave index from
/// start to goal (minimal-index paths), found by the paper's depth-first pass from the goal.
/// Empty (all false) when the wave did not reach goal.
Grid<std::uint8_t> trajectory_region(const Grid<std::int32_t>& wave, CellIndex start,
                                     CellIndex goal);

/// One "turn by turn_deg (counter-clockwise positive), then go move_m forward" command.
struct Command {
  double turn_deg = 0.0;
  double move_m = 0.0;
};

struct Route {
  std::vector<Command> commands;  ///< a final turn-only command when a goal heading was given
  std::vector<Eigen::Vector2d>
      waypoints_map;             ///< cell centres, map metres, start and goal included
  std::vector<CellIndex> cells;  ///< the same waypoints as cells
  int moves = 0;                 ///< straight segments
  int turns = 0;                 ///< commands with a non-zero turn
  double length_m = 0.0;
  std::string source;  ///< "paper", "exact" or "min_link": the search that found it
};

/// Start or goal given as a map point with an optional heading (degrees, counter-clockwise from
/// +x).
struct Pose2 {
  Eigen::Vector2d position_map = Eigen::Vector2d::Zero();
  std::optional<double> heading_deg;
};

/// What the planner did: expected outcomes (no route) are data here, not exceptions.
struct PlanResult {
  std::vector<Route> routes;  ///< ranked: fewest moves, then shortest; empty when none exists
  std::string message;        ///< why there is no route, or notes
  CellIndex start_cell, goal_cell;
  Grid<std::int32_t> wave;    ///< Lee wave from the start (stopped at the goal's index)
  Grid<std::uint8_t> region;  ///< trajectory region M_tb
  int paper_best_moves = -1;  ///< -1: the paper's rules found no route (or were not run)
  /// Fewest moves proven by the optimal search (planner.search: min_link or exact); -1: none /
  /// not run. The exact_* fields keep their names for either optimal search.
  int exact_best_moves = -1;
  bool exact_complete = false;  ///< the optimal search finished within its budget
  /// A search stopped at its budget: "planner.max_nodes" or "planner.max_seconds"; "" if none.
  std::string budget_reached;
  std::int64_t paper_nodes = 0, exact_nodes = 0;  ///< expanded nodes
};

/// Start or goal outside the grid.
class OutsideMapError : public Error {
 public:
  explicit OutsideMapError(const std::string& what) : Error(what, ExitCode::kBadInput) {}
};
/// Start or goal on a cell that is not kSafe; distance_m to the nearest kSafe cell (< 0: none).
class UnsafePointError : public Error {
 public:
  UnsafePointError(const std::string& what, double distance_m)
      : Error(what, ExitCode::kBadInput), distance_m_(distance_m) {}
  double distance_m() const { return distance_m_; }

 private:
  double distance_m_;
};

/// Plans on a safe-zone layout. Throws OutsideMapError / UnsafePointError (naming which of
/// "start" / "goal", and the distance to the nearest safe cell) and UsageError for bad params
/// (validate) or templates that do not match them.
PlanResult plan_routes(const Grid<SafeCell>& safe, const GridGeometry& geometry, const Pose2& start,
                       const Pose2& goal, const Templates& templates, const PlannerParams& params);

/// Checks ranges (0 <= D_min <= D_max, ...). Throws UsageError naming the key
/// ("invalid parameter planner.<key>: ..."). Called by make_templates and plan_routes.
void validate(const PlannerParams& params);
/// validate(robot), then validate(params).
void validate(const RobotParams& robot, const PlannerParams& params);

/// Lexicographic minimum (moves, length) route by an exact search over the whole safe zone
/// (A* over cells; the heading does not change which moves are valid nor their cost, so the
/// (cell, heading) state space collapses to cells). nullopt when no route exists or the budget
/// is exhausted (complete says which).
struct ExactResult {
  std::optional<std::vector<CellIndex>> cells;
  bool complete = true;
  std::int64_t nodes = 0;
};
/// bound: only routes of fewer moves are searched (nullopt then means "none with fewer").
ExactResult exact_min_moves(const Grid<SafeCell>& safe, CellIndex start, CellIndex goal,
                            const NeighbourhoodTemplate& tmpl, const PlannerParams& params,
                            int bound = std::numeric_limits<int>::max());

/// The fewest-moves route, as many moves as exact_min_moves, by a minimum-link search
/// (docs/route-planning.md): bidirectional layered link-distance runs bounded by a geodesic lower
/// bound (chamfer distance over the safe zone / D_max) for B = that bound, B + 1, ..., then a local
/// shortening among routes of as many moves (not always the shortest of them). Moves are checked
/// exactly as exact_min_moves checks them.
/// bound: only routes of at most that many moves are searched (nullopt: none within it).
ExactResult min_link_moves(const Grid<SafeCell>& safe, CellIndex start, CellIndex goal,
                           const NeighbourhoodTemplate& tmpl, const PlannerParams& params,
                           int bound = std::numeric_limits<int>::max());

/// A deterministic far-apart pair of safe cells for benchmarks and tests: in the largest
/// component of the Lee wave's connectivity, a double sweep (the cell farthest in wave steps from
/// the component's first cell in row-major order, then the cell farthest from that one; ties to
/// the lower index). nullopt when the map has no safe cell.
std::optional<std::pair<CellIndex, CellIndex>> far_apart_cells(const Grid<SafeCell>& safe);

/// Builds the commands, turns and length of a route through the given cells.
Route make_route(const std::vector<CellIndex>& cells, const GridGeometry& geometry,
                 std::optional<double> start_heading_deg, std::optional<double> goal_heading_deg);

}  // namespace indoormap::planning
