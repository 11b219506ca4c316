#pragma once
// Ray casting into a finished map, and the self-consistency check of a map against the scans it
// was built from: cast every beam from its pose, compare with the measured range.
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/laser/scan.hpp"

namespace indoormap::laser {

/// Where a cast ray stops: the first blocked cell and the ray's distances (metres) at its entry
/// into and exit from that cell.
struct RayHit {
  bool hit = false;  ///< false: nothing blocked within the range (entry_m = exit_m = range)
  CellIndex cell;
  double entry_m = 0.0;
  double exit_m = 0.0;
};

/// Exact grid traversal (Amanatides & Woo) from origin_m along angle_rad to the first cell for
/// which blocked(CellIndex) holds, within max_range_m. Cells outside the grid are never blocked;
/// entry_m is 0 when the origin's own cell is blocked.
template <class Blocked>
RayHit cast_ray_cell(const GridGeometry& g, const Eigen::Vector2d& origin_m, double angle_rad,
                     double max_range_m, Blocked&& blocked) {
  RayHit miss;
  miss.entry_m = miss.exit_m = max_range_m;
  const Eigen::Vector2d p = g.to_cell_coords(origin_m);
  const double dx = std::cos(angle_rad), dy = std::sin(angle_rad);
  const double t_max = g.to_cells(max_range_m);
  if (!(std::abs(p.x()) < 1e9 && std::abs(p.y()) < 1e9)) return miss;
  CellIndex c{static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y()))};
  const int sx = dx > 0 ? 1 : -1, sy = dy > 0 ? 1 : -1;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double tdx = dx != 0 ? 1.0 / std::abs(dx) : kInf, tdy = dy != 0 ? 1.0 / std::abs(dy) : kInf;
  double tx = dx != 0 ? ((dx > 0 ? c.col + 1 - p.x() : p.x() - c.col) * tdx) : kInf;
  double ty = dy != 0 ? ((dy > 0 ? c.row + 1 - p.y() : p.y() - c.row) * tdy) : kInf;
  double t = 0.0;
  bool was_inside = false;
  while (t <= t_max) {
    const bool inside = g.contains(c);
    if (inside && blocked(c)) return {true, c, t * g.cell_m(), std::min(tx, ty) * g.cell_m()};
    if (!inside && was_inside) break;  // the grid is convex: no way back in
    was_inside = was_inside || inside;
    if (tx < ty) {
      t = tx;
      tx += tdx;
      c.col += sx;
    } else {
      t = ty;
      ty += tdy;
      c.row += sy;
    }
  }
  return miss;
}

/// The distance in metres to the entry into the first blocked cell, or max_range_m (see
/// cast_ray_cell).
template <class Blocked>
double cast_ray(const GridGeometry& g, const Eigen::Vector2d& origin_m, double angle_rad,
                double max_range_m, Blocked&& blocked) {
  return cast_ray_cell(g, origin_m, angle_rad, max_range_m, blocked).entry_m;
}

/// kWall and kFurniture block.
inline bool is_obstacle(Cell c) {
  return c == Cell::kWall || c == Cell::kFurniture;
}

/// cast_ray into a cell map: walls and furniture block.
double cast_ray(const Grid<Cell>& cells, const GridGeometry& g, const Eigen::Vector2d& origin_m,
                double angle_rad, double max_range_m);

/// The check compares each measured range with the ray cast into the map: its error is the
/// distance from the measured range to the stretch of the ray inside the first obstacle cell
/// ([entry, exit]), so 0 when the measured end lies in the cell where the cast stops: a grid
/// locates a wall to a cell, not better. A cast that finds no obstacle within the range (plus the
/// tolerance) counts as an error of (range + tolerance - measured).
struct ConsistencyParams {
  double within_cells = 2.0;       ///< a beam agrees when its error <= within_cells * cell_m
  double max_range_m = 44.0;       ///< beams measuring further are not checked (as in mapping)
  double histogram_bin_m = 0.001;  ///< resolution of the median (bounded memory)
  double histogram_max_m = 20.0;
  void validate() const;
};

struct ConsistencyResult {
  std::size_t beams_checked = 0;  ///< beams with a return within max_range_m
  std::size_t beams_within = 0;
  double within_share = 0.0;        ///< beams_within / beams_checked (0 when none)
  double median_abs_error_m = 0.0;  ///< to histogram_bin_m
  double mean_abs_error_m = 0.0;
  double within_m = 0.0;  ///< the tolerance used, metres
};

/// Accumulates the check over a stream of scans (memory bounded by the histogram), against a
/// finished map held by value.
class ConsistencyCheck {
 public:
  ConsistencyCheck(Grid<Cell> cells, GridGeometry geometry, ConsistencyParams params = {});
  void add(const LaserScan& scan);
  ConsistencyResult result() const;

 private:
  Grid<Cell> cells_;
  GridGeometry geometry_;
  ConsistencyParams p_;
  std::vector<std::uint32_t> histogram_;  ///< the last bin collects everything beyond the range
  std::size_t checked_ = 0, within_ = 0;
  double sum_abs_m_ = 0.0;
};

}  // namespace indoormap::laser
