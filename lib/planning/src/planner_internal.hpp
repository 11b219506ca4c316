#pragma once
// Internal to im_planning: what planner.cpp and paper_search.cpp share.
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "indoormap/planning/planner.hpp"

namespace indoormap::planning::detail {

inline constexpr std::array<CellIndex, 8> kEight = {
    {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};

inline std::size_t idx(int width, CellIndex c) {
  return static_cast<std::size_t>(c.row) * static_cast<std::size_t>(width) +
         static_cast<std::size_t>(c.col);
}

/// Template end point id of every offset in the (2r+1)^2 square around the origin, -1 where the
/// offset is not an end point (outside D_max, or the origin).
inline std::vector<std::int32_t> offset_index(const NeighbourhoodTemplate& t) {
  const int r = t.radius_cells, side = 2 * r + 1;
  std::vector<std::int32_t> id_of(static_cast<std::size_t>(side) * side, -1);
  for (std::size_t i = 0; i < t.end_points.size(); ++i) {
    const auto& o = t.end_points[i].offset;
    id_of[static_cast<std::size_t>(o.row + r) * side + (o.col + r)] = static_cast<std::int32_t>(i);
  }
  return id_of;
}

/// End point id of an offset (offset_index's table), or -1 when it is not in the template.
inline std::int32_t end_point_id(const NeighbourhoodTemplate& t,
                                 const std::vector<std::int32_t>& id_of, CellIndex off) {
  const int r = t.radius_cells, side = 2 * r + 1;
  if (std::abs(off.col) > r || std::abs(off.row) > r) return -1;
  return id_of[static_cast<std::size_t>(off.row + r) * side + (off.col + r)];
}

/// The work budget shared by the searches of one plan_routes call: nodes per search
/// (max_nodes) and seconds over all of them (max_seconds), with progress about once a second.
class SearchBudget {
 public:
  explicit SearchBudget(const PlannerParams& p) : p_(p), start_(std::chrono::steady_clock::now()) {}
  /// Counts one expanded node of `search`; false (and reached() set) when over the budget. The
  /// clock is read every 16 nodes only (one node can take milliseconds on a large template).
  bool spend(const char* search, std::int64_t& nodes) {
    if (++nodes > p_.max_nodes) {
      reached_ = "planner.max_nodes";
      return false;
    }
    if ((nodes & 15) != 0) return true;
    const double s = seconds();
    if (s > p_.max_seconds) {
      reached_ = "planner.max_seconds";
      return false;
    }
    if (p_.progress && s >= next_report_s_) {
      p_.progress(search, nodes, s);
      next_report_s_ = s + 1.0;
    }
    return true;
  }
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  const std::string& reached() const { return reached_; }

 private:
  const PlannerParams& p_;
  std::chrono::steady_clock::time_point start_;
  double next_report_s_ = 1.0;
  std::string reached_;
};

/// Visits every end point of the template visible from `from`: its whole supercover line lies on
/// cells where passable(flat index) holds. One linear pass over the prefix tree; a blocked cell
/// skips its subtree (every line through it).
template <class Passable, class OnEnd>
void for_each_visible(const NeighbourhoodTemplate& t, int width, int height, CellIndex from,
                      Passable&& passable, OnEnd&& on_end) {
  const std::size_t n = t.dx.size();
  std::size_t i = 0;
  while (i < n) {
    const int c = from.col + t.dx[i], r = from.row + t.dy[i];
    if (c < 0 || r < 0 || c >= width || r >= height ||
        !passable(static_cast<std::size_t>(r) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(c))) {
      i = static_cast<std::size_t>(t.skip[i]);
      continue;
    }
    if (t.end_point[i] >= 0) on_end(t.end_point[i]);
    ++i;
  }
}

/// The paper's trajectory scenario generation (see the header and docs/plan-route.md). Returns
/// the cell sequences of every route that reached the goal, in the order found.
std::vector<std::vector<CellIndex>> paper_search(const Grid<SafeCell>& safe,
                                                 const Grid<std::int32_t>& wave,
                                                 const Grid<std::uint8_t>& region, CellIndex start,
                                                 CellIndex goal, const NeighbourhoodTemplate& t,
                                                 const PlannerParams& p, std::int64_t& expanded,
                                                 SearchBudget& budget);

/// exact_min_moves within a shared budget (plan_routes runs both searches within one).
ExactResult exact_search(const Grid<SafeCell>& safe, CellIndex start, CellIndex goal,
                         const NeighbourhoodTemplate& t, const PlannerParams& p, int bound,
                         SearchBudget& budget);

inline constexpr std::uint32_t kFar = std::numeric_limits<std::uint32_t>::max();
/// Chamfer (5-7) distance from `root` to every kSafe cell over 8-neighbour steps between kSafe
/// cells (diagonals past corners too); kFar where not connected. Dial's buckets: O(cells).
std::vector<std::uint32_t> chamfer_from(const Grid<SafeCell>& safe, CellIndex root);

inline constexpr std::uint16_t kNoMovesBound = 0xFFFF;
/// A lower bound on the moves between every cell and the root of the chamfer distances `d`
/// (min_link.cpp: d / the longest move's chamfer length); kNoMovesBound where not connected.
std::vector<std::uint16_t> moves_bound_from(const std::vector<std::uint32_t>& d,
                                            const NeighbourhoodTemplate& t);

/// The fewest moves from start to goal (flat indices) by the bidirectional layered search of
/// link_layers.cpp, at most `bound`; -1 when none (or the budget ran out: res.complete false).
/// `route` gets the cells, start first.
int layered_fewest_moves(const Grid<SafeCell>& safe, const NeighbourhoodTemplate& t,
                         const PlannerParams& p, std::int32_t start, std::int32_t goal, int bound,
                         std::vector<std::int32_t>& route, ExactResult& res, SearchBudget& budget);

/// min_link_moves within a shared budget.
ExactResult min_link_search(const Grid<SafeCell>& safe, CellIndex start, CellIndex goal,
                            const NeighbourhoodTemplate& t, const PlannerParams& p, int bound,
                            SearchBudget& budget);

}  // namespace indoormap::planning::detail
