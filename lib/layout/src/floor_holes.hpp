#pragma once
// Holes in the observed floor (nav_map.cpp): without ray evidence, the floor's returns leave
// gaps that are no obstacle: between the rings of a multi-beam scanner's beams, and around a
// mobile scanner's path where it stopped (its own blind disc). docs/pipeline.md, "Floor holes".
#include <cstdint>
#include <vector>

#include "indoormap/cloud/voxel.hpp"

namespace indoormap::layout::detail {

enum class NavState : std::uint8_t { kUnknown, kFree, kOccupied };

struct HoleParams {
  double max_cells = 0.0;        ///< larger unknown components stay unknown
  double min_free_share = 0.75;  ///< of the component's border cells that are free
  /// Unknown cells of the barrier, closed across gaps of this many cells, are no part of any
  /// hole; they count as the holes' border that is not free. 0: the barrier as it is.
  int barrier_gap_cells = 2;
};

/// A doorway is open at least this high (border.door_clear_height_m's default): a wall band cell
/// with no point between the body band's top and this is a lintel, no barrier of the holes.
constexpr double kDoorOpenM = 1.8;

/// The layers (inclusive) where a wall band cell's column must hold a point to bound the holes:
/// a wall seen above what hid its foot does, a doorway's lintel (open below) does not.
struct WallProof {
  std::int64_t lo_layer = 0, hi_layer = -1;
};

/// The holes' barrier: the occupied cells, and the wall band's cells (walls[i] set; empty: none)
/// whose column holds a point in `proof`'s layers.
std::vector<std::uint8_t> hole_barrier(const std::vector<NavState>& state,
                                       const cloud::VoxelGrid& g,
                                       const std::vector<std::uint8_t>& walls,
                                       const WallProof& proof);

/// Turns into free every 4-connected component of kUnknown cells of the w x h grid, barrier cells
/// (closed across barrier_gap_cells) left out, that does not touch the grid's edge, holds at
/// most max_cells cells, has at least min_free_share of its border (the 4-neighbours outside it)
/// free, and holds no cell with drop[i] set (points below the floor: a stairwell, a hole in the
/// floor). Returns the cells made free.
std::int64_t fill_floor_holes(std::vector<NavState>& state,
                              const std::vector<std::uint8_t>& barrier,
                              const std::vector<std::uint8_t>& drop, int w, int h,
                              const HoleParams& params);

}  // namespace indoormap::layout::detail
