#include "indoormap/formats/room_geojson.hpp"

#include <string>

#include "indoormap/border/border.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/polygon.hpp"
#include "json_read.hpp"
#include "json_write.hpp"

namespace indoormap::formats {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace detail;

namespace {

json object_json(const border::InteriorObject& o) {
  return {{"min_m", xy_json(o.min_m)},
          {"max_m", xy_json(o.max_m)},
          {"min_cell", {o.min.col, o.min.row}},
          {"max_cell", {o.max.col, o.max.row}},
          {"cells", o.cells},
          {"kind", std::string(border::to_string(o.kind))}};
}

// Inside or on the room: every vertex of `shape` lies inside `room` or within 1 um of its edges.
bool room_geojson_inside_or_on(const indoormap::Polygon& room, const indoormap::Polygon& shape) {
  for (const auto& p : shape) {
    if (indoormap::contains(room, p)) continue;
    bool on = false;
    for (std::size_t i = 0; i < room.size() && !on; ++i)
      on = indoormap::point_segment_distance(p, room[i], room[(i + 1) % room.size()]) <= 1e-6;
    if (!on) return false;
  }
  return true;
}

std::vector<Polygon> read_room_geojson_unguarded(const fs::path& path) {
  const json j = parse_json_file(path);
  if (j.value("type", "") != "FeatureCollection")
    bad(path, "type", "expected \"FeatureCollection\"");
  const json& features = member(j, "features", path, "");
  if (!features.is_array()) bad(path, "features", "expected a list");
  std::vector<Polygon> out;
  for (std::size_t i = 0; i < features.size(); ++i) {
    const std::string key = "features[" + std::to_string(i) + "]";
    const json& f = features[i];
    if (!f.is_object() || !f.contains("properties") || !f["properties"].is_object()) continue;
    if (f["properties"].value("kind", "") != "room") continue;
    const json& g = member(f, "geometry", path, key);
    if (g.value("type", "") != "Polygon")
      bad(path, key + ".geometry.type", "a room must be a Polygon");
    const json& rings = member(g, "coordinates", path, key + ".geometry");
    if (!rings.is_array() || rings.empty())
      bad(path, key + ".geometry.coordinates", "expected a list of rings");
    out.push_back(polygon(rings[0], path, key + ".geometry.coordinates[0]"));
  }
  return out;
}

}  // namespace

json border_opening_json(const border::Opening& o) {
  return {{"a_m", xy_json(o.a_m)},        {"b_m", xy_json(o.b_m)},
          {"width_m", o.width_m},         {"door_candidate", o.is_door_candidate},
          {"chain_first", o.chain_first}, {"chain_last", o.chain_last}};
}

json room_geojson(const border::BorderResult& r) {
  json features = json::array();
  if (r.closed) {
    features.push_back(
        {{"type", "Feature"},
         {"geometry",
          {{"type", "Polygon"}, {"coordinates", json::array({ring_json(r.polygon_m)})}}},
         {"properties",
          {{"kind", "room"}, {"area_m2", r.area_m2}, {"perimeter_m", r.perimeter_m}}}});
  }
  for (const auto& o : r.openings)
    features.push_back(
        {{"type", "Feature"},
         {"geometry", {{"type", "LineString"}, {"coordinates", {xy_json(o.a_m), xy_json(o.b_m)}}}},
         {"properties",
          {{"kind", "opening"}, {"width_m", o.width_m}, {"door_candidate", o.is_door_candidate}}}});
  // Interior objects only inside or on the room (the others are other rooms' or the outside's
  // components; room.json lists them all). Without a room, none.
  for (const auto& o : r.interior_objects) {
    const indoormap::Polygon box{
        o.min_m, {o.max_m.x(), o.min_m.y()}, o.max_m, {o.min_m.x(), o.max_m.y()}};
    if (!r.closed || !room_geojson_inside_or_on(r.polygon_m, box)) continue;
    features.push_back(
        {{"type", "Feature"},
         {"geometry", {{"type", "Polygon"}, {"coordinates", json::array({ring_json(box)})}}},
         {"properties",
          {{"kind", "interior_object"},
           {"class", std::string(border::to_string(o.kind))},
           {"cells", o.cells}}}});
  }
  json fc = {{"type", "FeatureCollection"}, {"features", features}, {"closed", r.closed}};
  if (!r.closed) fc["reason"] = r.reason;
  return fc;
}

void write_room_geojson(const fs::path& path, const border::BorderResult& r) {
  write_file_atomic(path, room_geojson(r).dump(2) + "\n");
}

json room_json(const border::BorderResult& r, const GridGeometry& geometry) {
  json openings = json::array();
  for (const auto& o : r.openings) openings.push_back(border_opening_json(o));
  json objects = json::array();
  for (const auto& o : r.interior_objects) objects.push_back(object_json(o));
  json chain_cells = json::array(), chain_m = json::array(), polygon = json::array(),
       components = json::array();
  for (const auto& c : r.chain) chain_cells.push_back({c.col, c.row});
  for (const auto& p : r.chain_m) chain_m.push_back(xy_json(p));
  for (const auto& p : r.polygon_m) polygon.push_back(xy_json(p));
  for (const auto& c : r.components)
    components.push_back({{"label", c.label},
                          {"start_cell", {c.start.col, c.start.row}},
                          {"min_cell", {c.min.col, c.min.row}},
                          {"max_cell", {c.max.col, c.max.row}},
                          {"cells", c.cells},
                          {"switches", c.switches},
                          {"kind", std::string(border::to_string(c.kind))},
                          {"note", c.note}});
  return {{"closed", r.closed},
          {"reason", r.reason},
          {"frame", "map"},
          {"cell_m", geometry.cell_m()},
          {"origin_m", xy_json(geometry.origin_m())},
          {"scanner_m", xy_json(r.scanner_m)},
          {"chain_cells", chain_cells},
          {"chain_m", chain_m},
          {"polygon_m", polygon},
          {"area_m2", r.area_m2},
          {"perimeter_m", r.perimeter_m},
          {"openings", openings},
          {"components", components},
          {"interior_objects", objects},
          {"warnings", r.warnings}};
}

std::vector<Polygon> read_room_geojson(const fs::path& path) {
  return guarded(path, [&] { return read_room_geojson_unguarded(path); });
}

}  // namespace indoormap::formats
