#pragma once
// Connected-component labelling as the paper describes it (section 3.2.B): a two-pass raster
// scan with a union-find table of equivalent marks. Optionally, two neighbouring cells join only
// when a predicate says they belong together (used to split touching objects by height).
#include <cstdint>
#include <functional>

#include "indoormap/core/grid.hpp"

namespace indoormap::objects {

enum class Connectivity { k4 = 4, k8 = 8 };

struct Labels {
  Grid<std::int32_t> labels;  ///< 0 = background, 1..count in raster order of first cell
  int count = 0;
};

/// Labels the non-zero cells of mask. The raster runs row by row from row 0, so label k's first
/// cell comes before label k+1's. With `joins`, two neighbouring set cells are merged only when
/// joins(a, b) is true (it must be symmetric).
Labels label_components(const Grid<std::uint8_t>& mask, Connectivity connectivity,
                        const std::function<bool(CellIndex, CellIndex)>& joins = {});

}  // namespace indoormap::objects
