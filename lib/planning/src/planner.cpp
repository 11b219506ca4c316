#include "indoormap/planning/planner.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>
#include <sstream>

#include "planner_internal.hpp"

namespace indoormap::planning {

using namespace detail;

namespace {

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(3);
  s << std::fixed << v;
  return s.str();
}

std::string point_str(const Eigen::Vector2d& p) {
  std::ostringstream s;
  s.precision(3);
  s << std::fixed << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

double normalize_deg(double a) {
  a = std::fmod(a, 360.0);
  if (a <= -180.0) a += 360.0;
  if (a > 180.0) a -= 360.0;
  return a;
}

void require(bool ok, const std::string& what) {
  if (!ok) throw UsageError("invalid parameter " + what);
}

// Which budget stopped the search, its value and what was done, and the keys to raise.
std::string budget_message(const PlannerParams& p, const PlanResult& r) {
  const std::string what = r.budget_reached == "planner.max_seconds"
                               ? "planner.max_seconds " + fmt(p.max_seconds) + " s"
                               : "planner.max_nodes " + std::to_string(p.max_nodes) + " nodes";
  return what + " reached (" + std::to_string(r.paper_nodes) + " paper + " +
         std::to_string(r.exact_nodes) + " " + to_string(p.search) +
         " nodes expanded); raise planner.max_seconds / planner.max_nodes, or plan to a "
         "nearer goal";
}

}  // namespace

const char* to_string(RouteSearch s) {
  switch (s) {
    case RouteSearch::kMinLink:
      return "min_link";
    case RouteSearch::kExact:
      return "exact";
    case RouteSearch::kPaper:
      return "paper";
  }
  return "?";
}

std::optional<RouteSearch> route_search_from(const std::string& name) {
  for (const auto s : {RouteSearch::kMinLink, RouteSearch::kExact, RouteSearch::kPaper})
    if (name == to_string(s)) return s;
  return std::nullopt;
}

void validate(const PlannerParams& p) {
  require(std::isfinite(p.d_max_m) && p.d_max_m > 0, "planner.d_max_m: must be > 0");
  require(std::isfinite(p.d_min_m) && p.d_min_m >= 0 && p.d_min_m <= p.d_max_m,
          "planner.d_min_m: must be in [0, planner.d_max_m]");
  require(p.paper_rules || p.search != RouteSearch::kPaper,
          "planner.search: 'paper' needs planner.paper_rules: true");
  require(p.max_routes >= 1 && p.max_routes <= 1000, "planner.max_routes: must be in [1, 1000]");
  require(p.extra_moves >= 0 && p.extra_moves <= 10, "planner.extra_moves: must be in [0, 10]");
  require(p.max_nodes >= 1, "planner.max_nodes: must be >= 1");
  require(p.max_seconds > 0 && p.max_seconds <= 86400,
          "planner.max_seconds: must be in (0, 86400] s");
}

void validate(const RobotParams& robot, const PlannerParams& params) {
  validate(robot);
  validate(params);
}

Templates make_templates(const RobotParams& robot, const PlannerParams& params, double cell_m) {
  validate(robot, params);
  check_disk_size(robot, cell_m);
  return {make_disk_template(d_save_m(robot), cell_m),
          make_neighbourhood_template(params.d_max_m, cell_m)};
}

Grid<std::int32_t> lee_wave(const Grid<SafeCell>& safe, CellIndex start,
                            std::optional<CellIndex> goal) {
  const int w = safe.width, h = safe.height;
  Grid<std::int32_t> wave(w, h, -1);
  if (!safe.contains(start.col, start.row) || safe.at(start) != SafeCell::kSafe) return wave;
  std::vector<CellIndex> queue;
  queue.reserve(1024);
  queue.push_back(start);
  wave.at(start) = 0;
  std::int32_t stop = std::numeric_limits<std::int32_t>::max();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const CellIndex c = queue[head];
    const std::int32_t k = wave.at(c);
    if (k >= stop) continue;  // cells beyond the goal's index are not mapped out
    for (const auto& d : kEight) {
      const CellIndex n{c.col + d.col, c.row + d.row};
      if (n.col < 0 || n.row < 0 || n.col >= w || n.row >= h) continue;
      std::int32_t& v = wave.at(n);
      if (v >= 0 || safe.at(n) != SafeCell::kSafe) continue;
      // No corner cutting: a diagonal step needs both side cells safe, as the supercover of a
      // diagonal move does; otherwise the region could lead through a gap no move can take.
      if (d.col != 0 && d.row != 0 &&
          (safe.at(c.col + d.col, c.row) != SafeCell::kSafe ||
           safe.at(c.col, c.row + d.row) != SafeCell::kSafe))
        continue;
      v = k + 1;
      if (goal && n == *goal) stop = v;
      queue.push_back(n);
    }
  }
  return wave;
}

Grid<std::uint8_t> trajectory_region(const Grid<std::int32_t>& wave, CellIndex start,
                                     CellIndex goal) {
  Grid<std::uint8_t> region(wave.width, wave.height, 0);
  if (!wave.contains(goal.col, goal.row) || wave.at(goal) < 0 ||
      !wave.contains(start.col, start.row))
    return region;
  // Depth-first from the goal down the wave: a cell belongs to a minimal-index path iff it is
  // reached by steps that each lower the index by one (every such chain ends at the start, the
  // only cell with index 0). The stack holds cells whose predecessors are still to be examined.
  std::vector<CellIndex> stack{goal};
  region.at(goal) = 1;
  while (!stack.empty()) {
    const CellIndex c = stack.back();
    stack.pop_back();
    const std::int32_t k = wave.at(c);
    if (k == 0) continue;
    for (const auto& d : kEight) {
      const CellIndex n{c.col + d.col, c.row + d.row};
      if (!wave.contains(n.col, n.row) || wave.at(n) != k - 1 || region.at(n)) continue;
      region.at(n) = 1;
      stack.push_back(n);
    }
  }
  return region;
}

Route make_route(const std::vector<CellIndex>& cells, const GridGeometry& geometry,
                 std::optional<double> start_heading_deg, std::optional<double> goal_heading_deg) {
  Route route;
  route.cells = cells;
  for (const auto& c : cells) route.waypoints_map.push_back(geometry.center_of(c));
  std::optional<double> heading = start_heading_deg;
  for (std::size_t i = 1; i < cells.size(); ++i) {
    const Eigen::Vector2d d = route.waypoints_map[i] - route.waypoints_map[i - 1];
    const double dir = std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
    // Without a start heading the robot is taken to face its first move.
    const double turn = heading ? normalize_deg(dir - *heading) : 0.0;
    route.commands.push_back({turn, d.norm()});
    route.length_m += d.norm();
    heading = dir;
  }
  route.moves = static_cast<int>(route.commands.size());
  if (goal_heading_deg) {
    const double turn = heading ? normalize_deg(*goal_heading_deg - *heading) : 0.0;
    if (std::abs(turn) > 1e-6) route.commands.push_back({turn, 0.0});
  }
  for (const auto& c : route.commands)
    if (std::abs(c.turn_deg) > 1e-6) ++route.turns;
  return route;
}

namespace {

CellIndex checked_cell(const Grid<SafeCell>& safe, const GridGeometry& geo, const Pose2& pose,
                       const std::string& which) {
  const auto& p = pose.position_map;
  if (!p.allFinite()) throw OutsideMapError(which + " is not a finite point");
  const CellIndex c = geo.cell_of(p);
  if (!geo.contains(c)) {
    const Eigen::Vector2d lo = geo.origin_m();
    const Eigen::Vector2d hi = lo + Eigen::Vector2d(geo.width(), geo.height()) * geo.cell_m();
    throw OutsideMapError(which + " " + point_str(p) + " m is outside the map (x in [" +
                          fmt(lo.x()) + ", " + fmt(hi.x()) + "), y in [" + fmt(lo.y()) + ", " +
                          fmt(hi.y()) + "))");
  }
  const SafeCell s = safe.at(c);
  if (s == SafeCell::kSafe) return c;
  double best = std::numeric_limits<double>::infinity();
  CellIndex nearest{-1, -1};
  for (int r = 0; r < safe.height; ++r)
    for (int col = 0; col < safe.width; ++col) {
      if (safe.at(col, r) != SafeCell::kSafe) continue;
      const double d = (geo.center_of({col, r}) - p).norm();
      if (d < best) best = d, nearest = {col, r};
    }
  const std::string where = s == SafeCell::kObstacle ? "on an obstacle"
                            : s == SafeCell::kOutside
                                ? "outside the room (unknown area)"
                                : "in the unsafe zone (closer than d_save to an obstacle)";
  if (nearest.col < 0)
    throw UnsafePointError(
        which + " " + point_str(p) + " m is " + where + ", and the map has no safe cell at all",
        -1.0);
  throw UnsafePointError(which + " " + point_str(p) + " m is " + where +
                             ": the nearest safe cell is " + fmt(best) + " m away at " +
                             point_str(geo.center_of(nearest)),
                         best);
}

}  // namespace

PlanResult plan_routes(const Grid<SafeCell>& safe, const GridGeometry& geometry, const Pose2& start,
                       const Pose2& goal, const Templates& templates, const PlannerParams& params) {
  validate(params);
  if (safe.width != geometry.width() || safe.height != geometry.height())
    throw UsageError("plan_routes: safe zone and geometry differ in size");
  const auto& t = templates.neighbourhood;
  if (std::abs(t.cell_m - geometry.cell_m()) > 1e-9 * geometry.cell_m() ||
      std::abs(t.d_max_m - params.d_max_m) > 1e-12)
    throw UsageError(
        "plan_routes: the neighbourhood template was built for another cell size or d_max_m");
  PlanResult res;
  res.start_cell = checked_cell(safe, geometry, start, "start");
  res.goal_cell = checked_cell(safe, geometry, goal, "goal");
  detail::SearchBudget budget(params);  // max_seconds counts from here: wave, region, searches
  res.wave = lee_wave(safe, res.start_cell, res.goal_cell);
  if (res.wave.at(res.goal_cell) < 0) {
    res.region = Grid<std::uint8_t>(safe.width, safe.height, 0);
    res.message = "no route: the goal is not connected to the start through the safe zone";
    return res;
  }
  res.region = trajectory_region(res.wave, res.start_cell, res.goal_cell);

  std::vector<std::pair<std::vector<CellIndex>, std::string>> found;
  if (params.paper_rules) {
    auto routes = paper_search(safe, res.wave, res.region, res.start_cell, res.goal_cell, t, params,
                               res.paper_nodes, budget);
    for (auto& r : routes) {
      const int m = static_cast<int>(r.size()) - 1;
      if (res.paper_best_moves < 0 || m < res.paper_best_moves) res.paper_best_moves = m;
      found.emplace_back(std::move(r), "paper");
    }
    if (res.start_cell == res.goal_cell)
      found.emplace_back(std::vector<CellIndex>{res.start_cell}, "paper");
  }
  const bool optimal = params.search != RouteSearch::kPaper;
  if (optimal) {
    // The paper's best route bounds the search. The exact search only looks for fewer moves; the
    // min-link search for at most as many, so that its route is also the shortest of them.
    const bool paper = res.paper_best_moves >= 0;
    const int most = std::numeric_limits<int>::max();
    ExactResult ex = params.search == RouteSearch::kExact
                         ? detail::exact_search(safe, res.start_cell, res.goal_cell, t, params,
                                                paper ? res.paper_best_moves : most, budget)
                         : detail::min_link_search(safe, res.start_cell, res.goal_cell, t, params,
                                                   paper ? res.paper_best_moves : most, budget);
    res.exact_complete = ex.complete;
    res.exact_nodes = ex.nodes;
    if (ex.cells) {
      res.exact_best_moves = static_cast<int>(ex.cells->size()) - 1;
      found.emplace_back(std::move(*ex.cells), to_string(params.search));
    } else if (ex.complete && res.paper_best_moves >= 0) {
      res.exact_best_moves = res.paper_best_moves;  // proven: no route with fewer moves exists
    }
  }
  for (auto& [cells, source] : found) {
    Route r = make_route(cells, geometry, start.heading_deg, goal.heading_deg);
    r.source = source;
    const bool dup = std::any_of(res.routes.begin(), res.routes.end(),
                                 [&](const Route& o) { return o.cells == r.cells; });
    if (!dup) res.routes.push_back(std::move(r));
  }
  std::stable_sort(res.routes.begin(), res.routes.end(), [](const Route& a, const Route& b) {
    if (a.moves != b.moves) return a.moves < b.moves;
    if (std::abs(a.length_m - b.length_m) > 1e-9) return a.length_m < b.length_m;
    return a.turns < b.turns;
  });
  if (static_cast<int>(res.routes.size()) > params.max_routes)
    res.routes.resize(static_cast<std::size_t>(params.max_routes));
  res.budget_reached = budget.reached();
  if (res.routes.empty()) {
    res.message =
        (optimal && !res.exact_complete) || (!optimal && !res.budget_reached.empty())
            ? "no route found within the work budget: " + budget_message(params, res)
            : "no route: the goal is connected to the start, but not by straight moves of " +
                  fmt(params.d_min_m) + " to " + fmt(params.d_max_m) + " m through the safe zone";
  } else if (params.paper_rules && optimal && res.exact_best_moves >= 0 &&
             (res.paper_best_moves < 0 || res.exact_best_moves < res.paper_best_moves)) {
    res.message = std::string("the ") + to_string(params.search) +
                  " search found a route with fewer moves than the paper's rules";
  }
  return res;
}

}  // namespace indoormap::planning
