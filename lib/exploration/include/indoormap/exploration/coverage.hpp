#pragma once
// The reference for "explored share": the free space a robot of this radius can reach from its
// start. The robot's centre can reach the free cells farther than its radius from every obstacle
// that connect to the start (8-connected); it can see at least the free cells its body covers
// there, so the reachable free space is those centre cells dilated by the radius, on free cells.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::exploration {

struct ReachableSpace {
  Grid<std::uint8_t> mask;           ///< 1: reachable free cell
  std::vector<std::uint32_t> cells;  ///< their indices (row * width + col)
  bool start_free = false;  ///< false: the start is inside an obstacle's inflation (mask empty)
};

ReachableSpace reachable_free_space(const Grid<Cell>& truth, const GridGeometry& g, CellIndex start,
                                    double robot_radius_m);

/// Fixed, reproducible start points: cells of the largest 8-connected region where the centre of a
/// robot with clearance_m fits (free, farther than clearance_m from every obstacle), taken at the
/// given fractions of that region's cells in row-major order. Empty when there is no such cell.
std::vector<Eigen::Vector2d> start_points(const Grid<Cell>& truth, const GridGeometry& g,
                                          double clearance_m,
                                          const std::vector<double>& fractions = {0.2, 0.5, 0.8});

/// Share of the reachable cells that the built map knows (anything but kUnknown).
double explored_share(const ReachableSpace& reachable, const Grid<Cell>& built);

}  // namespace indoormap::exploration
