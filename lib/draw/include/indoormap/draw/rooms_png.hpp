#pragma once
// pcd-to-map's rooms.png (docs/pcd-to-map.md, "Rooms"): the navigation map north up, each room's
// cells in its own pastel tint, its polygon outlined, its id at its centre, the doors as green
// lines, the objects' footprints in their kinds' colours, a legend and a 1 m scale bar.
#include <filesystem>
#include <string>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/core/object_kind.hpp"
#include "indoormap/core/polygon.hpp"
#include "indoormap/rooms/rooms.hpp"

namespace indoormap::draw {

/// nav: the navigation map (grid of rooms.geometry); objects: footprints, map frame, each in the
/// colour of its kind (kind_rgb, as in objects.png) when kinds has one entry per footprint, all
/// in furniture's otherwise. Throws OutputError.
void write_rooms_png(const std::filesystem::path& path, const rooms::RoomsResult& rooms,
                     const Grid<Cell>& nav, const std::vector<Polygon>& objects,
                     const std::string& title, const std::vector<ObjectKind>& kinds = {});

}  // namespace indoormap::draw
