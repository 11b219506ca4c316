#pragma once
// Sparsely sampled level surfaces of the navigation map (nav_map.cpp; docs/pipeline.md, "Sparse
// tops"). A mobile lidar 0.25 m above a table top crosses it in a few arcs decimetres apart: most
// of the top's cells hold no point, and the floor under them was seen between the legs, so they
// would be free.
#include <cstdint>
#include <vector>

namespace indoormap::layout::detail {

struct LevelTopParams {
  std::int32_t raised_lo = 0;    ///< lowest layer of a top (nav.ray_under_min_m above the floor)
  std::int32_t thin_layers = 0;  ///< a top's points lie within fewer layers than this
  int gap_cells = 0;             ///< a closing of this radius joins a top's samples; 0: off
  int min_cells = 0;             ///< samples a joined piece needs to be a surface
};

/// Columns whose body-band points (layers lo..hi, lo < 0: none) are thin and raised, over a floor
/// seen in their own cell (floor_seen), are samples of a top at level lo: a wall's face crossed by
/// one beam is thin too, but stands on no floor seen. Per level L, the samples at L and L + 1 are
/// joined by a closing of radius gap_cells; a joined piece (8-connected) holding at least min_cells
/// samples is a surface, and each of its cells becomes occupied and raised (the rays pass beneath
/// it). Returns the cells that were not occupied before.
std::int64_t fill_level_tops(const std::vector<std::int32_t>& lo,
                             const std::vector<std::int32_t>& hi,
                             const std::vector<std::uint8_t>& floor_seen, int w, int h,
                             const LevelTopParams& params, std::vector<std::uint8_t>& occupied,
                             std::vector<std::uint8_t>& raised);

}  // namespace indoormap::layout::detail
