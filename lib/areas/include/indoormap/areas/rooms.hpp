#pragma once
// Room segmentation on an in-memory grid (also used by the whole-floor split): a watershed of the
// free space's distance transform, basins kept apart at door-like necks (RoomParams), pieces under
// min_room_area_m2 merged into the neighbour they border most.
#include <cstdint>

#include "indoormap/areas/params.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::areas {

/// free: non-zero = free cell. Returns labels 1..n on free cells (0 elsewhere); n in *count.
Grid<int> segment_rooms(const Grid<std::uint8_t>& free, double cell_m, const RoomParams& params,
                        int* count = nullptr);

}  // namespace indoormap::areas
