#pragma once
// Internal to im_planning: what planner.cpp and paper_search.cpp share.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "indoormap/planning/planner.hpp"

namespace indoormap::planning::detail {

inline constexpr std::array<CellIndex, 8> kEight = {
    {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};

inline std::size_t idx(int width, CellIndex c) {
  return static_cast<std::size_t>(c.row) * static_cast<std::size_t>(width) +
         static_cast<std::size_t>(c.col);
}

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
                                                 const PlannerParams& p, std::int64_t& expanded);

}  // namespace indoormap::planning::detail
