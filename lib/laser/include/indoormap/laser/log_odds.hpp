#pragma once
// Log-odds Bayesian occupancy with a beam model: along each beam the cells before the end get the
// log-odds of p_miss, the end cell (a hit) the log-odds of p_hit. Unknown cells hold 0 (p = 0.5).
//
// With `clamp` (the default, for a robot mapping as it goes) the sum is bounded to the log-odds of
// [p_min, p_max], so that the map can still change its mind: a cell then follows its last few
// observations. Without it the sum is each cell's evidence over all its observations alike, the
// maximum-likelihood map of a whole log (what laser-to-map builds: docs/laser-to-map.md,
// "Why freiburg-079's beams disagreed").
#include "indoormap/laser/occupancy.hpp"

namespace indoormap::laser {

struct LogOddsParams {
  double p_hit = 0.7;             ///< P(occupied | the beam ended here)
  double p_miss = 0.4;            ///< P(occupied | the beam passed)
  double p_min = 0.12;            ///< clamp (when `clamp`)
  double p_max = 0.97;            ///< clamp (when `clamp`)
  double occupied_above_p = 0.6;  ///< p > this: kWall
  double free_below_p = 0.45;     ///< observed and p < this: kFree
  bool clamp = true;              ///< bound the sum to [p_min, p_max] (recent observations win)
  void validate() const;
};

class LogOddsMapper final : public OccupancyMapper {
 public:
  LogOddsMapper(OccupancyGridParams grid, LogOddsParams params);
  void integrate(const LaserScan& scan) override;
  const GridGeometry& geometry() const override { return geometry_; }
  Cell cell_at(CellIndex c) const override;
  void classify(Grid<Cell>& out) const override;
  Grid<float> raw() const override { return log_odds_; }
  std::size_t scan_count() const override { return scans_; }
  float log_odds(CellIndex c) const;

 private:
  Cell classify_value(float l) const;
  void grow_to(const GridGeometry& g);
  OccupancyGridParams grid_params_;
  LogOddsParams p_;
  float l_hit_, l_miss_, l_min_, l_max_, l_occ_, l_free_;
  GridGeometry geometry_;
  Grid<float> log_odds_;  ///< NaN: never observed
  std::size_t scans_ = 0;
};

}  // namespace indoormap::laser
