#include "indoormap/exploration/coverage.hpp"

#include <algorithm>
#include <cmath>

#include "indoormap/exploration/navigator.hpp"

namespace indoormap::exploration {

ReachableSpace reachable_free_space(const Grid<Cell>& truth, const GridGeometry& g, CellIndex start,
                                    double robot_radius_m) {
  ReachableSpace out;
  out.mask = Grid<std::uint8_t>(truth.width, truth.height, 0);
  const double r = g.to_cells(robot_radius_m);
  const Grid<std::uint8_t> blocked = inflate_obstacles(truth, r);
  if (!truth.contains(start.col, start.row) || blocked.at(start) || truth.at(start) != Cell::kFree)
    return out;
  out.start_free = true;
  // The centre cells: 8-connected flood over unblocked free cells.
  Grid<std::uint8_t> centre(truth.width, truth.height, 0);
  std::vector<CellIndex> queue{start};
  centre.at(start) = 1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const CellIndex c = queue[head];
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        const int cc = c.col + dc, rr = c.row + dr;
        if (!truth.contains(cc, rr) || centre.at(cc, rr) || blocked.at(cc, rr) ||
            truth.at(cc, rr) != Cell::kFree)
          continue;
        centre.at(cc, rr) = 1;
        queue.push_back({cc, rr});
      }
  }
  // Dilate by the radius: stamp discs around the centre cells on the edge of the centre region.
  const int ri = static_cast<int>(std::floor(r));
  for (const CellIndex& c : queue) {
    out.mask.at(c) = 1;
    bool edge = false;
    for (int k = 0; k < 4 && !edge; ++k) {
      const int cc = c.col + (k == 0) - (k == 1), rr = c.row + (k == 2) - (k == 3);
      edge = !truth.contains(cc, rr) || !centre.at(cc, rr);
    }
    if (!edge) continue;
    for (int dr = -ri; dr <= ri; ++dr)
      for (int dc = -ri; dc <= ri; ++dc) {
        const int cc = c.col + dc, rr = c.row + dr;
        if (dc * dc + dr * dr <= r * r && truth.contains(cc, rr) && truth.at(cc, rr) == Cell::kFree)
          out.mask.at(cc, rr) = 1;
      }
  }
  for (std::size_t i = 0; i < out.mask.data.size(); ++i)
    if (out.mask.data[i]) out.cells.push_back(static_cast<std::uint32_t>(i));
  return out;
}

std::vector<Eigen::Vector2d> start_points(const Grid<Cell>& truth, const GridGeometry& g,
                                          double clearance_m,
                                          const std::vector<double>& fractions) {
  const Grid<std::uint8_t> blocked = inflate_obstacles(truth, g.to_cells(clearance_m));
  auto fits = [&](int c, int r) {
    return truth.contains(c, r) && !blocked.at(c, r) && truth.at(c, r) == Cell::kFree;
  };
  Grid<std::uint32_t> label(truth.width, truth.height, 0);
  std::uint32_t next = 0, best = 0;
  std::size_t best_size = 0;
  std::vector<CellIndex> queue;
  for (int r = 0; r < truth.height; ++r)
    for (int c = 0; c < truth.width; ++c) {
      if (!fits(c, r) || label.at(c, r)) continue;
      label.at(c, r) = ++next;
      queue.assign(1, {c, r});
      for (std::size_t h = 0; h < queue.size(); ++h)
        for (int dr = -1; dr <= 1; ++dr)
          for (int dc = -1; dc <= 1; ++dc) {
            const int cc = queue[h].col + dc, rr = queue[h].row + dr;
            if (!fits(cc, rr) || label.at(cc, rr)) continue;
            label.at(cc, rr) = next;
            queue.push_back({cc, rr});
          }
      if (queue.size() > best_size) {
        best_size = queue.size();
        best = next;
      }
    }
  std::vector<CellIndex> region;
  region.reserve(best_size);
  for (int r = 0; r < truth.height; ++r)
    for (int c = 0; c < truth.width; ++c)
      if (best && label.at(c, r) == best) region.push_back({c, r});
  std::vector<Eigen::Vector2d> out;
  if (region.empty()) return out;
  for (double f : fractions) {
    const double k = std::clamp(f, 0.0, 1.0) * static_cast<double>(region.size());
    out.push_back(g.center_of(region[std::min(region.size() - 1, static_cast<std::size_t>(k))]));
  }
  return out;
}

double explored_share(const ReachableSpace& reachable, const Grid<Cell>& built) {
  if (reachable.cells.empty()) return 0.0;
  std::size_t known = 0;
  for (std::uint32_t i : reachable.cells) known += built.data[i] != Cell::kUnknown;
  return static_cast<double>(known) / static_cast<double>(reachable.cells.size());
}

}  // namespace indoormap::exploration
