#include "indoormap/rooms/room_objects.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace indoormap::rooms {

namespace {

/// The distinct rooms with a cell within reach_cells of the room grid's cell holding p.
void room_objects_near(const RoomsResult& rooms, const Eigen::Vector2d& p, int reach_cells,
                       std::set<int>& found) {
  const CellIndex at = rooms.geometry.cell_of(p);
  for (int r = at.row - reach_cells; r <= at.row + reach_cells; ++r)
    for (int c = at.col - reach_cells; c <= at.col + reach_cells; ++c) {
      if ((c - at.col) * (c - at.col) + (r - at.row) * (r - at.row) > reach_cells * reach_cells)
        continue;
      if (rooms.labels.contains(c, r) && rooms.labels.at(c, r) != 0)
        found.insert(rooms.labels.at(c, r));
    }
}

}  // namespace

std::vector<int> inner_wall_objects(const objects::ObjectsResult& objs, const GridGeometry& og,
                                    const RoomsResult& rooms, const RoomsParams& params) {
  std::vector<int> ids;
  if (rooms.rooms.size() < 2) return ids;
  // +1: a cell's centre is half a cell from its edge on both sides.
  const int reach =
      static_cast<int>(std::ceil(params.inner_wall_reach_m / rooms.geometry.cell_m())) + 1;
  std::vector<int> both(objs.objects.size(), 0), all(objs.objects.size(), 0);
  std::vector<int> index_of;
  for (std::size_t i = 0; i < objs.objects.size(); ++i) {
    const auto& o = objs.objects[i];
    if (o.id >= static_cast<int>(index_of.size())) index_of.resize(o.id + 1, -1);
    index_of[o.id] = static_cast<int>(i);
  }
  for (int r = 0; r < objs.labels.height; ++r)
    for (int c = 0; c < objs.labels.width; ++c) {
      const int id = objs.labels.at(c, r);
      if (id <= 0 || id >= static_cast<int>(index_of.size()) || index_of[id] < 0) continue;
      std::set<int> s;
      room_objects_near(rooms, og.center_of({c, r}), reach, s);
      const auto k = static_cast<std::size_t>(index_of[id]);
      ++all[k];
      both[k] += s.size() >= 2 ? 1 : 0;
    }
  for (std::size_t i = 0; i < objs.objects.size(); ++i) {
    const auto& o = objs.objects[i];
    const bool standing = o.kind == ObjectKind::kFurniture || o.kind == ObjectKind::kHanging;
    if (!standing || !o.own_cells.empty()) continue;
    // A wall strip has both rooms in reach along much of it; a cabinet beside a door at a corner.
    if (o.box.width_m <= params.inner_wall_max_width_m && all[i] > 0 && 4 * both[i] >= all[i])
      ids.push_back(o.id);
  }
  return ids;
}

std::vector<int> wall_piece_objects(const objects::ObjectsResult& objs, const RoomsResult& rooms,
                                    const RoomsParams& params) {
  std::vector<int> ids;
  if (rooms.rooms.size() < 2) return ids;
  for (const auto& o : objs.objects) {
    const bool standing = o.kind == ObjectKind::kFurniture || o.kind == ObjectKind::kHanging;
    if (!standing || !o.own_cells.empty()) continue;
    const Eigen::Vector2d c = o.box.center_m;
    bool in_room = false;
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& room : rooms.rooms) {
      const Polygon& p = room.polygon_m;
      if (contains(p, c)) {
        in_room = true;
        break;
      }
      for (std::size_t i = 0; i < p.size(); ++i)
        nearest = std::min(nearest, point_segment_distance(c, p[i], p[(i + 1) % p.size()]));
    }
    if (!in_room && nearest <= params.wall_piece_reach_m) ids.push_back(o.id);
  }
  return ids;
}

int remove_objects(objects::ObjectsResult& objs, const std::vector<int>& ids) {
  const std::set<int> drop(ids.begin(), ids.end());
  const auto before = objs.objects.size();
  std::erase_if(objs.objects, [&](const auto& o) { return drop.count(o.id) > 0; });
  for (auto& v : objs.labels.data)
    if (drop.count(v)) v = 0;
  return static_cast<int>(before - objs.objects.size());
}

std::vector<int> object_rooms(const objects::ObjectsResult& objs, const RoomsResult& rooms) {
  std::vector<int> out;
  out.reserve(objs.objects.size());
  for (const auto& o : objs.objects) out.push_back(room_at(rooms, o.box.center_m));
  return out;
}

}  // namespace indoormap::rooms
