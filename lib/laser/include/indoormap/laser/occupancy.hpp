#pragma once
// Occupancy mapping from 2D laser scans with known poses, behind one interface (OccupancyMapper)
// with two implementations: the paper's HIMM counters (himm.hpp) and a log-odds Bayesian update
// with a beam model (log_odds.hpp).
//
// Every beam updates the cells of its Bresenham line from the laser cell to the end cell: "miss"
// on every cell before the end, "hit" on the end cell when the beam measured an obstacle closer
// than max_range_m (except the hit_guard_cells before it). A beam without a return (or
// beyond max_range_m) clears up to no_return_clear_m when clear_no_return is set. Cells outside the
// grid are skipped, but a beam ending outside still clears the cells inside it (the paper's rule).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/laser/scan.hpp"

namespace indoormap::laser {

struct OccupancyGridParams {
  double cell_m = 0.05;
  /// Hits further than this are not used as obstacles (the paper: 44 m); such beams and beams
  /// without a return clear up to here when clear_no_return is set.
  double max_range_m = 44.0;
  /// Beams without a return (and returns beyond max_range_m) clear up to no_return_clear_m when
  /// set. Off by default: on real logs such readings (glass, black surfaces, spurious maxima) cut
  /// through walls; the exploration simulator turns it on for its ideal laser.
  bool clear_no_return = false;
  double no_return_clear_m = 44.0;
  /// The cells just before a hit that its beam does not clear: a wall seen at a slant or with
  /// range noise keeps its surface (0 = clear up to the hit cell, the paper's rule).
  int hit_guard_cells = 0;
  /// Fixed map extent (the paper's xmin..ymax); when unset the grid grows to fit the scans.
  std::optional<GridGeometry> fixed_geometry;
  /// Extra room added on each side when the grid grows, so that it grows rarely.
  double grow_margin_m = 5.0;
  /// Cell budget: growing beyond it throws indoormap::BudgetError before allocating.
  std::int64_t max_cells = 200'000'000;
  void validate() const;  ///< throws UsageError naming the field
};

/// A finished (or intermediate) map as values: cell classes and the raw per-cell values of the
/// method (HIMM counter 0..15, or log-odds), both on `geometry`.
struct OccupancyMap {
  GridGeometry geometry;
  Grid<Cell> cells;  ///< kWall occupied, kFree free, kUnknown never observed or undecided
  Grid<float> raw;
};

class OccupancyMapper {
 public:
  virtual ~OccupancyMapper() = default;
  /// Adds one scan (validated). Grows the grid first unless the geometry is fixed.
  virtual void integrate(const LaserScan& scan) = 0;
  virtual const GridGeometry& geometry() const = 0;
  /// The class of one cell (kUnknown outside the grid).
  virtual Cell cell_at(CellIndex c) const = 0;
  /// Writes the cell classes into out (resized to the geometry).
  virtual void classify(Grid<Cell>& out) const = 0;
  virtual Grid<float> raw() const = 0;
  OccupancyMap snapshot() const;
  /// Number of scans integrated so far.
  virtual std::size_t scan_count() const = 0;
};

/// A map extent that holds every beam of scans taken from these laser positions with this
/// maximum range (cells aligned to multiples of cell_m). Throws BudgetError above max_cells,
/// before allocating anything.
GridGeometry bound_for_positions(const std::vector<Eigen::Vector2d>& laser_positions_m,
                                 double max_range_m, double cell_m, std::int64_t max_cells);

}  // namespace indoormap::laser
