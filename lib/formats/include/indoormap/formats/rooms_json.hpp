#pragma once
// The rooms of a floor (docs/pcd-to-map.md, "Rooms"): rooms.geojson (a Polygon per room, a
// LineString per door) and rooms.json (the room graph), writers and the rooms.geojson reader of
// map-eval.
#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "indoormap/core/polygon.hpp"
#include "indoormap/rooms/rooms.hpp"

namespace indoormap::formats {

/// rooms.geojson: FeatureCollection; per room a Polygon {kind "room", id, area_m2, perimeter_m,
/// neighbours}, per door a LineString {kind "door", rooms [a, b], width_m}. Map frame, metres.
nlohmann::json rooms_geojson(const rooms::RoomsResult& r);
void write_rooms_geojson(const std::filesystem::path& path, const rooms::RoomsResult& r);

/// rooms.json: {frame, count, rooms: [{id, area_m2, perimeter_m, cells, neighbours, doors,
/// objects}], doors: [{id, rooms, width_m, a_m, b_m}]}. object_rooms: the room of each object
/// (object_ids in the same order), or both empty.
nlohmann::json rooms_graph_json(const rooms::RoomsResult& r, const std::vector<int>& object_ids,
                                const std::vector<int>& object_rooms);

/// rooms.geojson as map-eval reads it.
struct RoomsFile {
  struct RoomEntry {
    int id = 0;
    Polygon polygon;  ///< outer ring, no closing vertex
  };
  struct DoorEntry {
    int a = 0, b = 0;
    Eigen::Vector2d end0_m = Eigen::Vector2d::Zero(), end1_m = Eigen::Vector2d::Zero();
    double width_m = 0.0;
  };
  std::vector<RoomEntry> rooms;
  std::vector<DoorEntry> doors;
};

/// Reads rooms.geojson. Throws InputError naming the file and the key.
RoomsFile read_rooms_geojson(const std::filesystem::path& path);

}  // namespace indoormap::formats
