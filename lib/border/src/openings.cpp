// Step 7 of the closure: the openings of the room border, and the obstacle cells open below
// door height (doors under a lintel).
#include <cmath>
#include <limits>

#include "indoormap/layout/pipeline.hpp"
#include "internal.hpp"

namespace indoormap::border {

namespace detail {

// The openings of a closed chain: maximal cyclic runs of chain cells with no obstacle within r
// cells, measured between the nearest obstacle cells on either side.
std::vector<Opening> find_openings(const std::vector<CellIndex>& chain, const Grid<Cell>& layout,
                                   const GridGeometry& geo, const BorderParams& params,
                                   const Grid<std::uint8_t>* open_below) {
  std::vector<Opening> out;
  const int r = static_cast<int>(std::lround(geo.to_cells(params.opening_search_m)));
  auto obstacle = [&](int c, int row) {
    if (!layout.contains(c, row)) return false;
    const Cell v = layout.at(c, row);
    if (v != Cell::kWall && v != Cell::kFurniture) return false;
    return !(open_below && open_below->at(c, row));
  };
  auto near_obstacle = [&](CellIndex p, int rad) {
    for (int dr = -rad; dr <= rad; ++dr)
      for (int dc = -rad; dc <= rad; ++dc)
        if (obstacle(p.col + dc, p.row + dr)) return true;
    return false;
  };
  const std::size_t n = chain.size();
  std::vector<std::uint8_t> open(n, 0);
  std::size_t first_closed = n;
  for (std::size_t i = 0; i < n; ++i) {
    open[i] = !near_obstacle(chain[i], r);
    if (!open[i] && first_closed == n) first_closed = i;
  }
  if (first_closed == n) return out;  // no obstacle anywhere along the chain
  auto obstacles_near = [&](CellIndex p, int rad) {
    std::vector<CellIndex> v;
    for (int dr = -rad; dr <= rad; ++dr)
      for (int dc = -rad; dc <= rad; ++dc)
        if (obstacle(p.col + dc, p.row + dr)) v.push_back({p.col + dc, p.row + dr});
    return v;
  };
  // Walk once round the chain starting at a closed cell, so no run wraps the seam.
  for (std::size_t k = 0; k < n;) {
    const std::size_t i = (first_closed + k) % n;
    if (!open[i]) {
      ++k;
      continue;
    }
    std::size_t len = 0;
    while (k + len < n && open[(first_closed + k + len) % n]) ++len;
    const std::size_t first = i, last = (first_closed + k + len - 1) % n;
    const CellIndex before = chain[(first + n - 1) % n], after = chain[(last + 1) % n];
    const auto sa = obstacles_near(before, r + 1), sb = obstacles_near(after, r + 1);
    double best = std::numeric_limits<double>::infinity();
    CellIndex ba{}, bb{};
    for (const auto& a : sa)
      for (const auto& b : sb) {
        const double d = std::hypot(a.col - b.col, a.row - b.row);
        if (d < best) {
          best = d;
          ba = a;
          bb = b;
        }
      }
    k += len;
    if (!std::isfinite(best) || best <= 1.0) continue;
    // From obstacle centre to obstacle centre, less half a cell at each end: the clear width.
    const Eigen::Vector2d ca = geo.center_of(ba), cb = geo.center_of(bb);
    const Eigen::Vector2d u = (cb - ca).normalized();
    Opening o;
    o.a_m = ca + u * (0.5 * geo.cell_m());
    o.b_m = cb - u * (0.5 * geo.cell_m());
    o.width_m = (o.b_m - o.a_m).norm();
    o.chain_first = first;
    o.chain_last = last;
    if (o.width_m < params.opening_min_m) continue;
    o.is_door_candidate =
        o.width_m >= params.door_min_m - 1e-9 && o.width_m <= params.door_max_m + 1e-9;
    out.push_back(o);
  }
  return out;
}

}  // namespace detail

Grid<std::uint8_t> open_below_mask(const layout::MapResult& m,
                                   const std::vector<Eigen::Vector2d>& scanners_map,
                                   const BorderParams& params) {
  params.validate();
  const auto& lay = m.layout.layout;
  Grid<std::uint8_t> mask(lay.width, lay.height, 0);
  const auto& vx = m.voxels;
  if (vx.nx != lay.width || vx.ny != lay.height || vx.nz <= 0 || vx.counts.empty() ||
      scanners_map.empty())
    return mask;
  auto layer_of = [&](double z) { return vx.layer_of(z); };
  // Empty below: no point from the furniture band's bottom to the door height.
  const std::int64_t lo = std::max<std::int64_t>(0, m.layers.furniture_band.lo_layer);
  const std::int64_t hi =
      std::min<std::int64_t>(vx.nz - 1, layer_of(m.layers.floor_z_m + params.door_clear_height_m));
  // Seen beyond: any point from just below the floor to the door height (the floor or the far
  // wall of a corridor seen through the door).
  const std::int64_t see_lo = std::max<std::int64_t>(0, layer_of(m.layers.floor_z_m) - 1);
  if (hi < lo) return mask;
  auto column_has_points = [&](int c, int r, std::int64_t z0, std::int64_t z1) {
    for (std::int64_t z = z0; z <= z1; ++z)
      if (vx.count(c, r, z) > 0) return true;
    return false;
  };
  const GridGeometry& geo = m.geometry;
  const int probe = std::max(2, static_cast<int>(std::lround(geo.to_cells(params.door_probe_m))));
  for (int r = 0; r < lay.height; ++r)
    for (int c = 0; c < lay.width; ++c) {
      const Cell v = lay.at(c, r);
      if (v != Cell::kWall && v != Cell::kFurniture) continue;
      if (column_has_points(c, r, lo, hi)) continue;
      // Empty below can also mean hidden (the foot of a wall behind a cabinet). A door is seen
      // through: along a scanner's ray, beyond the cell, there are points below door height.
      const Eigen::Vector2d p = geo.center_of({c, r});
      bool seen_through = false;
      for (const auto& s : scanners_map) {
        const Eigen::Vector2d d = p - s;
        const double len = geo.to_cells(d.norm());
        if (len < 1.0) continue;
        const Eigen::Vector2d step = d / len;  // one cell length per step, map metres
        for (int k = 2; k <= probe && !seen_through; ++k) {
          const CellIndex q = geo.cell_of(p + step * k);
          if (!lay.contains(q.col, q.row)) break;
          if (column_has_points(q.col, q.row, see_lo, hi)) seen_through = true;
        }
        if (seen_through) break;
      }
      mask.at(c, r) = seen_through ? 1 : 0;
    }
  return mask;
}

}  // namespace indoormap::border
