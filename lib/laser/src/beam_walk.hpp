#pragma once
// Internal: what both occupancy mappers share: the beam end points of a scan, growing the grid
// to fit them, and walking every beam's Bresenham cells inside the grid.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "indoormap/laser/bresenham.hpp"
#include "indoormap/laser/occupancy.hpp"

namespace indoormap::laser::detail {

struct BeamEnds {
  Eigen::Vector2d origin_m = Eigen::Vector2d::Zero();  ///< the laser in the map frame
  std::vector<Eigen::Vector2d> end_m;
  std::vector<unsigned char> hit;  ///< 1: the end is an obstacle; 0: clear only
};

/// End points of the beams to integrate (hits within max range; no-return beams cut at the
/// maximum range when clear_no_return).
void compute_beam_ends(const LaserScan& scan, const OccupancyGridParams& p, BeamEnds& out);

/// The geometry that holds g and every point of ends (plus the margin), or nullopt when g
/// already holds them. `empty`: g holds nothing yet. Throws BudgetError above max_cells.
std::optional<GridGeometry> grown_geometry(const GridGeometry& g, bool empty, const BeamEnds& ends,
                                           const OccupancyGridParams& p);

/// Copies grid (on `from`) onto `to` (which contains `from`, cells aligned), filling the rest.
template <class T>
void regrid(Grid<T>& grid, const GridGeometry& from, const GridGeometry& to, T fill) {
  Grid<T> out(to.width(), to.height(), fill);
  const CellIndex off = to.cell_of(from.center_of({0, 0}));
  for (int r = 0; r < grid.height; ++r)
    std::copy_n(&grid.at(0, r), grid.width, &out.at(off.col, off.row + r));
  grid = std::move(out);
}

/// Calls miss(index) for every in-grid cell of each beam before its end and hit(index) for an
/// in-grid end cell of a hit; index is row * width + col. A beam from outside the grid is clipped
/// to it first.
template <class Miss, class Hit>
void walk_beams(const BeamEnds& ends, const GridGeometry& g, int hit_guard_cells, Miss&& miss,
                Hit&& hit) {
  const int w = g.width(), h = g.height();
  const CellIndex a0 = g.cell_of(ends.origin_m);
  const bool inside = g.contains(a0);
  for (std::size_t i = 0; i < ends.end_m.size(); ++i) {
    const CellIndex b = g.cell_of(ends.end_m[i]);
    CellIndex a = a0;
    if (!inside) {  // Liang-Barsky clip of the segment to the grid box, in cell coordinates
      const Eigen::Vector2d p0 = g.to_cell_coords(ends.origin_m);
      const Eigen::Vector2d d = g.to_cell_coords(ends.end_m[i]) - p0;
      double t0 = 0.0, t1 = 1.0;
      auto clip = [&](double q, double dq, double lo, double hi) {
        if (dq == 0.0) return q >= lo && q <= hi;
        double ta = (lo - q) / dq, tb = (hi - q) / dq;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        return t0 <= t1;
      };
      if (!clip(p0.x(), d.x(), 0.0, w) || !clip(p0.y(), d.y(), 0.0, h)) continue;
      const Eigen::Vector2d e = p0 + d * t0;
      a = {std::clamp(static_cast<int>(std::floor(e.x())), 0, w - 1),
           std::clamp(static_cast<int>(std::floor(e.y())), 0, h - 1)};
    }
    const bool is_hit = ends.hit[i] != 0;
    // Steps of the line (its cells minus one); a hit's last hit_guard_cells before it are left
    // alone (the wall surface seen at a slant, range noise).
    const long long steps = std::max(std::llabs(static_cast<long long>(b.col) - a.col),
                                     std::llabs(static_cast<long long>(b.row) - a.row));
    const long long last_miss = is_hit ? steps - 1 - hit_guard_cells : steps;
    long long k = 0;
    bresenham(a, b, [&](CellIndex c) {
      if (c.col < 0 || c.row < 0 || c.col >= w || c.row >= h) return false;  // left the grid
      const std::size_t idx = static_cast<std::size_t>(c.row) * w + c.col;
      if (is_hit && c == b)
        hit(idx);
      else if (k <= last_miss)
        miss(idx);
      ++k;
      return true;
    });
  }
}

}  // namespace indoormap::laser::detail
