#include "rooms_outputs.hpp"

#include <algorithm>
#include <chrono>

#include "indoormap/draw/rooms_png.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/formats/rooms_json.hpp"
#include "indoormap/layout/nav_map.hpp"
#include "indoormap/rooms/room_objects.hpp"

namespace indoormap::app {

namespace fs = std::filesystem;
using nlohmann::json;

StoreyRooms find_storey_rooms(const layout::MapResult& m, objects::ObjectsResult& objs,
                              const border::BorderParams& border_params,
                              const rooms::RoomsParams& params) {
  const auto t0 = std::chrono::steady_clock::now();
  StoreyRooms r;
  const Grid<Cell> seen_nav = layout::map_without_over_low(m.nav);
  r.rooms = rooms::find_rooms(seen_nav, m.geometry, params);
  // A neck between furniture across one room, wider than a door and without jambs, is no door.
  rooms::join_furniture_necks(r.rooms, m.layout.layout, border_params.door_max_m);
  r.inner_walls = rooms::inner_wall_objects(objs, m.geometry, r.rooms, params);
  // The polygons reach the walls of M_r (behind furniture too), never into an inner-wall strip
  // or a piece the objects step took for wall (the wall under a window, a wall's face).
  Grid<std::uint8_t> blocked(objs.labels.width, objs.labels.height, 0);
  const bool wall_cells = objs.wall_cells.data.size() == blocked.data.size();
  for (std::size_t i = 0; i < objs.labels.data.size(); ++i)
    blocked.data[i] = std::find(r.inner_walls.begin(), r.inner_walls.end(), objs.labels.data[i]) !=
                          r.inner_walls.end() ||
                      (wall_cells && objs.wall_cells.data[i]);
  // Walls that M_r saw from one side only keep their body, so that the room on the unseen side
  // does not take the wall in.
  const Grid<Cell> walls =
      rooms::mark_wall_bodies(m.layout.layout, seen_nav, r.rooms, params.wall_piece_reach_m);
  rooms::fill_rooms(r.rooms, walls, blocked);
  r.fitted = rooms::fit_rooms_to_faces(r.rooms, walls, border_params);
  rooms::remove_objects(objs, r.inner_walls);
  r.wall_pieces = rooms::wall_piece_objects(objs, r.rooms, params);
  rooms::remove_objects(objs, r.wall_pieces);
  r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

void remove_objects_on(objects::ObjectsResult& objs, const Grid<std::int32_t>& pieces,
                       const StoreyRooms& r) {
  std::vector<int> dropped = r.inner_walls;
  dropped.insert(dropped.end(), r.wall_pieces.begin(), r.wall_pieces.end());
  if (dropped.empty() || pieces.data.size() != objs.labels.data.size()) return;
  std::vector<std::int64_t> on(objs.objects.size() + 1, 0);
  std::vector<int> index_of;  // object id -> index + 1
  for (std::size_t i = 0; i < objs.objects.size(); ++i) {
    const int id = objs.objects[i].id;
    if (id >= static_cast<int>(index_of.size())) index_of.resize(id + 1, 0);
    index_of[id] = static_cast<int>(i) + 1;
  }
  for (std::size_t c = 0; c < pieces.data.size(); ++c) {
    const int id = objs.labels.data[c];
    if (id > 0 && id < static_cast<int>(index_of.size()) && index_of[id] > 0 &&
        std::find(dropped.begin(), dropped.end(), pieces.data[c]) != dropped.end())
      ++on[index_of[id]];
  }
  std::vector<int> ids;
  for (std::size_t i = 0; i < objs.objects.size(); ++i)
    if (objs.objects[i].own_cells.empty() && 2 * on[i + 1] >= objs.objects[i].cells)
      ids.push_back(objs.objects[i].id);
  rooms::remove_objects(objs, ids);
}

void assign_rooms(StoreyRooms& r, const objects::ObjectsResult& objs) {
  r.object_rooms = rooms::object_rooms(objs, r.rooms);
}

json write_rooms_outputs(const fs::path& out, const layout::MapResult& m,
                         const objects::ObjectsResult& objs, const StoreyRooms& r) {
  std::vector<int> ids;
  std::vector<Polygon> footprints;
  std::vector<ObjectKind> kinds;
  for (const auto& o : objs.objects) {
    ids.push_back(o.id);
    footprints.push_back(o.footprint_m);
    kinds.push_back(o.kind);
  }
  formats::write_rooms_geojson(out / "rooms.geojson", r.rooms);
  formats::write_json(out / "rooms.json", formats::rooms_graph_json(r.rooms, ids, r.object_rooms));
  draw::write_rooms_png(out / "rooms.png", r.rooms, m.nav.map, footprints,
                        "rooms of the navigation map", kinds);
  double area = 0.0;
  for (const auto& room : r.rooms.rooms) area += room.area_m2;
  return {{"count", r.rooms.rooms.size()},
          {"doors", r.rooms.doors.size()},
          {"area_m2", area},
          {"inner_walls_dropped", r.inner_walls},
          {"wall_pieces_dropped", r.wall_pieces},
          {"fitted_to_faces", r.fitted},
          {"time_ms", r.ms},
          {"outputs", {"rooms.geojson", "rooms.json", "rooms.png"}}};
}

}  // namespace indoormap::app
