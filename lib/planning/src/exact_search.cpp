// The exact search: A* over cells on (moves, length) with the straight-line bound (the reference
// of the min-link search; see planner.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "planner_internal.hpp"

namespace indoormap::planning {

using namespace detail;

ExactResult exact_min_moves(const Grid<SafeCell>& safe, CellIndex start, CellIndex goal,
                            const NeighbourhoodTemplate& t, const PlannerParams& p, int bound) {
  detail::SearchBudget budget(p);
  return detail::exact_search(safe, start, goal, t, p, bound, budget);
}

ExactResult detail::exact_search(const Grid<SafeCell>& safe, CellIndex start, CellIndex goal,
                                 const NeighbourhoodTemplate& t, const PlannerParams& p, int bound,
                                 SearchBudget& budget) {
  ExactResult res;
  const int w = safe.width, h = safe.height;
  if (!safe.contains(start.col, start.row) || !safe.contains(goal.col, goal.row) ||
      safe.at(start) != SafeCell::kSafe || safe.at(goal) != SafeCell::kSafe) {
    return res;
  }
  if (start == goal) {
    res.cells = std::vector<CellIndex>{start};
    return res;
  }
  const double cell_m = t.cell_m;
  // Admissible and consistent: a move covers at most d_max, and a cell other than the goal needs
  // at least one more move. Length: the straight-line distance.
  auto h_moves = [&](CellIndex c) {
    if (c == goal) return 0;
    const double d = std::hypot(c.col - goal.col, c.row - goal.row) * cell_m;
    return std::max(1, static_cast<int>(std::ceil(d / p.d_max_m - 1e-9)));
  };
  auto h_len = [&](CellIndex c) { return std::hypot(c.col - goal.col, c.row - goal.row) * cell_m; };
  const std::size_t n = safe.size();
  std::vector<std::int32_t> g_moves(n, std::numeric_limits<std::int32_t>::max());
  std::vector<double> g_len(n, std::numeric_limits<double>::infinity());
  std::vector<std::int32_t> parent(n, -1);
  std::vector<std::uint8_t> closed(n, 0);
  struct Item {
    int f_moves;
    double f_len;
    std::int32_t cell;
    bool operator>(const Item& o) const {
      return f_moves != o.f_moves ? f_moves > o.f_moves : f_len > o.f_len;
    }
  };
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  const auto si = static_cast<std::int32_t>(idx(w, start));
  const auto gi = static_cast<std::int32_t>(idx(w, goal));
  g_moves[static_cast<std::size_t>(si)] = 0;
  g_len[static_cast<std::size_t>(si)] = 0;
  open.push({h_moves(start), h_len(start), si});
  const auto& sd = safe.data;
  while (!open.empty()) {
    const Item it = open.top();
    open.pop();
    const auto ci = static_cast<std::size_t>(it.cell);
    if (closed[ci]) continue;
    closed[ci] = 1;
    if (it.cell == gi) break;
    if (!budget.spend("exact", res.nodes)) {
      res.complete = false;
      return res;
    }
    const CellIndex c{static_cast<int>(ci % static_cast<std::size_t>(w)),
                      static_cast<int>(ci / static_cast<std::size_t>(w))};
    const int gm = g_moves[ci] + 1;
    const double gl = g_len[ci];
    for_each_visible(
        t, w, h, c, [&](std::size_t i) { return sd[i] == SafeCell::kSafe; },
        [&](std::int32_t e) {
          const auto& ep = t.end_points[static_cast<std::size_t>(e)];
          const CellIndex nc{c.col + ep.offset.col, c.row + ep.offset.row};
          const std::size_t ni = idx(w, nc);
          // Every move but the last is at least D_min long.
          if (static_cast<std::int32_t>(ni) != gi && ep.length_m < p.d_min_m) return;
          if (closed[ni]) return;
          // A route of `bound` moves is known: only strictly fewer moves can improve on it (the
          // length tie-break among equal moves is left to the known route).
          if (gm + h_moves(nc) >= bound) return;
          const double nl = gl + ep.length_m;
          if (gm > g_moves[ni] || (gm == g_moves[ni] && nl >= g_len[ni])) return;
          g_moves[ni] = gm;
          g_len[ni] = nl;
          parent[ni] = it.cell;
          open.push({gm + h_moves(nc), nl + h_len(nc), static_cast<std::int32_t>(ni)});
        });
  }
  if (!closed[static_cast<std::size_t>(gi)]) return res;  // complete, and no route
  std::vector<CellIndex> cells;
  for (std::int32_t i = gi; i >= 0; i = parent[static_cast<std::size_t>(i)])
    cells.push_back({i % w, i / w});
  std::reverse(cells.begin(), cells.end());
  res.cells = std::move(cells);
  return res;
}

}  // namespace indoormap::planning
