// Minimum-link route search (docs/route-planning.md): the fewest "turn, then go straight" moves
// between two cells over the same move graph as the exact search (a move ends on any template end
// point whose supercover line is kSafe; every move but the last is at least D_min long), then the
// shortest of the fewest-moves routes.
//
// Why it is fast: the exact search's straight-line bound ceil(|goal - c| / D_max) is weak in a
// building (the route runs around walls), so its A* expands most of the map. Here the bound is
// the geodesic one: a straight move of length L is also a path of 8-neighbour steps through its
// supercover cells (each y step of the staircase pairs with the x step before it into a
// diagonal), of chamfer length 5 (dx - dy) + 7 dy <= 5 * octile <= 5 K L, K = sqrt(4 - 2 sqrt 2)
// the largest octile / Euclidean ratio. So a cell at chamfer distance D from the goal needs at
// least ceil(D / (5 K D_max)) more moves: an admissible and consistent bound, computed for every
// cell by one bucketed Dijkstra from the goal (weights 5 and 7, diagonals allowed past corners,
// which only lowers D).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "planner_internal.hpp"

namespace indoormap::planning::detail {

namespace {

/// sqrt(4 - 2 sqrt 2), rounded up: the largest octile / Euclidean length ratio.
constexpr double kOctile = 1.0823922002923941 * (1 + 1e-12);

}  // namespace

std::vector<std::uint32_t> chamfer_from(const Grid<SafeCell>& safe, CellIndex goal) {
  const int w = safe.width, h = safe.height;
  std::vector<std::uint32_t> d(safe.size(), kFar);
  std::array<std::vector<std::int32_t>, 8> bucket;  // weights 5 and 7 < 8
  const auto gi = static_cast<std::int32_t>(idx(w, goal));
  d[static_cast<std::size_t>(gi)] = 0;
  bucket[0].push_back(gi);
  std::size_t pending = 1;
  for (std::uint32_t cur = 0; pending > 0; ++cur) {
    auto& b = bucket[cur & 7];  // a step never pushes into the bucket being read
    for (const std::int32_t i : b) {
      --pending;
      if (d[static_cast<std::size_t>(i)] != cur) continue;
      const int c = i % w, r = i / w;
      for (const auto& s : kEight) {
        const int cc = c + s.col, rr = r + s.row;
        if (cc < 0 || rr < 0 || cc >= w || rr >= h) continue;
        const std::size_t j = idx(w, {cc, rr});
        if (safe.data[j] != SafeCell::kSafe) continue;
        const std::uint32_t nd = cur + (s.col != 0 && s.row != 0 ? 7u : 5u);
        if (nd >= d[j]) continue;
        d[j] = nd;
        bucket[nd & 7].push_back(static_cast<std::int32_t>(j));
        ++pending;
      }
    }
    b.clear();
  }
  return d;
}

namespace {

/// Upper bound (cells) on the distance from each prefix-tree node to the end points of its
/// subtree, bottom up over the depth-first order.
std::vector<float> subtree_reach(const NeighbourhoodTemplate& t) {
  const std::size_t n = t.dx.size();
  std::vector<float> reach(n, 0.0f);
  for (std::size_t i = n; i-- > 0;) {
    float r = 0.0f;  // every leaf is an end point
    for (auto j = i + 1; j < static_cast<std::size_t>(t.skip[i]);
         j = static_cast<std::size_t>(t.skip[j]))
      r = std::max(r,
                   reach[j] + static_cast<float>(std::hypot(t.dx[j] - t.dx[i], t.dy[j] - t.dy[i])));
    reach[i] = r * (1 + 1e-6f) + 1e-4f;
  }
  return reach;
}

/// The move graph, the goal's chamfer distances and the bound on moves they give.
struct Graph {
  const Grid<SafeCell>& safe;
  const NeighbourhoodTemplate& t;
  const PlannerParams& p;
  std::int32_t goal;
  std::vector<std::int32_t> id_of = offset_index(t);
  std::vector<std::uint32_t> dist = chamfer_from(safe, {goal % safe.width, goal / safe.width});
  std::vector<float> reach = subtree_reach(t);
  /// Chamfer length of the longest move (the template's end points satisfy dx^2 + dy^2 <= rc^2
  /// + 1e-9): a cell at chamfer distance D needs at least ceil(D / per_move) more moves.
  double per_move = 5.0 * kOctile * std::sqrt(std::pow(t.d_max_m / t.cell_m, 2) + 1e-9);

  /// The largest chamfer distance of a cell that can reach the goal in `moves` more moves.
  double within(int moves) const { return (moves + 1e-9) * per_move; }
  /// Lower bound on the moves from cell i to the goal; -1 when not connected.
  int hops(std::int32_t i) const {
    const auto d = dist[static_cast<std::size_t>(i)];
    return d == kFar ? -1 : static_cast<int>(std::ceil(d / per_move - 1e-9));
  }
  /// Is `to` one move from `from` (the last move: any length)? The same test as the template walk.
  bool sees(std::int32_t from, std::int32_t to) const {
    const int w = safe.width;
    const CellIndex a{from % w, from / w}, b{to % w, to / w};
    if (end_point_id(t, id_of, {b.col - a.col, b.row - a.row}) < 0) return false;
    for (const auto& o : supercover(b.col - a.col, b.row - a.row)) {
      const int c = a.col + o.col, r = a.row + o.row;
      if (!safe.contains(c, r) || safe.at(c, r) != SafeCell::kSafe) return false;
    }
    return true;
  }
  /// Calls f(cell, length_m) for every cell other than the goal one intermediate move (at least
  /// D_min) from `from` that can reach the goal in `moves` more moves. The template walk of
  /// for_each_visible (the same safety test), also skipping a subtree when even its farthest end
  /// point cannot come within that distance of the goal: D(end) >= D(node) - 5 K |end - node|
  /// (the line from the node to the end is a chamfer path of at most that length). Sets `cut`
  /// when the bound skipped anything.
  template <class F>
  void moves_from(std::int32_t from, int moves, bool& cut, F&& f) const {
    const int w = safe.width, h = safe.height;
    const CellIndex c{from % w, from / w};
    const double limit = within(moves);
    const std::size_t n = t.dx.size();
    std::size_t i = 0;
    while (i < n) {
      const int cc = c.col + t.dx[i], rr = c.row + t.dy[i];
      if (cc < 0 || rr < 0 || cc >= w || rr >= h) {
        i = static_cast<std::size_t>(t.skip[i]);
        continue;
      }
      const std::size_t j = idx(w, {cc, rr});
      if (safe.data[j] != SafeCell::kSafe) {
        i = static_cast<std::size_t>(t.skip[i]);
        continue;
      }
      const double d = dist[j];
      if (d - 5.0 * kOctile * reach[i] > limit) {
        cut = true;
        i = static_cast<std::size_t>(t.skip[i]);
        continue;
      }
      if (const auto e = t.end_point[i]; e >= 0 && static_cast<std::int32_t>(j) != goal) {
        const double len = t.end_points[static_cast<std::size_t>(e)].length_m;
        if (d > limit)
          cut = true;
        else if (len >= p.d_min_m)
          f(static_cast<std::int32_t>(j), len);
      }
      ++i;
    }
  }
};

/// Tie-break among routes of equal moves: each waypoint in turn moves to the cell that makes its
/// two moves shortest while both stay valid (two sweeps). A local improvement: the route keeps
/// its moves and gets no longer, but is not always the shortest with that many moves.
void shorten(const Graph& gr, std::vector<std::int32_t>& route) {
  const int w = gr.safe.width;
  auto dist = [w](std::int32_t a, std::int32_t b) {
    return std::hypot(a % w - b % w, a / w - b / w);
  };
  for (int sweep = 0; sweep < 2; ++sweep)
    for (std::size_t i = 1; i + 1 < route.size(); ++i) {
      const std::int32_t prev = route[i - 1], next = route[i + 1];
      const bool next_is_goal = i + 2 == route.size();
      double best = dist(prev, route[i]) + dist(route[i], next) - 1e-9;
      bool cut = false;
      gr.moves_from(prev, 1 << 20, cut, [&](std::int32_t x, double) {
        const double d = dist(prev, x) + dist(x, next);
        if (d >= best || (!next_is_goal && dist(x, next) * gr.t.cell_m < gr.p.d_min_m) ||
            !gr.sees(x, next))
          return;
        best = d;
        route[i] = x;
      });
    }
}

}  // namespace

std::vector<std::uint16_t> moves_bound_from(const std::vector<std::uint32_t>& d,
                                            const NeighbourhoodTemplate& t) {
  const double per_move = 5.0 * kOctile * std::sqrt(std::pow(t.d_max_m / t.cell_m, 2) + 1e-9);
  std::vector<std::uint16_t> out(d.size(), kNoMovesBound);
  for (std::size_t i = 0; i < d.size(); ++i)
    if (d[i] != kFar)
      out[i] = static_cast<std::uint16_t>(
          std::min(65534.0, std::ceil(static_cast<double>(d[i]) / per_move - 1e-9)));
  return out;
}

ExactResult min_link_search(const Grid<SafeCell>& safe, CellIndex start, CellIndex goal,
                            const NeighbourhoodTemplate& t, const PlannerParams& p, int bound,
                            SearchBudget& budget) {
  ExactResult res;
  if (!safe.contains(start.col, start.row) || !safe.contains(goal.col, goal.row) ||
      safe.at(start) != SafeCell::kSafe || safe.at(goal) != SafeCell::kSafe)
    return res;
  if (start == goal) {
    res.cells = std::vector<CellIndex>{start};
    return res;
  }
  const int w = safe.width;
  const auto si = static_cast<std::int32_t>(idx(w, start));
  const Graph gr{safe, t, p, static_cast<std::int32_t>(idx(w, goal))};
  if (gr.hops(si) < 0) return res;  // not connected to the goal at all
  std::vector<std::int32_t> route;
  if (layered_fewest_moves(safe, t, p, si, gr.goal, bound, route, res, budget) < 0) return res;
  shorten(gr, route);
  res.cells.emplace();
  for (const auto i : route) res.cells->push_back({i % w, i / w});
  return res;
}

}  // namespace indoormap::planning::detail

namespace indoormap::planning {

ExactResult min_link_moves(const Grid<SafeCell>& safe, CellIndex start, CellIndex goal,
                           const NeighbourhoodTemplate& tmpl, const PlannerParams& params,
                           int bound) {
  detail::SearchBudget budget(params);
  return detail::min_link_search(safe, start, goal, tmpl, params, bound, budget);
}

}  // namespace indoormap::planning
