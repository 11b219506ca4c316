#pragma once
// Nav2 costmap-filter masks of the areas (docs/grid-areas.md, "Nav2 masks"):
//  - speed_mask.pgm + speed_mask.yaml: a map_server map in "mode: scale" with free_thresh 0 and
//    occupied_thresh 1, so that map_server publishes value = round(100 * (255 - pixel) / 255);
//    speed_filter_info.yaml (Costmap Filter Info Server, type 1: percent of maximum speed) with
//    base 0 and multiplier 1, so that the Speed Filter's limit = base + multiplier * value =
//    value percent. Value 0 is Nav2's "no limit": areas at 100 % are written as 0.
//  - keepout_mask.pgm + keepout_mask.yaml (trinary): free cells too narrow for the footprint are
//    occupied (black), everything else free; keepout_filter_info.yaml (type 0).
#include <array>
#include <cstdint>
#include <filesystem>

#include "indoormap/areas/areas.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::formats {

/// Speed limit in percent of the maximum speed, per area kind (indexed by AreaKind).
using SpeedPercents = std::array<double, 3>;

/// The mask value (0..100) map_server publishes for a pixel of a scale-mode mask with
/// free_thresh 0, occupied_thresh 1, negate 0.
int scale_mode_value(std::uint8_t pixel);
/// The pixel that map_server decodes to value (0..100).
std::uint8_t scale_mode_pixel(int value);

/// The speed mask's grid (rows y up): per cell the pixel of its area's percent.
Grid<std::uint8_t> speed_mask(const areas::AreasResult& r, const SpeedPercents& percent);

/// Writes the speed and keepout masks, their map YAMLs and filter info YAMLs into dir.
void write_costmap_masks(const std::filesystem::path& dir, const areas::AreasResult& r,
                         const GridGeometry& geometry, const SpeedPercents& percent);

}  // namespace indoormap::formats
