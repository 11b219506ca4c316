#pragma once
// Which truth-free cells some scanner could see, computed from the simulated rays themselves
// (docs/scene-sim.md, "Seen mask"). Rule: a truth-free cell is seen when at least one ray, on its
// way from its scanner to its return point, passes over the cell at a height (storey frame)
// between min_height_m and max_height_m, or ends on the cell's floor. The default band, up to
// 1.0 m, is the robot's body band (0.05-1.0 m) and what lies below it: space a ray crossed there
// is known to be empty where a robot drives. Rays without a return (no surface within range) are
// not walked. The cells are those the segment's 2D projection crosses (a DDA).
#include <cstdint>
#include <vector>

#include "indoormap/core/grid.hpp"
#include "indoormap/sim/ground_truth.hpp"
#include "indoormap/sim/simulate.hpp"

namespace indoormap::sim {

struct SeenParams {
  double min_height_m = -0.05;  ///< storey frame; a little below the floor for the range noise
  double max_height_m = 1.0;
};

/// Throws UsageError unless min_height_m < max_height_m, both in [-1, 10] m.
void validate(const SeenParams& params);

/// The seen mask on the truth layout's grid: 1 for truth-free cells seen, 0 elsewhere.
/// sim: tilted frame (tilt: the scene's tilt); only the scans whose scanner s has
/// scanner_storey[s] == storey are walked (scanner_storey empty: every scan); floor_z_m: the
/// storey's floor in the scene frame.
Grid<std::uint8_t> seen_cells(const TruthLayout& layout, const SimResult& sim, const Tilt& tilt,
                              const std::vector<int>& scanner_storey = {}, int storey = 0,
                              double floor_z_m = 0.0, const SeenParams& params = {});

/// The mask as a PGM image of a ROS map: seen 254 (free), everything else 0.
Grid<std::uint8_t> seen_image(const Grid<std::uint8_t>& seen);

/// Number of seen cells.
std::int64_t seen_count(const Grid<std::uint8_t>& seen);

}  // namespace indoormap::sim
