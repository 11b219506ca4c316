#pragma once
// Rooms, corridors and crossings of a 2D grid map, as a label grid, polygons in map metres, doors
// and the connectivity graph (docs/grid-areas.md). Needs no start point: every part of the free
// space the footprint can reach is split.
#include <Eigen/Core>
#include <cstdint>
#include <string_view>
#include <vector>

#include "indoormap/areas/params.hpp"
#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/core/polygon.hpp"

namespace indoormap::areas {

enum class AreaKind : std::uint8_t { kRoom, kCorridor, kCrossing };
std::string_view to_string(AreaKind k);

struct Area {
  int id = 0;  ///< 1-based; the value of its cells in AreasResult::labels
  AreaKind kind = AreaKind::kRoom;
  int cells = 0;
  double area_m2 = 0.0;
  /// Counter-clockwise outer ring along the cells' edges, map frame, no closing vertex: simple,
  /// and sharing its border exactly with the neighbouring areas' rings (core/cell_rings.hpp).
  Polygon outline_m;
  std::vector<Polygon> holes_m;  ///< clockwise interior rings (obstacles of at least min area)
  std::vector<int> neighbours;   ///< ids of the areas it shares a border with, ascending
};

/// The border between two areas: the end points of their shared boundary (map frame).
struct Door {
  int a = 0, b = 0;  ///< area ids, a < b
  Eigen::Vector2d end0_m = Eigen::Vector2d::Zero(), end1_m = Eigen::Vector2d::Zero();
  double width_m = 0.0;
  int shared_cells = 0;
};

/// A crossing candidate and what the fan-of-turns test said (kept for the docs and tests).
struct CrossingCheck {
  Eigen::Vector2d at_m = Eigen::Vector2d::Zero();
  int arms = 0;  ///< 3+: junction, 2: corner
  bool confirmed = false;
};

struct AreasResult {
  Grid<std::uint16_t> labels;  ///< 0: not in an area (obstacle, unknown, or free but too narrow)
  std::vector<Area> areas;     ///< areas[i].id == i + 1
  std::vector<Door> doors;
  std::vector<CrossingCheck> crossing_checks;
  Grid<std::uint8_t> too_narrow;  ///< 1: free cell the footprint cannot reach (keepout)
  int free_cells = 0;
  int reachable_cells = 0;
  int reachable_components = 0;
  int graph_components = 0;
};

/// Splits the free cells (Cell::kFree) of a map into areas. Throws UsageError on bad parameters.
/// No free cell, or none the footprint can reach, gives an empty result (no exception).
AreasResult split_areas(const Grid<Cell>& cells, const GridGeometry& geometry,
                        const AreasParams& params);

}  // namespace indoormap::areas
