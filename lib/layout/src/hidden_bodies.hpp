#pragma once
// The unseen bodies of furniture taller than the scanner (hidden_bodies.cpp; build_layout's
// flood, LayoutParams::hidden_body_max_depth_m).
#include <cstdint>

#include "indoormap/core/grid.hpp"

namespace indoormap::layout::detail {

/// The cells between furniture whose top no scanner saw (`tall`) and the nearest wall (`walls`),
/// where that wall lies within max_depth_m of it and the scan saw the floor (`seen`) of none of
/// the cells on the straight line between them; each such line three cells wide (over unseen
/// cells, neither tall nor wall), so that the lines of neighbouring face cells, which diverge
/// on a turned face, leave no gap between them: the body of a shelf taller than the scanner,
/// between its face and the wall it stands against. The flood must not call them free (a scanner
/// sees such a shelf as its front face only, and the flood ran in round its unseen end). A shadow
/// behind a tall object farther from any wall stays floodable: the scan cannot tell the object's
/// depth there. All grids share one size; max_depth_m <= 0: none.
Grid<std::uint8_t> hidden_bodies(const Grid<std::uint8_t>& seen, const Grid<std::uint8_t>& tall,
                                 const Grid<std::uint8_t>& walls, double cell_m,
                                 double max_depth_m);

}  // namespace indoormap::layout::detail
