#pragma once
// HIMM (histogramic in-motion mapping), as in the paper: a counter per cell, +3 at the hit, -1 on
// every cell the beam passes (Bresenham), bounded 0..15; a cell at 15 is never decreased; the
// "mask" raises a cell whose four neighbours are all occupied to 15. Unknown cells hold 7 (the
// paper's Fig. 2); above 7 is occupied, below 7 free.
#include "indoormap/laser/occupancy.hpp"

namespace indoormap::laser {

struct HimmParams {
  int initial_value = 7;
  int hit_increment = 3;
  int miss_decrement = 1;
  int max_value = 15;         ///< at most 15 (4 bits)
  int occupied_above = 7;     ///< value > occupied_above: kWall
  int free_below = 7;         ///< observed and value < free_below: kFree
  bool freeze_at_max = true;  ///< a cell at max_value is never decreased
  bool mask = true;           ///< a cell whose four neighbours are occupied becomes max_value
  void validate() const;
};

class HimmMapper final : public OccupancyMapper {
 public:
  HimmMapper(OccupancyGridParams grid, HimmParams himm);
  void integrate(const LaserScan& scan) override;
  const GridGeometry& geometry() const override { return geometry_; }
  Cell cell_at(CellIndex c) const override;
  void classify(Grid<Cell>& out) const override;
  Grid<float> raw() const override;
  std::size_t scan_count() const override { return scans_; }
  /// The counter of a cell (initial_value outside the grid) and whether a beam touched it.
  int value(CellIndex c) const;
  bool observed(CellIndex c) const;

 private:
  void grow_to(const GridGeometry& g);
  void apply_mask(CellIndex c);
  OccupancyGridParams grid_params_;
  HimmParams p_;
  GridGeometry geometry_;
  Grid<std::uint8_t> cells_;  ///< bits 0-3 the counter, bit 4 observed
  std::vector<CellIndex> hits_;
  std::size_t scans_ = 0;
};

}  // namespace indoormap::laser
