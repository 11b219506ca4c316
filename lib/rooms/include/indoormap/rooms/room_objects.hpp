#pragma once
// The objects of each room, and the inner walls the objects step lists as furniture
// (docs/border-closure.md, "Rooms of a floor"). The room layout M_r marks what stands in the
// furniture band below the wall band; a wall between two rooms whose top the scanners do not see
// clear of the ceiling lands there as a long thin "furniture" strip. The navigation map knows
// better: such a strip has the free space of two different rooms right beside it.
#include <vector>

#include "indoormap/objects/objects.hpp"
#include "indoormap/rooms/rooms.hpp"

namespace indoormap::rooms {

/// Ids of the objects that are inner walls: kind furniture, oriented box at most
/// params.inner_wall_max_width_m wide, at least a quarter of whose cells have cells of two
/// different rooms within params.inner_wall_reach_m. objects_geometry: the grid of objs.labels (the
/// layout's); the rooms' grid may differ (cells are matched by their centres).
std::vector<int> inner_wall_objects(const objects::ObjectsResult& objs,
                                    const GridGeometry& objects_geometry, const RoomsResult& rooms,
                                    const RoomsParams& params = {});

/// Ids of the objects that lie in a wall, once the rooms' polygons are on the wall faces
/// (fit_rooms_to_faces): kind furniture or hanging, without cells of its own (a lamp has them),
/// box centre in no room's polygon and within params.wall_piece_reach_m of one (the wall under a window whose
/// lintel was not seen, pieces of a wall's face or of an inner wall the strip rule left). None
/// with fewer than two rooms: a single room's scan sees furniture beyond its door or window.
std::vector<int> wall_piece_objects(const objects::ObjectsResult& objs, const RoomsResult& rooms,
                                    const RoomsParams& params = {});

/// Removes the objects of `ids` from objs.objects and their cells from objs.labels (ids of the
/// others unchanged). Returns how many were removed.
int remove_objects(objects::ObjectsResult& objs, const std::vector<int>& ids);

/// The room id of each object (room_at of its box centre; 0: in no room), in objs.objects order.
std::vector<int> object_rooms(const objects::ObjectsResult& objs, const RoomsResult& rooms);

}  // namespace indoormap::rooms
