// A deterministic far-apart pair of safe cells (benchmarks and tests of the route searches).
#include "indoormap/planning/planner.hpp"
#include "planner_internal.hpp"

namespace indoormap::planning {

namespace {

/// The highest wave index and its lowest flat index.
CellIndex farthest(const Grid<std::int32_t>& wave) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < wave.size(); ++i)
    if (wave.data[i] > wave.data[best]) best = i;
  const auto w = static_cast<std::size_t>(wave.width);
  return {static_cast<int>(best % w), static_cast<int>(best / w)};
}

}  // namespace

std::optional<std::pair<CellIndex, CellIndex>> far_apart_cells(const Grid<SafeCell>& safe) {
  // Components with the Lee wave's connectivity (a diagonal step needs both side cells safe),
  // labelled in row-major order of their first cell; the largest (the first of equal size) wins.
  const int w = safe.width, h = safe.height;
  std::vector<std::int32_t> label(safe.size(), -1);
  std::vector<CellIndex> queue;
  std::size_t best_size = 0;
  CellIndex best_first{-1, -1};
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      if (safe.at(c, r) != SafeCell::kSafe || label[detail::idx(w, {c, r})] >= 0) continue;
      queue.assign(1, {c, r});
      label[detail::idx(w, {c, r})] = 1;
      for (std::size_t head = 0; head < queue.size(); ++head) {
        const CellIndex q = queue[head];
        for (const auto& d : detail::kEight) {
          const CellIndex n{q.col + d.col, q.row + d.row};
          if (!safe.contains(n.col, n.row) || safe.at(n) != SafeCell::kSafe ||
              label[detail::idx(w, n)] >= 0)
            continue;
          if (d.col != 0 && d.row != 0 &&
              (safe.at(q.col + d.col, q.row) != SafeCell::kSafe ||
               safe.at(q.col, q.row + d.row) != SafeCell::kSafe))
            continue;
          label[detail::idx(w, n)] = 1;
          queue.push_back(n);
        }
      }
      if (queue.size() > best_size) best_size = queue.size(), best_first = {c, r};
    }
  if (best_size == 0) return std::nullopt;
  const CellIndex a = farthest(lee_wave(safe, best_first));
  const CellIndex b = farthest(lee_wave(safe, a));
  return std::make_pair(a, b);
}

}  // namespace indoormap::planning
