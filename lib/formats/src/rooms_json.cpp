#include "indoormap/formats/rooms_json.hpp"

#include <cmath>
#include <string>

#include "indoormap/formats/json.hpp"
#include "json_read.hpp"
#include "json_write.hpp"

namespace indoormap::formats {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace detail;

namespace {

int rooms_int(const json& j, const fs::path& path, const std::string& key) {
  const double v = number(j, path, key);
  // Range first: converting a double outside int's range is undefined.
  if (!(std::abs(v) <= 1e9) || v != std::floor(v)) bad(path, key, "expected an integer");
  return static_cast<int>(v);
}

RoomsFile read_rooms_unguarded(const fs::path& path) {
  const json j = parse_json_file(path);
  if (j.value("type", "") != "FeatureCollection")
    bad(path, "type", "expected \"FeatureCollection\"");
  const json& features = member(j, "features", path, "");
  if (!features.is_array()) bad(path, "features", "expected a list");
  RoomsFile out;
  for (std::size_t i = 0; i < features.size(); ++i) {
    const std::string key = "features[" + std::to_string(i) + "]";
    const json& f = features[i];
    if (!f.is_object() || !f.contains("properties") || !f["properties"].is_object()) continue;
    const json& props = f["properties"];
    const std::string kind = props.value("kind", "");
    if (kind != "room" && kind != "door") continue;
    const json& g = member(f, "geometry", path, key);
    const json& coords = member(g, "coordinates", path, key + ".geometry");
    if (kind == "room") {
      if (g.value("type", "") != "Polygon")
        bad(path, key + ".geometry.type", "a room must be a Polygon");
      if (!coords.is_array() || coords.empty())
        bad(path, key + ".geometry.coordinates", "expected a list of rings");
      RoomsFile::RoomEntry r;
      r.id =
          rooms_int(member(props, "id", path, key + ".properties"), path, key + ".properties.id");
      r.polygon = polygon(coords[0], path, key + ".geometry.coordinates[0]");
      out.rooms.push_back(std::move(r));
      continue;
    }
    if (g.value("type", "") != "LineString" || !coords.is_array() || coords.size() != 2)
      bad(path, key + ".geometry", "a door must be a LineString of two points");
    const json& ab = member(props, "rooms", path, key + ".properties");
    if (!ab.is_array() || ab.size() != 2)
      bad(path, key + ".properties.rooms", "expected two room ids");
    RoomsFile::DoorEntry d;
    d.a = rooms_int(ab[0], path, key + ".properties.rooms[0]");
    d.b = rooms_int(ab[1], path, key + ".properties.rooms[1]");
    d.end0_m = point(coords[0], path, key + ".geometry.coordinates[0]");
    d.end1_m = point(coords[1], path, key + ".geometry.coordinates[1]");
    d.width_m = (d.end1_m - d.end0_m).norm();
    out.doors.push_back(d);
  }
  return out;
}

}  // namespace

json rooms_geojson(const rooms::RoomsResult& r) {
  json features = json::array();
  for (const auto& room : r.rooms)
    features.push_back(
        {{"type", "Feature"},
         {"geometry",
          {{"type", "Polygon"}, {"coordinates", json::array({ring_json(room.polygon_m)})}}},
         {"properties",
          {{"kind", "room"},
           {"id", room.id},
           {"area_m2", room.area_m2},
           {"perimeter_m", room.perimeter_m},
           {"neighbours", room.neighbours}}}});
  for (const auto& d : r.doors)
    features.push_back(
        {{"type", "Feature"},
         {"geometry",
          {{"type", "LineString"}, {"coordinates", {xy_json(d.end0_m), xy_json(d.end1_m)}}}},
         {"properties", {{"kind", "door"}, {"rooms", {d.a, d.b}}, {"width_m", d.width_m}}}});
  return {{"type", "FeatureCollection"}, {"features", features}, {"frame", "map"}};
}

void write_rooms_geojson(const fs::path& path, const rooms::RoomsResult& r) {
  write_json(path, rooms_geojson(r));
}

json rooms_graph_json(const rooms::RoomsResult& r, const std::vector<int>& object_ids,
                      const std::vector<int>& object_rooms) {
  json rooms = json::array();
  for (const auto& room : r.rooms) {
    json doors = json::array(), objects = json::array();
    for (std::size_t k = 0; k < r.doors.size(); ++k)
      if (r.doors[k].a == room.id || r.doors[k].b == room.id) doors.push_back(k + 1);
    for (std::size_t k = 0; k < object_ids.size() && k < object_rooms.size(); ++k)
      if (object_rooms[k] == room.id) objects.push_back(object_ids[k]);
    rooms.push_back({{"id", room.id},
                     {"area_m2", room.area_m2},
                     {"perimeter_m", room.perimeter_m},
                     {"cells", room.cells},
                     {"neighbours", room.neighbours},
                     {"doors", doors},
                     {"objects", objects}});
  }
  json doors = json::array();
  for (std::size_t k = 0; k < r.doors.size(); ++k) {
    const auto& d = r.doors[k];
    doors.push_back({{"id", k + 1},
                     {"rooms", {d.a, d.b}},
                     {"width_m", d.width_m},
                     {"a_m", xy_json(d.end0_m)},
                     {"b_m", xy_json(d.end1_m)}});
  }
  return {{"frame", "map"},
          {"count", r.rooms.size()},
          {"rooms", rooms},
          {"doors", doors},
          {"geometry", "rooms.geojson"}};
}

RoomsFile read_rooms_geojson(const fs::path& path) {
  return guarded(path, [&] { return read_rooms_unguarded(path); });
}

}  // namespace indoormap::formats
