#pragma once
// Generated grid maps with known rooms, corridors and crossings (straight corridors, corners,
// T- and X-junctions, a floor with all of them and rooms behind doors), of any corridor width,
// rotated, with wall noise and clutter: the ground truth of grid-areas' corridor and crossing
// tests (docs/grid-areas.md). Drawn in a design frame, then rasterised rotated.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::sim {

enum class AreaMapShape : std::uint8_t { kStraight, kCorner, kTJunction, kXJunction, kFloor };

/// What a free cell of a generated map is (0: not free).
enum class AreaTruth : std::uint8_t { kNone = 0, kRoom = 1, kCorridor = 2, kCrossing = 3 };

struct AreaMapParams {
  double cell_m = 0.05;
  double corridor_width_m = 1.6;
  double arm_length_m = 6.0;  ///< length of each way beyond a crossing
  double rotation_deg = 0.0;  ///< the design rotated counter-clockwise about its centre
  double wall_noise = 0.0;    ///< probability that a free cell next to a wall is an obstacle
  int clutter_per_room = 0;   ///< small boxes (0.2-0.4 m) in each room
  std::uint32_t seed = 1;
};
/// Throws UsageError naming the field.
void validate(const AreaMapParams& p);

struct AreaMap {
  Grid<Cell> cells;  ///< kFree or kWall
  GridGeometry geometry;
  Grid<std::uint8_t> truth;                  ///< AreaTruth per cell
  std::vector<Eigen::Vector2d> crossings_m;  ///< centre of each junction / corner (map frame)
};

AreaMap make_area_map(AreaMapShape shape, const AreaMapParams& params);

}  // namespace indoormap::sim
