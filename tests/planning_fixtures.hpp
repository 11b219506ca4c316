#pragma once
// Shared fixtures of the test_planning_*.cpp files: independent references (supercover
// test, exact search), route checks and random maps.
#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <set>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/formats/ros_map.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "indoormap/planning/planner.hpp"
#include "plan_config.hpp"
#include "test_support.hpp"

using namespace indoormap;
using namespace indoormap::planning;

namespace planning_fixtures {

// --- independent references -------------------------------------------------------------

/// Does the segment between cell centres a and b touch the closed square of cell c? Exact in
/// doubles of half-integers: clip the segment (Liang-Barsky) against the square.
inline bool touches(CellIndex a, CellIndex b, CellIndex c) {
  double t0 = 0.0, t1 = 1.0;
  const double px = a.col, py = a.row, dx = b.col - a.col, dy = b.row - a.row;
  auto clip = [&](double p, double q) {  // p * t <= q
    if (p == 0) return q >= 0;
    const double t = q / p;
    if (p < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    return t0 <= t1;
  };
  return clip(-dx, px - (c.col - 0.5)) && clip(dx, (c.col + 0.5) - px) &&
         clip(-dy, py - (c.row - 0.5)) && clip(dy, (c.row + 0.5) - py);
}

inline bool move_is_safe(const Grid<SafeCell>& safe, CellIndex a, CellIndex b) {
  for (int r = std::min(a.row, b.row) - 1; r <= std::max(a.row, b.row) + 1; ++r)
    for (int c = std::min(a.col, b.col) - 1; c <= std::max(a.col, b.col) + 1; ++c)
      if (touches(a, b, {c, r}) && (!safe.contains(c, r) || safe.at(c, r) != SafeCell::kSafe))
        return false;
  return true;
}

/// Reference exact search: breadth-first over (cell, heading) states, heading = index of the last
/// move's direction (0 = none yet), with brute-force move checks. Returns the fewest moves, or -1.
inline int reference_min_moves(const Grid<SafeCell>& safe, CellIndex s, CellIndex g, double cell_m,
                               double d_min, double d_max) {
  if (s == g) return 0;
  const int r = static_cast<int>(std::floor(d_max / cell_m + 1e-9));
  std::vector<CellIndex> dirs;  // every move offset is its own heading
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx)
      if ((dx || dy) && std::hypot(dx, dy) * cell_m <= d_max + 1e-9) dirs.push_back({dx, dy});
  // The reachable (cell, heading) states after k moves; a cell is expanded once per BFS layer
  // with any heading, since the move rules do not depend on the heading.
  const int w = safe.width;
  std::vector<int> moves_at(safe.size(), -1);
  std::deque<CellIndex> q{s};
  moves_at[static_cast<std::size_t>(s.row) * w + s.col] = 0;
  while (!q.empty()) {
    const CellIndex c = q.front();
    q.pop_front();
    const int k = moves_at[static_cast<std::size_t>(c.row) * w + c.col];
    for (const auto& d : dirs) {
      const CellIndex n{c.col + d.col, c.row + d.row};
      if (!safe.contains(n.col, n.row) || safe.at(n) != SafeCell::kSafe) continue;
      const double len = std::hypot(d.col, d.row) * cell_m;
      if (!(n == g) && len < d_min - 1e-12) continue;
      if (moves_at[static_cast<std::size_t>(n.row) * w + n.col] >= 0) continue;
      if (!move_is_safe(safe, c, n)) continue;
      if (n == g) return k + 1;
      moves_at[static_cast<std::size_t>(n.row) * w + n.col] = k + 1;
      q.push_back(n);
    }
  }
  return -1;
}

/// Checks the acceptance properties of one route; returns "" or the first violation.
inline std::string check_route(const Route& route, const Grid<SafeCell>& safe,
                               const GridGeometry& geo, CellIndex s, CellIndex g,
                               const PlannerParams& p) {
  if (route.cells.empty() || !(route.cells.front() == s)) return "does not start at the start cell";
  if (!(route.cells.back() == g)) return "does not end at the goal cell";
  if ((route.waypoints_map.front() - geo.center_of(s)).norm() > 1e-9)
    return "first waypoint is not the start";
  if ((route.waypoints_map.back() - geo.center_of(g)).norm() > 1e-9)
    return "last waypoint is not the goal";
  if (route.moves != static_cast<int>(route.cells.size()) - 1) return "moves != segments";
  double total = 0;
  for (std::size_t i = 1; i < route.cells.size(); ++i) {
    const double len = (route.waypoints_map[i] - route.waypoints_map[i - 1]).norm();
    total += len;
    if (len > p.d_max_m + 1e-9) return "move " + std::to_string(i) + " longer than D_max";
    if (i + 1 < route.cells.size() && len < p.d_min_m - 1e-9)
      return "move " + std::to_string(i) + " shorter than D_min";
    if (!move_is_safe(safe, route.cells[i - 1], route.cells[i]))
      return "move " + std::to_string(i) + " leaves the safe zone";
    if (std::abs(route.commands[i - 1].move_m - len) > 1e-9) return "command length mismatch";
  }
  if (std::abs(total - route.length_m) > 1e-6) return "length mismatch";
  return "";
}

struct RandomMap {
  Grid<Cell> layout;
  GridGeometry geo;
};

/// A room with random rectangular furniture and a random wall with a door (fixed seed).
inline RandomMap random_map(std::mt19937& rng, double cell_m) {
  std::uniform_int_distribution<int> size(18, 34);
  const int w = size(rng), h = size(rng);
  RandomMap m{Grid<Cell>(w, h, Cell::kFree), GridGeometry({0, 0}, cell_m, w, h)};
  for (int c = 0; c < w; ++c) m.layout.at(c, 0) = m.layout.at(c, h - 1) = Cell::kWall;
  for (int r = 0; r < h; ++r) m.layout.at(0, r) = m.layout.at(w - 1, r) = Cell::kWall;
  std::uniform_int_distribution<int> n_boxes(1, 7);
  const int nb = n_boxes(rng);
  for (int b = 0; b < nb; ++b) {
    const int bw = std::uniform_int_distribution<int>(1, 6)(rng),
              bh = std::uniform_int_distribution<int>(1, 6)(rng);
    const int c0 = std::uniform_int_distribution<int>(1, w - 2)(rng),
              r0 = std::uniform_int_distribution<int>(1, h - 2)(rng);
    for (int r = r0; r < std::min(h - 1, r0 + bh); ++r)
      for (int c = c0; c < std::min(w - 1, c0 + bw); ++c) m.layout.at(c, r) = Cell::kFurniture;
  }
  if (rng() % 2) {  // an inner wall with a door
    const int c = std::uniform_int_distribution<int>(5, w - 6)(rng);
    const int door = std::uniform_int_distribution<int>(2, h - 8)(rng);
    for (int r = 1; r < h - 1; ++r)
      if (r < door || r > door + 5) m.layout.at(c, r) = Cell::kWall;
  }
  return m;
}

inline std::vector<CellIndex> safe_cells(const Grid<SafeCell>& safe) {
  std::vector<CellIndex> out;
  for (int r = 0; r < safe.height; ++r)
    for (int c = 0; c < safe.width; ++c)
      if (safe.at(c, r) == SafeCell::kSafe) out.push_back({c, r});
  return out;
}

}  // namespace planning_fixtures
