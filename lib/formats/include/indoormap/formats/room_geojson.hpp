#pragma once
// The room border (pcd-to-map, docs/border-closure.md): room.geojson and room.json, and the
// room.geojson reader of map-eval. The border's value types are only declared here: the
// writers' callers include indoormap/border/border.hpp (im_border).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "indoormap/core/grid.hpp"
#include "indoormap/core/polygon.hpp"

namespace indoormap::border {
struct Opening;
struct BorderResult;
}  // namespace indoormap::border

namespace indoormap::formats {

/// One opening of the border (its ends in map metres, width, door candidate, chain indices).
nlohmann::json border_opening_json(const border::Opening& o);

/// room.geojson: a FeatureCollection in map metres: the room Polygon (kind "room", area_m2,
/// perimeter_m; counter-clockwise, closed ring) when the border is closed, one LineString per
/// opening (kind "opening", width_m, door_candidate) and the boxes of the interior objects that lie
/// inside or on the room polygon (kind "interior_object", class "ring" / "object", cells; the
/// others are in room.json only); "closed", and the "reason" when it is not (then no room and no
/// interior objects, only the openings).
nlohmann::json room_geojson(const border::BorderResult& r);
void write_room_geojson(const std::filesystem::path& path, const border::BorderResult& r);

/// room.json: the raw chain (cells and metres), polygon, openings, components, interior objects
/// and warnings; geometry: the layout's grid.
nlohmann::json room_json(const border::BorderResult& r, const GridGeometry& geometry);

/// Reads room.geojson: the Polygon features whose property "kind" is "room" (outer rings).
/// Throws InputError naming the file and the key.
std::vector<Polygon> read_room_geojson(const std::filesystem::path& path);

}  // namespace indoormap::formats
