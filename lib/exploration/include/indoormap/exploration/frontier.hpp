#pragma once
// Wavefront Frontier Detection (Keidar & Kaminka), exactly as the paper's pseudo-code (Fig. 1):
// an outer BFS from the robot over the points that touch open space, and an inner BFS that
// extracts each frontier, with the four marks Map-Open-List, Map-Close-List, Frontier-Open-List
// and Frontier-Close-List.
//
// Open space: kFree. A frontier point: an unknown cell (kUnknown, not blacklisted) with at least
// one open-space neighbour. Adjacency: the 8 neighbours. The outer BFS enqueues a neighbour v of p
// when v is not marked Map-Open / Map-Close and v has an open-space neighbour, so (as in the
// paper) it can pass a wall one or two cells thick: that is how a frontier "behind the wall"
// arises, which the navigator then finds unreachable and the goal rule blacklists.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::exploration {

struct Frontier {
  std::vector<CellIndex> cells;  ///< in the order the inner BFS found them
  CellIndex closest_to_robot;    ///< the cell nearest the robot (Euclidean, in cells)
  Eigen::Vector2d centroid_m = Eigen::Vector2d::Zero();
  std::size_t size() const { return cells.size(); }
};

struct WfdParams {
  /// The paper's speed-up: stop at the first frontier the outer BFS meets (the nearest one).
  bool stop_at_first = false;
  /// Frontiers with fewer cells are dropped (1 keeps all, as the pseudo-code).
  std::size_t min_frontier_cells = 1;
  void validate() const;
};

struct WfdResult {
  std::vector<Frontier> frontiers;  ///< in the order found (nearest first in BFS order)
  std::size_t outer_dequeued = 0;   ///< work done by the outer BFS
  std::size_t inner_dequeued = 0;
};

/// Blacklisted cells (nonzero) are never frontier points (the paper's "value 10" for cells found
/// unreachable). An empty blacklist grid means none.
using Blacklist = Grid<std::uint8_t>;

/// Runs WFD on map (geometry g) from the robot's cell. A robot outside the grid finds nothing.
WfdResult detect_frontiers(const Grid<Cell>& map, const GridGeometry& g, CellIndex robot,
                           const WfdParams& params = {}, const Blacklist& blacklist = {});

/// True when c is a frontier point of map (see above).
bool is_frontier_point(const Grid<Cell>& map, CellIndex c, const Blacklist& blacklist = {});

}  // namespace indoormap::exploration
