#include "indoormap/exploration/navigator.hpp"

#include <array>
#include <cmath>
#include <string>

#include "indoormap/core/errors.hpp"

namespace indoormap::exploration {

void NavigatorParams::validate() const {
  auto nonneg = [](double v, const char* key) {
    if (!(v >= 0.0) || !std::isfinite(v))
      throw UsageError(std::string("navigator: ") + key + " must be >= 0");
  };
  nonneg(robot_radius_m, "robot_radius_m");
  nonneg(inflation_margin_m, "inflation_margin_m");
  nonneg(keep_clear_m, "keep_clear_m");
  nonneg(escape_clear_m, "escape_clear_m");
  if (max_expanded_cells == 0) throw UsageError("navigator: max_expanded_cells must be positive");
}

namespace {
bool obstacle(Cell c) {
  return c == Cell::kWall || c == Cell::kFurniture;
}

std::vector<CellIndex> disc_offsets(double radius_cells) {
  std::vector<CellIndex> out;
  const int r = static_cast<int>(std::floor(radius_cells));
  for (int dr = -r; dr <= r; ++dr)
    for (int dc = -r; dc <= r; ++dc)
      if (dc * dc + dr * dr <= radius_cells * radius_cells) out.push_back({dc, dr});
  return out;
}

constexpr std::array<CellIndex, 8> kAdj = {
    {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, 1}, {1, -1}, {-1, -1}}};
}  // namespace

Grid<std::uint8_t> inflate_obstacles(const Grid<Cell>& map, double radius_cells) {
  Grid<std::uint8_t> out(map.width, map.height, 0);
  const auto disc = disc_offsets(radius_cells);
  for (int r = 0; r < map.height; ++r)
    for (int c = 0; c < map.width; ++c) {
      if (!obstacle(map.at(c, r))) continue;
      out.at(c, r) = 1;
      // Only obstacle cells on a border need their disc stamped.
      bool border = false;
      for (int k = 0; k < 4 && !border; ++k) {
        const int cc = c + kAdj[k].col, rr = r + kAdj[k].row;
        border = map.contains(cc, rr) && !obstacle(map.at(cc, rr));
      }
      if (!border) continue;
      for (const CellIndex& d : disc) {
        const int cc = c + d.col, rr = r + d.row;
        if (map.contains(cc, rr)) out.at(cc, rr) = 1;
      }
    }
  return out;
}

TraversableMap::TraversableMap(const Grid<Cell>& map, const GridGeometry& g,
                               const NavigatorParams& params)
    : map_(&map) {
  params.validate();
  const Grid<std::uint8_t> inflated =
      inflate_obstacles(map, g.to_cells(params.robot_radius_m + params.inflation_margin_m));
  grid_ = Grid<std::uint8_t>(map.width, map.height, 0);
  for (std::size_t i = 0; i < map.data.size(); ++i)
    grid_.data[i] = map.data[i] == Cell::kFree && !inflated.data[i];
  keep_clear_cells_ = static_cast<int>(std::ceil(g.to_cells(params.keep_clear_m)));
}

void TraversableMap::keep_clear(CellIndex c) {
  keep_clear(c, keep_clear_cells_);
}

void TraversableMap::keep_clear(CellIndex c, int radius_cells) {
  const int r = radius_cells;
  for (int dr = -r; dr <= r; ++dr)
    for (int dc = -r; dc <= r; ++dc) {
      const int cc = c.col + dc, rr = c.row + dr;
      if (dc * dc + dr * dr > r * r || !grid_.contains(cc, rr)) continue;
      if (map_->at(cc, rr) == Cell::kFree) grid_.at(cc, rr) = 1;
    }
}

Wavefront::Wavefront(const TraversableMap& t, CellIndex start, std::size_t max_expanded,
                     CellIndex goal) {
  const auto& tg = t.grid();
  steps_ = Grid<std::uint32_t>(tg.width, tg.height, kUnreached);
  if (!tg.contains(start.col, start.row)) return;
  std::vector<CellIndex> queue;
  queue.reserve(1024);
  std::size_t head = 0;
  steps_.at(start) = 0;
  queue.push_back(start);
  while (head < queue.size()) {
    if (expanded_ >= max_expanded) {
      budget_exceeded_ = true;
      return;
    }
    const CellIndex c = queue[head++];
    ++expanded_;
    if (c == goal) return;  // the wave met the goal
    const std::uint32_t next = steps_.at(c) + 1;
    for (int k = 0; k < 8; ++k) {
      const CellIndex n{c.col + kAdj[k].col, c.row + kAdj[k].row};
      if (!tg.contains(n.col, n.row) || steps_.at(n) != kUnreached) continue;
      const bool enter = tg.at(n) == 1 || n == goal;
      if (!enter) continue;
      if (k >= 4 && n != goal &&
          !(tg.at(c.col + kAdj[k].col, c.row) == 1 && tg.at(c.col, c.row + kAdj[k].row) == 1))
        continue;  // a diagonal step must not cut a corner
      steps_.at(n) = next;
      queue.push_back(n);
    }
  }
}

std::uint32_t Wavefront::steps(CellIndex c) const {
  return steps_.contains(c.col, c.row) ? steps_.at(c) : kUnreached;
}

std::uint32_t Wavefront::steps_to_enter(CellIndex c) const {
  if (steps(c) != kUnreached) return steps(c);
  std::uint32_t best = kUnreached;
  for (const CellIndex& d : kAdj) {
    const std::uint32_t s = steps({c.col + d.col, c.row + d.row});
    if (s != kUnreached && s + 1 < best) best = s + 1;
  }
  return best;
}

std::vector<CellIndex> Wavefront::path_to(CellIndex c) const {
  std::vector<CellIndex> rev;
  if (steps_to_enter(c) == kUnreached) return rev;
  rev.push_back(c);
  CellIndex cur = c;
  std::uint32_t s = steps_to_enter(c);
  CellIndex last_dir{0, 0};
  while (s > 0) {
    // Among the neighbours one step closer, keep the direction of the previous step if possible.
    CellIndex best{-1, -1}, best_dir{0, 0};
    for (const CellIndex& d : kAdj) {
      const CellIndex n{cur.col + d.col, cur.row + d.row};
      if (steps(n) != s - 1) continue;
      if (best.col < 0 || d == last_dir) {
        best = n;
        best_dir = d;
        if (d == last_dir) break;
      }
    }
    if (best.col < 0) return {};  // cannot happen on a consistent wave
    rev.push_back(best);
    cur = best;
    last_dir = best_dir;
    --s;
  }
  return {rev.rbegin(), rev.rend()};
}

double path_length_m(const std::vector<CellIndex>& cells, const GridGeometry& g) {
  double len = 0.0;
  for (std::size_t i = 1; i < cells.size(); ++i)
    len += std::hypot(cells[i].col - cells[i - 1].col, cells[i].row - cells[i - 1].row);
  return len * g.cell_m();
}

PathResult plan_path(const Grid<Cell>& map, const GridGeometry& g, CellIndex start, CellIndex goal,
                     const NavigatorParams& params) {
  if (!map.contains(start.col, start.row) || !map.contains(goal.col, goal.row)) {
    PathResult out;
    out.status = PathStatus::kStartOutside;
    return out;
  }
  return plan_path(TraversableMap(map, g, params), g, start, goal, params);
}

PathResult plan_path(const TraversableMap& base, const GridGeometry& g, CellIndex start,
                     CellIndex goal, const NavigatorParams& params) {
  PathResult out;
  if (!base.grid().contains(start.col, start.row) || !base.grid().contains(goal.col, goal.row)) {
    out.status = PathStatus::kStartOutside;
    return out;
  }
  TraversableMap t = base;
  t.keep_clear(start);
  t.keep_clear(goal);
  const Wavefront wave(t, start, params.max_expanded_cells, goal);
  out.expanded = wave.expanded();
  if (wave.steps(goal) == Wavefront::kUnreached) {
    out.status = wave.budget_exceeded() ? PathStatus::kBudgetExceeded : PathStatus::kNoPath;
    return out;
  }
  out.cells = wave.path_to(goal);
  out.status = PathStatus::kFound;
  out.length_m = path_length_m(out.cells, g);
  out.waypoints_m.reserve(out.cells.size());
  for (const CellIndex& c : out.cells) out.waypoints_m.push_back(g.center_of(c));
  return out;
}

}  // namespace indoormap::exploration
