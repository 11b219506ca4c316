#pragma once
// Ground truth of a scene: the furniture list and the true 2D layout, i.e. what a perfect map
// would show (even where the scanner cannot see). See docs/evaluation.md.
#include <string>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/core/polygon.hpp"
#include "indoormap/sim/scene.hpp"
#include "indoormap/sim/world.hpp"

namespace indoormap::sim {

struct TruthItem {
  std::string id;
  FurnitureType type = FurnitureType::kBox;
  Polygon footprint;  ///< scene frame, counter-clockwise
  double z_min_m = 0.0, z_max_m = 0.0;
  bool on_floor = true;  ///< false for lamps hanging from the ceiling
  int room = -1;
};

/// One entry per furniture item of a normalised scene, in scene order.
std::vector<TruthItem> furniture_truth(const Scene& scene);

struct TruthLayout {
  GridGeometry geometry;  ///< scene frame; row 0 is the lowest y
  Grid<Cell> cells;
};

/// Rasterises the true layout at cell_m, classifying every cell by its centre:
///   wall      inside a wall solid that reaches the floor (a window's sill part is wall; the
///             lintel over a door is not);
///   furniture inside the footprint of an item standing on the floor (not lamps);
///   free      inside a room / corridor polygon or a door opening, and not furniture;
///   unknown   elsewhere.
/// The grid covers every wall plus margin_m; its origin is a multiple of cell_m. Throws
/// BudgetError above max_cells.
TruthLayout truth_layout(const Scene& scene, const SceneGeometry& geometry, double cell_m = 0.05,
                         double margin_m = 0.5, std::int64_t max_cells = 200'000'000);

}  // namespace indoormap::sim
