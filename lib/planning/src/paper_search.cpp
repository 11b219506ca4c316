#include <algorithm>
#include <deque>
#include <limits>

#include "planner_internal.hpp"

namespace indoormap::planning::detail {

namespace {

// Virgin 8-neighbours of every region cell (neighbours outside M_tb).
Grid<std::uint8_t> virgin_counts(const Grid<std::uint8_t>& region) {
  const int w = region.width, h = region.height;
  Grid<std::uint8_t> virgin(w, h, 0);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      if (!region.at(c, r)) continue;
      int n = 0;
      for (const auto& d : kEight) {
        const int cc = c + d.col, rr = r + d.row;
        if (!region.contains(cc, rr) || !region.at(cc, rr)) ++n;
      }
      virgin.at(c, r) = static_cast<std::uint8_t>(n);
    }
  return virgin;
}

struct Node {
  CellIndex cell;
  std::int32_t parent;
  int moves;
};

// The cell sequence of every route that reached the goal (ends), in the order found.
std::vector<std::vector<CellIndex>> trace_routes(const std::vector<Node>& nodes,
                                                 const std::vector<std::int32_t>& ends) {
  std::vector<std::vector<CellIndex>> routes;
  for (const std::int32_t e : ends) {
    std::vector<CellIndex> cells;
    for (std::int32_t i = e; i >= 0; i = nodes[static_cast<std::size_t>(i)].parent)
      cells.push_back(nodes[static_cast<std::size_t>(i)].cell);
    std::reverse(cells.begin(), cells.end());
    routes.push_back(std::move(cells));
  }
  return routes;
}

}  // namespace

/// The paper's trajectory scenario generation (see the header and docs/plan-route.md). Returns
/// the cell sequences of every route that reached the goal, in the order found.
std::vector<std::vector<CellIndex>> paper_search(const Grid<SafeCell>& safe,
                                                 const Grid<std::int32_t>& wave,
                                                 const Grid<std::uint8_t>& region, CellIndex start,
                                                 CellIndex goal, const NeighbourhoodTemplate& t,
                                                 const PlannerParams& p, std::int64_t& expanded,
                                                 SearchBudget& budget) {
  const int w = safe.width, h = safe.height;
  const auto id_of = offset_index(t);
  const Grid<std::uint8_t> virgin = virgin_counts(region);
  std::vector<Node> nodes{{start, -1, 0}};
  std::deque<std::int32_t> queue{0};
  std::vector<std::uint8_t> enqueued(safe.size(), 0);
  enqueued[idx(w, start)] = 1;
  std::vector<std::uint32_t> visible(t.end_points.size(), 0);
  std::vector<std::uint32_t> passed(safe.size(), 0), unique(safe.size(), 0);
  std::uint32_t gen = 0;
  std::vector<std::int32_t> ends, ray_passed;
  int best_end = std::numeric_limits<int>::max();
  expanded = 0;

  while (!queue.empty()) {
    const std::int32_t ni = queue.front();
    queue.pop_front();
    const Node node = nodes[static_cast<std::size_t>(ni)];
    if (node.cell == goal) {
      ends.push_back(ni);
      best_end = std::min(best_end, node.moves);
      continue;
    }
    // Paths "significantly" longer than the best found are not explored further.
    if (best_end != std::numeric_limits<int>::max() && node.moves + 1 > best_end + p.extra_moves)
      continue;
    if (!budget.spend("paper", expanded)) break;
    ++gen;
    const auto& wv = wave.data;
    const auto& rg = region.data;
    // Safety of a move is judged on the safe zone (the whole supercover must be kSafe); the
    // region M_tb only bounds where rays may go and end (below). Requiring the supercover itself
    // to lie in M_tb would block every diagonal through a one-cell-wide band of the region.
    const auto& sd = safe.data;
    for_each_visible(
        t, w, h, node.cell, [&](std::size_t i) { return sd[i] == SafeCell::kSafe; },
        [&](std::int32_t e) { visible[static_cast<std::size_t>(e)] = gen; });
    // A straight move to the goal ends the path here: no other move from this node is considered.
    const auto goal_id =
        end_point_id(t, id_of, {goal.col - node.cell.col, goal.row - node.cell.row});
    if (goal_id >= 0 && visible[static_cast<std::size_t>(goal_id)] == gen) {
      nodes.push_back({goal, ni, node.moves + 1});
      queue.push_back(static_cast<std::int32_t>(nodes.size() - 1));
      continue;
    }
    const std::int32_t here = wv[idx(w, node.cell)];
    std::int32_t node_max = -1;
    std::vector<std::int32_t> node_opt;
    for (const auto& ray : t.rays) {
      std::int32_t last = -1;
      bool abandoned = false;
      ray_passed.clear();
      for (const std::int32_t e : ray) {
        if (visible[static_cast<std::size_t>(e)] != gen) break;  // blocked: stop before it
        const auto& o = t.end_points[static_cast<std::size_t>(e)].offset;
        const CellIndex c{node.cell.col + o.col, node.cell.row + o.row};
        if (!rg[idx(w, c)]) break;   // virgin area (outside M_tb): stop before it
        if (wv[idx(w, c)] < here) {  // the wave index falls: this turning angle leads back
          abandoned = true;
          break;
        }
        if (last >= 0) ray_passed.push_back(last);  // passed over on the way to e
        last = e;
      }
      if (abandoned || last < 0) continue;
      // The passability matrix records the points this ray passes over. Only rays that are kept
      // count: a ray abandoned further on (the wave index falls) offers no move past them.
      for (const std::int32_t q : ray_passed) {
        const auto& qo = t.end_points[static_cast<std::size_t>(q)].offset;
        passed[idx(w, {node.cell.col + qo.col, node.cell.row + qo.row})] = gen;
      }
      const auto& ep = t.end_points[static_cast<std::size_t>(last)];
      if (ep.length_m < p.d_min_m) continue;  // too short for an intermediate move
      const CellIndex c{node.cell.col + ep.offset.col, node.cell.row + ep.offset.row};
      const std::size_t ci = idx(w, c);
      if (unique[ci] == gen) continue;
      if (virgin.data[ci] >= 5) {
        node_opt.push_back(last);
        unique[ci] = gen;
      }
      if (node_max < 0) {
        node_max = last;
        unique[ci] = gen;
      } else {
        const auto& mp = t.end_points[static_cast<std::size_t>(node_max)];
        const std::int32_t wm =
            wv[idx(w, {node.cell.col + mp.offset.col, node.cell.row + mp.offset.row})];
        if (wv[ci] > wm || (wv[ci] == wm && ep.length_m < mp.length_m)) {
          node_max = last;
          unique[ci] = gen;
        }
      }
    }
    if (node_max >= 0) node_opt.push_back(node_max);
    for (const std::int32_t e : node_opt) {
      const auto& o = t.end_points[static_cast<std::size_t>(e)].offset;
      const CellIndex c{node.cell.col + o.col, node.cell.row + o.row};
      const std::size_t ci = idx(w, c);
      if (passed[ci] == gen || enqueued[ci]) continue;
      enqueued[ci] = 1;
      nodes.push_back({c, ni, node.moves + 1});
      queue.push_back(static_cast<std::int32_t>(nodes.size() - 1));
    }
  }
  return trace_routes(nodes, ends);
}

}  // namespace indoormap::planning::detail
