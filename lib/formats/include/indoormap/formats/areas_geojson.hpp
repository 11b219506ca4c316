#pragma once
// grid-areas' files (docs/grid-areas.md): areas.geojson (a Polygon per area in map metres, doors
// as LineStrings), areas.json (id -> type, the connectivity graph with the door of each pair)
// and areas_labels.png (16-bit, north up, value = area id, 0 = not in an area).
#include <filesystem>
#include <nlohmann/json.hpp>

#include "indoormap/areas/areas.hpp"

namespace indoormap::formats {

/// FeatureCollection: per area a Polygon (outer ring counter-clockwise, holes clockwise, rings
/// closed) with properties type (room / corridor / crossing), id, area_m2, connects_to; per door
/// a LineString with type "door", between [a, b] and width_m.
nlohmann::ordered_json areas_geojson(const areas::AreasResult& r);
void write_areas_geojson(const std::filesystem::path& path, const areas::AreasResult& r);

/// areas.json: areas (id, type, area_m2, cells), graph (nodes, edges with their door), the
/// crossing checks, and the counts (free, reachable, components).
nlohmann::ordered_json areas_json(const areas::AreasResult& r);

/// The label grid as a 16-bit grey PNG, north up. Throws OutputError.
void write_labels_png(const std::filesystem::path& path, const Grid<std::uint16_t>& labels);
/// Reads a 16-bit (or 8-bit) label PNG written by write_labels_png (rows back to y up).
/// Throws InputError naming the file.
Grid<std::uint16_t> read_labels_png(const std::filesystem::path& path);

}  // namespace indoormap::formats
