#pragma once
// pcd-to-map's rooms of a storey (docs/pcd-to-map.md, "Rooms"): found on the navigation map,
// the inner walls dropped from the objects, each object's room; rooms.geojson, rooms.json and
// rooms.png, and the summary's "rooms" block.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "indoormap/border/params.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "indoormap/objects/objects.hpp"
#include "indoormap/rooms/rooms.hpp"

namespace indoormap::app {

struct StoreyRooms {
  rooms::RoomsResult rooms;
  std::vector<int> inner_walls;   ///< ids of the objects dropped as inner walls
  std::vector<int> wall_pieces;   ///< ids of the objects dropped as lying in a wall
  std::vector<int> object_rooms;  ///< per object of the final list (set by assign_rooms)
  int fitted = 0;                 ///< rooms whose polygon was fitted to the wall faces
  double ms = 0.0;
};

/// Finds the rooms of the map's navigation map, fits their polygons to the wall faces (with the
/// border closure's parameters) and drops the inner-wall strips and the pieces in a wall from objs.
StoreyRooms find_storey_rooms(const layout::MapResult& m, objects::ObjectsResult& objs,
                              const border::BorderParams& border_params,
                              const rooms::RoomsParams& params = {});

/// Sets r.object_rooms for the final object list.
void assign_rooms(StoreyRooms& r, const objects::ObjectsResult& objs);

/// Writes rooms.geojson, rooms.json and rooms.png into out; returns the summary block (with its
/// "outputs").
/// Drops from objs the objects that lie mostly (half their cells or more) on the pieces that r
/// dropped as inner walls or as lying in a wall; `pieces` holds those pieces' ids per cell (the
/// labels of the extraction find_storey_rooms was given). For objects extracted again from the
/// same map, without its stray returns.
void remove_objects_on(objects::ObjectsResult& objs, const Grid<std::int32_t>& pieces,
                       const StoreyRooms& r);

nlohmann::json write_rooms_outputs(const std::filesystem::path& out, const layout::MapResult& m,
                                   const objects::ObjectsResult& objs, const StoreyRooms& r);

}  // namespace indoormap::app
