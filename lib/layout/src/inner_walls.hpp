#pragma once
// The walls between rooms in M_r (inner_walls.cpp; build_layout's wall_max_thickness_m).
#include <cstdint>

#include "indoormap/layout/layout.hpp"

namespace indoormap::layout::detail {

/// Adds to `walls` (M_w) the insides of walls (wall_inside) and the walls with one face in the
/// furniture band (wall_slabs; only with `seen`): the cells inside the passage area, neither
/// flooded (free_mask) nor seen, of pieces longer than 2 * max_span_m along an axis (a pillar's
/// inside is left as it is: the objects step describes a pillar by its ring of faces).
void add_inner_walls(const Grid<std::uint8_t>& furniture, const Grid<std::uint8_t>* seen,
                     const Grid<std::uint8_t>& passage, const Grid<std::uint8_t>& free_mask,
                     double cell_m, double max_span_m, Grid<std::uint8_t>& walls);

}  // namespace indoormap::layout::detail
