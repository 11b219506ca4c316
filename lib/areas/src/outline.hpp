#pragma once
// Polygons, doors and the area graph from a label grid (internal to im_areas).
#include "indoormap/areas/areas.hpp"

namespace indoormap::areas::detail {

/// Fills each area's cells, area_m2, outline_m and holes_m (holes of at least min_hole_cells):
/// the cells' own edges (core/cell_rings.hpp), so every ring is simple, and neighbouring areas'
/// polygons share their borders exactly.
void build_outlines(AreasResult& r, const GridGeometry& geometry, int min_hole_cells);

/// Doors between 4-adjacent areas, the neighbours lists and r.graph_components.
void build_graph(AreasResult& r, const GridGeometry& geometry);

}  // namespace indoormap::areas::detail
