#pragma once
// The fan-of-turns test of van Galen's prototype: from a pose, the robot turns on its minimum
// radius by each angle of the fan, then drives straight until it has travelled travel_m; a turn is
// possible when the footprint stays on free cells all along. A crossing is a place where a turn
// beyond side_turn_min_deg is possible.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "indoormap/areas/params.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::areas {

/// Cell-frame pose: (col, row) continuous cell coordinates, heading in radians from +col.
struct CellPose {
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  double heading_rad = 0.0;
};

/// True when the footprint (centred at the pose) covers only free cells.
bool footprint_free(const Grid<std::uint8_t>& free, double cell_m, const FootprintParams& fp,
                    const CellPose& pose);

/// The fan's angles (degrees, + is to the left) whose turn is possible from pose.
std::vector<double> possible_turns(const Grid<std::uint8_t>& free, double cell_m,
                                   const FootprintParams& fp, const CorridorParams& cp,
                                   const CellPose& pose);

/// True when some possible turn from pose goes beyond side_turn_min_deg.
bool can_turn_aside(const Grid<std::uint8_t>& free, double cell_m, const FootprintParams& fp,
                    const CorridorParams& cp, const CellPose& pose);

}  // namespace indoormap::areas
