#pragma once
// The rooms of a floor (docs/border-closure.md, "Rooms of a floor"): the free space of a storey's
// navigation map split into rooms joined by doors (the room segmentation of im_areas,
// docs/grid-areas.md), each room's closed polygon and the room graph.
//
// Polygon: the outer outline of the room's cells, pushed half a cell outwards. A wall face lies,
// on average, half a cell inside the first occupied cell, so the free cells' edge is half a cell
// short of it; the outline at half-cell resolution, grown by one half cell, lands on the face.
// Obstacles inside the room (furniture, unseen spots) are holes and left out: the polygon is the
// outer ring only. fit_rooms_to_faces then fits that outline to M_r's wall faces (the border
// closure's step 6), which takes off the staircase of rotated walls and the notches of shadows.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "indoormap/areas/params.hpp"
#include "indoormap/border/params.hpp"
#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/core/polygon.hpp"

namespace indoormap::rooms {

struct RoomsParams {
  /// The segmentation (areas::RoomParams); its defaults are set for a robot of about 0.5 m on
  /// 5 cm cells, not for any scene: doors are necks of at most 1.5 m.
  areas::RoomParams segmentation;
  /// Pieces of free space smaller than this are no room (specks outside windows, under tables).
  double min_room_area_m2 = 1.5;
  /// Inner-wall strips among the objects (room_objects.hpp): an object whose oriented box is at
  /// most this wide ...
  double inner_wall_max_width_m = 0.45;
  /// ... with cells of two different rooms within this distance of most of its cells is wall:
  /// furniture stands in one room, and a wall (0.1 m or more) plus its face cells lie between it
  /// and the next room.
  double inner_wall_reach_m = 0.15;
  /// An object whose box centre lies in no room's polygon but within this distance of one lies in
  /// a wall (room_objects.hpp, wall_piece_objects): furniture stands in a room, and a wall is
  /// at most 0.3 m thick on the simulated and scanned buildings. Also the depth of a wall's body
  /// behind a face seen from one side only (mark_wall_bodies).
  double wall_piece_reach_m = 0.3;
};

/// Throws UsageError naming the key (rooms.<key>).
void validate(const RoomsParams& params);

struct Room {
  int id = 0;  ///< 1-based; the value of its cells in RoomsResult::labels
  int cells = 0;
  double area_m2 = 0.0;         ///< of the polygon
  double perimeter_m = 0.0;     ///< of the polygon
  Polygon polygon_m;            ///< counter-clockwise, map frame, no closing vertex
  std::vector<int> neighbours;  ///< rooms it shares a door with, ascending
};

/// A door: where two rooms' cells touch (4-neighbours); end points of that border, map frame.
struct RoomDoor {
  int a = 0, b = 0;  ///< room ids, a < b
  Eigen::Vector2d end0_m = Eigen::Vector2d::Zero(), end1_m = Eigen::Vector2d::Zero();
  double width_m = 0.0;  ///< extent of the shared border along its main axis, plus one cell
  int shared_cells = 0;
};

struct RoomsResult {
  GridGeometry geometry;       ///< the navigation map's
  Grid<std::uint16_t> labels;  ///< room id per cell of the navigation map (0: no room)
  std::vector<Room> rooms;     ///< rooms[i].id == i + 1
  std::vector<RoomDoor> doors;
  /// Non-zero: a door's passage through its wall, which fill_rooms took out of both rooms (empty
  /// before fill_rooms). fit_rooms_to_faces counts it as no room space.
  Grid<std::uint8_t> passages;
};

/// Splits the free cells (Cell::kFree) of a navigation map into rooms. No free cell gives no
/// room (no exception). Throws UsageError for invalid params.
RoomsResult find_rooms(const Grid<Cell>& nav, const GridGeometry& geometry,
                       const RoomsParams& params = {});

/// Joins the rooms the segmentation split at a neck between furniture: a door wider than
/// door_max_m neither of whose ends has a jamb within reach_m (a wall cell of the room layout M_r,
/// `layout`, on the rooms' grid, in a piece of wall of at least 1 m2: a pillar is none) is no
/// opening in a wall, but the narrowing between furniture and pillars across one room (an
/// L-shaped room with a table at its bend). A door in a wall M_r saw only low (as furniture) has
/// no jambs either; its width tells it apart. Labels, rooms, polygons and doors are rebuilt; ids
/// stay in the order of the rooms' first pieces. Returns how many doors were joined across; a
/// layout of another size joins none.
int join_furniture_necks(RoomsResult& rooms, const Grid<Cell>& layout, double door_max_m = 1.2,
                         double reach_m = 0.2);

/// M_r with the bodies of walls seen from one side only marked as wall (nav: the navigation map
/// the rooms were found in). Where M_r's wall band saw a wall between two rooms from one side only
/// (a corridor's wall at a grazing angle, a face in a pillar's shadow, a face a mobile scanner
/// passed by), its flood ran through the wall's body up to the far face, and the room on the
/// unseen side would take the wall in. The far face is the other room's: its wall cells have that
/// room's free cells (and no other room's) within two cells, straight in front of the face. From
/// each such cell, straight back along the face's normal: after at most two wall cells (the face),
/// the cells that M_r calls free or furniture and that are no room's free cells are the body, up
/// to max_wall_m, a room's cell, an unknown cell or a second wall, or an obstacle of nav that
/// follows body cells which are none (the near face seen low down). They become wall when another
/// room lies behind: within 2 m of the face, or within max_wall_m and two cells of it when nav saw
/// the whole body as an obstacle (the wall's top, seen from above by a mobile scanner). The
/// result is for fill_rooms and fit_rooms_to_faces; M_r itself stays the paper's. Grids of another
/// size than the rooms' leave layout as it is.
Grid<Cell> mark_wall_bodies(const Grid<Cell>& layout, const Grid<Cell>& nav,
                            const RoomsResult& rooms, double max_wall_m);

/// Wall-bounded rooms: each room's cells grown (all rooms at once, 4-neighbours, first come
/// first served) into the cells that are not free, up to max_fill_m (2 m: a group of cabinets
/// filling a room's corner; at 1 m the buildings' rooms kept notches there, 3 m changes nothing
/// more on them), stopping at the wall cells
/// of the room layout M_r (its wall band, seen above the furniture), at `blocked` cells (the
/// inner-wall strips) and at other rooms' cells; the polygons (and areas, perimeters) are
/// redrawn from the grown cells, so furniture and the unseen floor behind it along a wall no
/// longer cut notches into them. A door's passage leaves both rooms (rooms.passages holds it).
/// Labels and doors stay those of the free space. layout and
/// blocked (non-zero: blocked; may be empty) share the rooms' grid; a layout of another size
/// leaves the rooms unchanged.
void fill_rooms(RoomsResult& rooms, const Grid<Cell>& layout, const Grid<std::uint8_t>& blocked,
                double max_fill_m = 2.0);

/// Every room's polygon fitted to the wall faces of the room layout M_r (`layout`, on the rooms'
/// grid; the rooms' free cells count as room space beside a face, the doors' passages as none:
/// a jamb's side is no face of the room), as the paper's border closure
/// fits a single room's (border::fit_to_wall_faces): a straight line per wall face instead of the
/// cells' staircase, door recesses and the shadows of objects along a wall bridged. A room keeps
/// its cell outline when the fit fails, when the fitted polygon's area differs from the outline's
/// by more than max_area_change (a share), covers more than 0.1 m2 of other rooms' free cells or
/// leaves more than 5 % of its own outside. Area and perimeter follow the polygon. Returns how many
/// rooms were fitted; a layout of another size fits none.
int fit_rooms_to_faces(RoomsResult& rooms, const Grid<Cell>& layout,
                       const border::BorderParams& params = {}, double max_area_change = 0.1);

/// The id of the room whose polygon holds p (map frame), else of the room with a labelled cell
/// nearest p within max_m, else 0.
int room_at(const RoomsResult& rooms, const Eigen::Vector2d& p_m, double max_m = 0.5);

}  // namespace indoormap::rooms
