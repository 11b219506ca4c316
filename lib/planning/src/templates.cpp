// The neighbourhood template (paper: "point neighbourhood or trajectory node") and supercover
// lines.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "indoormap/core/errors.hpp"
#include "indoormap/planning/planner.hpp"

namespace indoormap::planning {

std::vector<CellIndex> supercover(int dx, int dy) {
  // Walk from (0,0) to (dx,dy) crossing the grid lines at half-integers. The k-th vertical line
  // is crossed at t = (2k+1) / (2|dx|), the k-th horizontal one at (2k+1) / (2|dy|); comparing
  // (2ix+1)|dy| with (2iy+1)|dx| orders them exactly in integers.
  const int sx = dx > 0 ? 1 : -1, sy = dy > 0 ? 1 : -1;
  const std::int64_t ax = std::abs(dx), ay = std::abs(dy);
  std::vector<CellIndex> out;
  out.reserve(static_cast<std::size_t>(ax + ay + 1));
  int x = 0, y = 0;
  std::int64_t ix = 0, iy = 0;
  out.push_back({0, 0});
  while (ix < ax || iy < ay) {
    const std::int64_t tx = ix < ax ? (2 * ix + 1) * ay : -1;  // -1: no more vertical lines
    const std::int64_t ty = iy < ay ? (2 * iy + 1) * ax : -1;
    if (ty < 0 || (tx >= 0 && tx < ty)) {
      x += sx, ++ix;
    } else if (tx < 0 || ty < tx) {
      y += sy, ++iy;
    } else {  // exactly through a corner: both side cells are touched
      out.push_back({x + sx, y});
      out.push_back({x, y + sy});
      x += sx, y += sy, ++ix, ++iy;
    }
    out.push_back({x, y});
  }
  return out;
}

NeighbourhoodTemplate make_neighbourhood_template(double d_max_m, double cell_m) {
  if (!(cell_m > 0) || !std::isfinite(cell_m))
    throw UsageError("neighbourhood template: cell_m must be > 0");
  if (!(d_max_m > 0) || !std::isfinite(d_max_m))
    throw UsageError("neighbourhood template: d_max_m must be > 0");
  const double rc = d_max_m / cell_m;
  if (rc > 300) {
    char msg[320];
    std::snprintf(msg, sizeof msg,
                  "planner.d_max_m %g m is %g cells of the map resolution %g m, above the limit "
                  "of 300 cells (the neighbourhood template would need too much memory): check "
                  "planner.d_max_m and the map resolution",
                  d_max_m, rc, cell_m);
    throw BudgetError(msg);
  }
  NeighbourhoodTemplate t;
  t.cell_m = cell_m;
  t.d_max_m = d_max_m;
  const int r = static_cast<int>(std::floor(rc + 1e-9));
  t.radius_cells = r;
  const double r2 = rc * rc + 1e-9;
  const int side = 2 * r + 1;
  std::vector<std::int32_t> id_of(static_cast<std::size_t>(side) * side, -1);
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      if ((dx == 0 && dy == 0) || double(dx) * dx + double(dy) * dy > r2) continue;
      t.end_points.push_back({{dx, dy}, std::hypot(dx, dy) * cell_m, std::atan2(dy, dx)});
    }
  std::stable_sort(t.end_points.begin(), t.end_points.end(),
                   [](const auto& a, const auto& b) { return a.length_m < b.length_m; });
  for (std::size_t i = 0; i < t.end_points.size(); ++i) {
    const auto& o = t.end_points[i].offset;
    id_of[static_cast<std::size_t>(o.row + r) * side + (o.col + r)] = static_cast<std::int32_t>(i);
  }

  // Prefix tree of the supercover lines (without the origin cell).
  struct TNode {
    std::int16_t dx, dy;
    std::int32_t first_child = -1, next_sibling = -1, end_point = -1;
  };
  std::vector<TNode> nodes;
  std::int32_t root_first = -1;
  for (std::size_t e = 0; e < t.end_points.size(); ++e) {
    const auto& o = t.end_points[e].offset;
    const auto line = supercover(o.col, o.row);
    std::int32_t cur = -1;  // parent node; -1 = root
    for (std::size_t k = 1; k < line.size(); ++k) {
      const std::int32_t first = cur < 0 ? root_first : nodes[cur].first_child;
      std::int32_t c = first;
      while (c >= 0 && !(nodes[c].dx == line[k].col && nodes[c].dy == line[k].row))
        c = nodes[c].next_sibling;
      if (c < 0) {
        c = static_cast<std::int32_t>(nodes.size());
        TNode n{static_cast<std::int16_t>(line[k].col), static_cast<std::int16_t>(line[k].row)};
        n.next_sibling = first;
        nodes.push_back(n);
        if (cur < 0)
          root_first = c;
        else
          nodes[cur].first_child = c;
      }
      cur = c;
    }
    nodes[cur].end_point = static_cast<std::int32_t>(e);
  }
  // Flatten depth-first with subtree ends.
  t.dx.reserve(nodes.size());
  t.dy.reserve(nodes.size());
  t.skip.reserve(nodes.size());
  t.end_point.reserve(nodes.size());
  // Iterative pre-order: a close marker (-1 - flat) sets skip when the subtree is done.
  std::vector<std::int64_t> work;
  for (std::int32_t c = root_first; c >= 0; c = nodes[c].next_sibling) work.push_back(c);
  std::reverse(work.begin(), work.end());
  while (!work.empty()) {
    const std::int64_t item = work.back();
    work.pop_back();
    if (item < 0) {
      const auto flat = static_cast<std::size_t>(-1 - item);
      t.skip[flat] = static_cast<std::int32_t>(t.dx.size());
      continue;
    }
    const auto& n = nodes[static_cast<std::size_t>(item)];
    const auto flat = static_cast<std::int64_t>(t.dx.size());
    t.dx.push_back(n.dx);
    t.dy.push_back(n.dy);
    t.skip.push_back(0);
    t.end_point.push_back(n.end_point);
    work.push_back(-1 - flat);
    std::vector<std::int32_t> kids;
    for (std::int32_t c = n.first_child; c >= 0; c = nodes[c].next_sibling) kids.push_back(c);
    for (auto it = kids.rbegin(); it != kids.rend(); ++it) work.push_back(*it);
  }

  // The paper's rays: turning angles 1/r rad apart (neighbouring rays at most one cell apart at
  // D_max), along each the cells at whole-cell distances, nearest first, without repeats.
  const int n_angles =
      std::max(8, static_cast<int>(std::ceil(2.0 * std::numbers::pi * std::max(r, 1))));
  for (int a = 0; a < n_angles; ++a) {
    const double phi = 2.0 * std::numbers::pi * a / n_angles;
    std::vector<std::int32_t> ray;
    for (int k = 1; k <= r; ++k) {
      const int dx = static_cast<int>(std::lround(k * std::cos(phi)));
      const int dy = static_cast<int>(std::lround(k * std::sin(phi)));
      if (std::abs(dx) > r || std::abs(dy) > r) continue;
      const auto id = id_of[static_cast<std::size_t>(dy + r) * side + (dx + r)];
      if (id < 0 || (!ray.empty() && ray.back() == id)) continue;
      ray.push_back(id);
    }
    if (!ray.empty()) t.rays.push_back(std::move(ray));
  }
  return t;
}

}  // namespace indoormap::planning
