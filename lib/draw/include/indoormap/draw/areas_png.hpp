#pragma once
// grid-areas' picture (docs/grid-areas.md): areas.png, the map north up with each area filled by
// its kind (rooms in varied pastel tints so that neighbours differ, corridors blue, crossings
// orange), area borders, doors, free space too narrow for the footprint, a legend and a 1 m
// scale bar.
#include <filesystem>
#include <string>

#include "indoormap/areas/areas.hpp"
#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::draw {

/// Throws OutputError.
void write_areas_png(const std::filesystem::path& path, const areas::AreasResult& r,
                     const Grid<Cell>& cells, const GridGeometry& geometry,
                     const std::string& title);

}  // namespace indoormap::draw
