// lib/rooms: rooms of a navigation map, their polygons and doors, the inner-wall rule and each
// object's room; rooms.geojson / rooms.json of lib/formats. Hand-made grids of 5 cm cells.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <set>

#include "indoormap/border/border.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/core/polygon.hpp"
#include "indoormap/formats/rooms_json.hpp"
#include "indoormap/rooms/room_objects.hpp"
#include "indoormap/rooms/rooms.hpp"
#include "test_support.hpp"

using namespace indoormap;

namespace {

constexpr double kCell = 0.05;

// Two rooms 3 m x 2 m (60 x 40 cells) side by side along x, a 0.2 m wall (4 cells) between them
// with a 0.8 m door (16 cells) in its middle, and a one-cell wall all round. Cell (0, 0) has its
// lower-left corner at the map origin.
struct TwoRooms {
  Grid<Cell> nav{1 + 60 + 4 + 60 + 1, 1 + 40 + 1, Cell::kWall};
  GridGeometry geometry{{0.0, 0.0}, kCell, 126, 42};
  TwoRooms() {
    for (int r = 1; r <= 40; ++r) {
      for (int c = 1; c <= 60; ++c) nav.at(c, r) = Cell::kFree;
      for (int c = 65; c <= 124; ++c) nav.at(c, r) = Cell::kFree;
    }
    for (int r = 13; r < 29; ++r)  // the door
      for (int c = 61; c <= 64; ++c) nav.at(c, r) = Cell::kFree;
  }
};

// The rooms of TwoRooms with the door's passage labelled by `room_of(col, row)` (as the
// segmentation may split it) and the door's ends set: the input of fill_rooms' passage cut.
template <class RoomOf>
rooms::RoomsResult split_passage(const TwoRooms& t, RoomOf room_of, Eigen::Vector2d end0,
                                 Eigen::Vector2d end1) {
  rooms::RoomsResult r = rooms::find_rooms(t.nav, t.geometry);
  EXPECT_EQ(r.rooms.size(), 2u);
  EXPECT_EQ(r.doors.size(), 1u);
  for (int row = 13; row < 29; ++row)
    for (int c = 61; c <= 64; ++c)
      r.labels.at(c, row) = static_cast<std::uint16_t>(room_of(c, row));
  if (!r.doors.empty()) r.doors[0].end0_m = end0, r.doors[0].end1_m = end1;
  return r;
}

}  // namespace

TEST(Rooms, TwoRoomsJoinedByOneDoor) {
  const TwoRooms t;
  const rooms::RoomsResult r = rooms::find_rooms(t.nav, t.geometry);
  ASSERT_EQ(r.rooms.size(), 2u);
  ASSERT_EQ(r.doors.size(), 1u);
  const auto& d = r.doors[0];
  EXPECT_EQ(d.a, 1);
  EXPECT_EQ(d.b, 2);
  EXPECT_NEAR(d.width_m, 0.8, 1e-9);  // the door's 16 cells across
  // The door lies in the wall between x = 3.05 and 3.25 m, spanning y = 0.65 .. 1.45 m.
  const Eigen::Vector2d mid = 0.5 * (d.end0_m + d.end1_m);
  EXPECT_GT(mid.x(), 3.05);
  EXPECT_LT(mid.x(), 3.25);
  EXPECT_NEAR(mid.y(), 1.05, 1e-9);
  for (const auto& room : r.rooms) {
    // The free cells (6 m2, plus up to the door's cells) grown half a cell all round: the
    // rectangle 3.05 x 2.05 m = 6.2525 m2, with at most the door passage (0.16 m2) on top; the
    // simplification (half a cell) may cut corners by a little.
    EXPECT_GT(room.area_m2, 6.25 * 0.99) << room.id;
    EXPECT_LT(room.area_m2, 6.25 + 0.17) << room.id;
    EXPECT_NEAR(room.perimeter_m, 2 * (3.05 + 2.05), 0.5) << room.id;
    EXPECT_EQ(room.neighbours, std::vector<int>{room.id == 1 ? 2 : 1});
  }
  // Room 1 is the left one; its polygon holds its centre, not the other's.
  EXPECT_EQ(rooms::room_at(r, {1.5, 1.0}), 1);
  EXPECT_EQ(rooms::room_at(r, {4.8, 1.0}), 2);
  EXPECT_EQ(rooms::room_at(r, {10.0, 10.0}), 0);
}

TEST(Rooms, OneRoomWithoutDoorsAndAnEmptyMap) {
  TwoRooms t;
  for (int r = 13; r < 29; ++r)  // wall the door up
    for (int c = 61; c <= 64; ++c) t.nav.at(c, r) = Cell::kWall;
  const auto r = rooms::find_rooms(t.nav, t.geometry);
  EXPECT_EQ(r.rooms.size(), 2u);
  EXPECT_TRUE(r.doors.empty());
  const Grid<Cell> none(10, 10, Cell::kUnknown);
  const auto e = rooms::find_rooms(none, GridGeometry({0, 0}, kCell, 10, 10));
  EXPECT_TRUE(e.rooms.empty());
  EXPECT_TRUE(e.doors.empty());
}

TEST(Rooms, InvalidParametersNameTheKey) {
  rooms::RoomsParams p;
  p.inner_wall_reach_m = -1.0;
  try {
    rooms::validate(p);
    FAIL() << "no exception";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("rooms.inner_wall_reach_m"), std::string::npos);
  }
}

TEST(Rooms, InnerWallStripIsDroppedFurnitureStays) {
  const TwoRooms t;
  const auto r = rooms::find_rooms(t.nav, t.geometry);
  objects::ObjectsResult objs;
  objs.labels = Grid<std::int32_t>(t.nav.width, t.nav.height, 0);
  // 1: the wall strip below the door (columns 61-64, rows 1-12), 0.2 m x 0.6 m.
  objects::FurnitureObject wall;
  wall.id = 1;
  wall.box.width_m = 0.2;
  wall.box.length_m = 0.6;
  wall.box.center_m = {3.15, 0.35};
  for (int row = 1; row <= 12; ++row)
    for (int c = 61; c <= 64; ++c) objs.labels.at(c, row) = 1;
  // 2: a cabinet 0.4 x 0.6 m against the wall in room 2 (columns 65-72, rows 30-40).
  objects::FurnitureObject cabinet;
  cabinet.id = 2;
  cabinet.box.width_m = 0.4;
  cabinet.box.length_m = 0.55;
  cabinet.box.center_m = {3.45, 1.78};
  for (int row = 30; row <= 40; ++row)
    for (int c = 65; c <= 72; ++c) objs.labels.at(c, row) = 2;
  objs.objects = {wall, cabinet};
  const std::vector<int> ids = rooms::inner_wall_objects(objs, t.geometry, r);
  EXPECT_EQ(ids, std::vector<int>{1});
  EXPECT_EQ(rooms::remove_objects(objs, ids), 1);
  ASSERT_EQ(objs.objects.size(), 1u);
  EXPECT_EQ(objs.objects[0].id, 2);
  EXPECT_EQ(objs.labels.at(62, 5), 0);
  EXPECT_EQ(objs.labels.at(66, 35), 2);
  EXPECT_EQ(rooms::object_rooms(objs, r), std::vector<int>{2});
}

// M_r holds the door's lintel: wall along both faces of the passage, its inside unseen. The
// segmentation split the passage along a diagonal (jamb corner to jamb corner), so the cells it
// gave each room are not closed along the door's axis and the passage cut leaves them; they are
// cut off from the room by the lintel's face, so the room keeps only its main part and its
// outline ends at its own face.
TEST(Rooms, PassagePiecesBeyondTheLintelLeaveTheRoom) {
  const TwoRooms t;
  rooms::RoomsResult r = rooms::find_rooms(t.nav, t.geometry);
  ASSERT_EQ(r.rooms.size(), 2u);
  ASSERT_EQ(r.doors.size(), 1u);
  Grid<Cell> layout = t.nav;
  for (int row = 13; row < 29; ++row) {
    layout.at(61, row) = layout.at(64, row) = Cell::kWall;
    layout.at(62, row) = layout.at(63, row) = Cell::kUnknown;
    for (int c = 61; c <= 64; ++c)  // below the diagonal: room 1, above: room 2
      r.labels.at(c, row) = static_cast<std::uint16_t>(4 * (c - 61) < (row - 13) ? 1 : 2);
  }
  r.doors[0].end0_m = {3.05, 0.65};
  r.doors[0].end1_m = {3.25, 1.45};
  rooms::fill_rooms(r, layout, {});
  const int left = rooms::room_at(r, {1.5, 1.0}), right = rooms::room_at(r, {4.8, 1.0});
  ASSERT_EQ(left, 1);
  ASSERT_EQ(right, 2);
  for (const auto& v : r.rooms[0].polygon_m) EXPECT_LE(v.x(), 3.05 + 0.03);
  for (const auto& v : r.rooms[1].polygon_m) EXPECT_GE(v.x(), 3.25 - 0.03);
  EXPECT_EQ(r.labels.at(62, 27), 1);  // the segmentation's labels stay as they were
}

// A group of furniture 1.5 m x 1.5 m fills room 2's corner: its far cells lie 1.5 m (30 cells, 4-
// neighbour steps) from the room's free floor. The room grows through it to its walls (up to 2 m),
// and its polygon takes the corner in: the whole room, 3 m x 2 m (its cells' outline, pushed out by
// half a cell: 6.25 m2; 6.0 m2 when the growth stops at 1 m).
TEST(Rooms, ARoomGrowsThroughTheFurnitureInItsCornerToTheWalls) {
  TwoRooms t;
  for (int r = 1; r <= 30; ++r)
    for (int c = 95; c <= 124; ++c) t.nav.at(c, r) = Cell::kFurniture;
  rooms::RoomsResult r = rooms::find_rooms(t.nav, t.geometry);
  ASSERT_EQ(r.rooms.size(), 2u);
  rooms::fill_rooms(r, t.nav, {});
  const rooms::Room& right = r.rooms[static_cast<std::size_t>(rooms::room_at(r, {4.8, 1.8}) - 1)];
  EXPECT_TRUE(contains(right.polygon_m, t.geometry.center_of({124, 1})));
  EXPECT_NEAR(right.area_m2, 6.25, 0.01);
}

// One room 5 m x 3 m (a wall two cells thick all round) narrowed in its middle by furniture
// against both long walls: the segmentation splits it at the neck between them, 1.3 m wide.
// Neither end of that "door" has a jamb (a wall cell of a piece of at least 1 m2 within 0.2 m),
// and it is wider than a door (1.2 m): the two rooms are one. A pillar (a small piece of wall) at
// one end changes nothing; a wall stub at the ends, or a neck of 1.0 m, keeps the door.
TEST(Rooms, ANeckBetweenFurnitureIsNoDoor) {
  const auto room_with_neck = [](int furniture_rows, Cell stub) {
    Grid<Cell> nav(100, 60, Cell::kWall);
    for (int r = 2; r <= 57; ++r)
      for (int c = 2; c <= 97; ++c) nav.at(c, r) = Cell::kFree;
    for (int c = 45; c <= 54; ++c)
      for (int k = 0; k < furniture_rows; ++k) nav.at(c, 2 + k) = nav.at(c, 57 - k) = stub;
    return nav;
  };
  const GridGeometry geo({0.0, 0.0}, kCell, 100, 60);
  const auto split_and_join = [&](const Grid<Cell>& nav) {
    rooms::RoomsResult r = rooms::find_rooms(nav, geo);
    EXPECT_EQ(r.rooms.size(), 2u);
    EXPECT_EQ(r.doors.size(), 1u);
    rooms::join_furniture_necks(r, nav);
    return r;
  };
  const rooms::RoomsResult joined = split_and_join(room_with_neck(15, Cell::kFurniture));
  ASSERT_EQ(joined.rooms.size(), 1u);
  EXPECT_TRUE(joined.doors.empty());
  EXPECT_EQ(joined.rooms[0].id, 1);
  EXPECT_EQ(joined.rooms[0].cells, 96 * 56 - 2 * 10 * 15);
  for (int r = 20; r <= 40; ++r) EXPECT_EQ(joined.labels.at(50, r), 1);

  Grid<Cell> pillar = room_with_neck(15, Cell::kFurniture);
  for (int r = 12; r <= 16; ++r)
    for (int c = 47; c <= 52; ++c) pillar.at(c, r) = Cell::kWall;
  EXPECT_EQ(split_and_join(pillar).rooms.size(), 1u);

  EXPECT_EQ(split_and_join(room_with_neck(15, Cell::kWall)).rooms.size(), 2u);
  EXPECT_EQ(split_and_join(room_with_neck(19, Cell::kFurniture)).rooms.size(), 2u);
}

// A moving scanner walked through the door: M_r calls the whole passage free, and the
// segmentation gave room 1 all of it but the last column. Every passage cell is closed along the
// door's axis within the door's span (the jambs), also those beside a jamb, whose way to the far
// jamb is longer than half the door: the passage leaves both rooms, which end at their faces.
TEST(Rooms, ASeenPassageLeavesBothRoomsUpToItsJambs) {
  const TwoRooms t;
  rooms::RoomsResult r =
      split_passage(t, [](int c, int) { return c < 64 ? 1 : 2; }, {3.2, 0.65}, {3.2, 1.45});
  ASSERT_EQ(r.rooms.size(), 2u);
  rooms::fill_rooms(r, t.nav, {});
  ASSERT_EQ(rooms::room_at(r, {1.5, 1.0}), 1);
  ASSERT_EQ(rooms::room_at(r, {4.8, 1.0}), 2);
  for (const auto& v : r.rooms[0].polygon_m) EXPECT_LE(v.x(), 3.05 + 0.03);
  for (const auto& v : r.rooms[1].polygon_m) EXPECT_GE(v.x(), 3.25 - 0.03);
}

// A veil of mixed pixels (furniture, outside every room) stands in room 2 before the door. Lines
// from the lower jamb to it, 35-40 degrees off the wall, cross room 2's cells in front of the door
// and are no longer than the door: without a guide, those cells would leave the room and its
// polygon take a notch there. Only chords within 15 degrees of the passage's axis (the shortest
// closed chord through the door's middle, jamb to jamb) cut.
TEST(Rooms, AVeilBeforeTheDoorCutsNoNotchInFrontOfIt) {
  const TwoRooms t;
  rooms::RoomsResult r =
      split_passage(t, [](int c, int) { return c < 63 ? 1 : 2; }, {3.15, 0.65}, {3.15, 1.45});
  ASSERT_EQ(r.rooms.size(), 2u);
  Grid<Cell> layout = t.nav;
  for (int row = 22; row <= 26; ++row)
    for (int c = 72; c <= 75; ++c) {
      layout.at(c, row) = Cell::kFurniture;
      r.labels.at(c, row) = 0;
    }
  rooms::fill_rooms(r, layout, {});
  ASSERT_EQ(rooms::room_at(r, {4.8, 1.0}), 2);
  for (int row = 13; row <= 21; ++row)  // room 2's cells in front of the door stay in its polygon
    for (int c = 65; c <= 71; ++c)
      EXPECT_TRUE(contains(r.rooms[1].polygon_m, t.geometry.center_of({c, row})))
          << c << " " << row;
  for (const auto& v : r.rooms[1].polygon_m) EXPECT_GE(v.x(), 3.25 - 0.03);
}

// The passage of a door the scanner walked through, split between the rooms along a diagonal,
// leaves both rooms' cells (fill_rooms marks it in rooms.passages) and is no room space for the
// fit: the sides of the jambs are no faces of either room, and both fitted polygons end at their
// own face of the wall.
TEST(Rooms, FittedPolygonsEndAtTheirFacesAcrossASeenPassage) {
  const TwoRooms t;
  rooms::RoomsResult r =
      split_passage(t, [](int c, int row) { return 4 * (c - 61) < (row - 13) ? 1 : 2; },
                    {3.05, 0.65}, {3.25, 1.45});
  ASSERT_EQ(r.rooms.size(), 2u);
  rooms::fill_rooms(r, t.nav, {});
  ASSERT_EQ(r.passages.width, t.nav.width);
  EXPECT_TRUE(r.passages.at(62, 20));
  EXPECT_FALSE(r.passages.at(66, 20));
  EXPECT_EQ(rooms::fit_rooms_to_faces(r, t.nav, border::BorderParams{}), 2);
  for (const auto& v : r.rooms[0].polygon_m) EXPECT_LE(v.x(), 3.05 + 0.03);
  for (const auto& v : r.rooms[1].polygon_m) EXPECT_GE(v.x(), 3.25 - 0.03);
}

namespace {

// Two rooms 4 x 3 m side by side, the whole rotated by 30 degrees about the origin, 0.2 m walls
// with a 0.9 m door between them, rasterised at 5 cm (nav and layout alike). Room A
// has an unseen pocket 0.8 m long and 0.3 m deep along its far wall (unknown in both maps: the
// shadow of something in the room) and a crack one cell wide running 0.5 m into its outer wall
// (free in nav, as a doorway's edge or a window's gap can be).
struct RotatedRooms {
  static constexpr double kYaw = 30.0 * M_PI / 180.0;
  Eigen::Matrix2d rot = Eigen::Rotation2Dd(kYaw).toRotationMatrix();
  Polygon a = rectangle(rot * Eigen::Vector2d(2.0, 1.5), {4.0, 3.0}, kYaw);
  Polygon b = rectangle(rot * Eigen::Vector2d(6.2, 1.5), {4.0, 3.0}, kYaw);
  GridGeometry geometry{{-3.0, -1.0}, kCell, 220, 180};
  Grid<Cell> nav{220, 180, Cell::kUnknown};
  Grid<Cell> layout{220, 180, Cell::kUnknown};
  RotatedRooms() {
    const Polygon outer = rectangle(rot * Eigen::Vector2d(4.1, 1.5), {8.6, 3.4}, kYaw);
    const Polygon door = rectangle(rot * Eigen::Vector2d(4.1, 1.5), {0.3, 0.9}, kYaw);
    const Polygon pocket = rectangle(rot * Eigen::Vector2d(2.0, 2.85), {0.8, 0.3}, kYaw);
    const Polygon crack = rectangle(rot * Eigen::Vector2d(1.0, -0.2), {0.05, 0.5}, kYaw);
    // A cell is wall when the face crosses it (as the face's points mark it in a scan): the free
    // cells are those whose centre lies half a cell inside the face.
    const Polygon free_a = rectangle(rot * Eigen::Vector2d(2.0, 1.5), {3.95, 2.95}, kYaw);
    const Polygon free_b = rectangle(rot * Eigen::Vector2d(6.2, 1.5), {3.95, 2.95}, kYaw);
    for (int r = 0; r < nav.height; ++r)
      for (int c = 0; c < nav.width; ++c) {
        const Eigen::Vector2d p = geometry.center_of({c, r});
        Cell v = Cell::kUnknown;
        if (contains(outer, p)) v = Cell::kWall;
        if (contains(free_a, p) || contains(free_b, p) || contains(door, p)) v = Cell::kFree;
        if (contains(pocket, p)) v = Cell::kUnknown;
        layout.at(c, r) = v;
        nav.at(c, r) = contains(crack, p) ? Cell::kFree : v;
      }
  }
};

}  // namespace

// The cells' outline cuts the pocket out of room A; fitted to the wall faces, both polygons lie on
// the true walls (a cell's centre is within half a diagonal of the face: 0.035 m), the pocket is
// bridged along its wall and the crack leaves no spike.
TEST(Rooms, PolygonsFittedToTheWallFacesOfRotatedRooms) {
  const RotatedRooms t;
  rooms::RoomsResult r = rooms::find_rooms(t.nav, t.geometry);
  ASSERT_EQ(r.rooms.size(), 2u);
  rooms::fill_rooms(r, t.layout, {});
  const int a = rooms::room_at(r, t.rot * Eigen::Vector2d(2.0, 1.5));
  ASSERT_GE(a, 1);
  const Polygon outline_a = r.rooms[static_cast<std::size_t>(a - 1)].polygon_m;
  EXPECT_GT(boundary_hausdorff(outline_a, t.a), 0.2);  // the pocket's notch
  EXPECT_EQ(rooms::fit_rooms_to_faces(r, t.layout), 2);
  for (const auto& room : r.rooms) {
    const Polygon& truth =
        boundary_hausdorff(room.polygon_m, t.a) < boundary_hausdorff(room.polygon_m, t.b) ? t.a
                                                                                          : t.b;
    EXPECT_LT(boundary_hausdorff(room.polygon_m, truth), 0.06) << room.id;
    EXPECT_NEAR(room.area_m2, 12.0, 0.12) << room.id;
    EXPECT_NEAR(room.perimeter_m, 14.0, 0.2) << room.id;
    EXPECT_TRUE(is_simple(room.polygon_m)) << room.id;
  }
  // Each polygon holds its own room's centre and not the other's.
  const Polygon& p1 = r.rooms[0].polygon_m;
  const Polygon& p2 = r.rooms[1].polygon_m;
  EXPECT_NE(contains(p1, t.rot * Eigen::Vector2d(2.0, 1.5)),
            contains(p2, t.rot * Eigen::Vector2d(2.0, 1.5)));
  EXPECT_NE(contains(p1, t.rot * Eigen::Vector2d(6.2, 1.5)),
            contains(p2, t.rot * Eigen::Vector2d(6.2, 1.5)));
  // A layout of another size fits nothing.
  EXPECT_EQ(rooms::fit_rooms_to_faces(r, Grid<Cell>(3, 3, Cell::kWall)), 0);
}

// Along 0.8 m of the wall between the rooms, M_r saw only room B's face: its flood ran through
// the wall's body and A's face (free in M_r), and the navigation map never saw them (unknown). The
// body behind B's face becomes wall and A's polygon ends at A's face instead of taking the wall
// in. A cabinet in room A, whose sides M_r calls wall, has room A itself behind its sides and
// stays as it is.
TEST(Rooms, WallBodySeenFromTheOtherRoomOnlyIsWall) {
  RotatedRooms t;
  const auto local = [&](int c, int r) -> Eigen::Vector2d {
    return t.rot.transpose() * t.geometry.center_of({c, r});
  };
  for (int r = 0; r < t.nav.height; ++r)
    for (int c = 0; c < t.nav.width; ++c) {
      const Eigen::Vector2d l = local(c, r);
      if (l.x() > 3.975 && l.x() < 4.15 && l.y() > 0.1 && l.y() < 0.9)
        t.layout.at(c, r) = Cell::kFree, t.nav.at(c, r) = Cell::kUnknown;
      if (std::abs(l.x() - 1.0) < 0.2 && std::abs(l.y() - 1.0) < 0.2) {
        const bool side = std::abs(l.x() - 1.0) > 0.15 || std::abs(l.y() - 1.0) > 0.15;
        t.layout.at(c, r) = side ? Cell::kWall : Cell::kFurniture;
        t.nav.at(c, r) = Cell::kWall;
      }
    }
  rooms::RoomsResult plain = rooms::find_rooms(t.nav, t.geometry);
  rooms::RoomsResult marked = plain;
  ASSERT_EQ(plain.rooms.size(), 2u);
  const int a = rooms::room_at(plain, t.rot * Eigen::Vector2d(2.0, 1.5));
  ASSERT_GE(a, 1);
  const Grid<Cell> walls = rooms::mark_wall_bodies(t.layout, t.nav, plain, 0.3);
  int changed = 0;
  for (int r = 0; r < t.nav.height; ++r)
    for (int c = 0; c < t.nav.width; ++c) {
      if (walls.at(c, r) == t.layout.at(c, r)) continue;
      ++changed;
      EXPECT_EQ(walls.at(c, r), Cell::kWall);
      const Eigen::Vector2d l = local(c, r);  // only in the stretch of the wall
      EXPECT_TRUE(l.x() > 3.95 && l.x() < 4.2 && l.y() > 0.05 && l.y() < 0.95) << l.transpose();
    }
  EXPECT_GT(changed, 30);  // about 3 cells deep along 16 cells
  rooms::fill_rooms(plain, t.layout, {});
  rooms::fit_rooms_to_faces(plain, t.layout);
  rooms::fill_rooms(marked, walls, {});
  rooms::fit_rooms_to_faces(marked, walls);
  const auto& pa = plain.rooms[static_cast<std::size_t>(a - 1)].polygon_m;
  const auto& ma = marked.rooms[static_cast<std::size_t>(a - 1)].polygon_m;
  EXPECT_GT(boundary_hausdorff(pa, t.a), 0.12);  // the wall's body taken in
  EXPECT_LT(boundary_hausdorff(ma, t.a), 0.06);
  EXPECT_NEAR(std::abs(signed_area(ma)), 12.0, 0.12);
  // Grids of another size leave M_r as it is.
  EXPECT_EQ(rooms::mark_wall_bodies(t.layout, Grid<Cell>(3, 3, Cell::kWall), plain, 0.3).data,
            t.layout.data);
}

// An object whose centre lies in the wall between two rooms (in no polygon, within 0.3 m of one)
// is a piece of wall; one inside a room, one far outside every room (seen through a window) and a
// pillar (not furniture) stay; with one room nothing is dropped.
TEST(Rooms, ObjectsInAWallAreDroppedOthersStay) {
  const TwoRooms t;
  const auto r = rooms::find_rooms(t.nav, t.geometry);
  ASSERT_EQ(r.rooms.size(), 2u);
  objects::ObjectsResult objs;
  const auto add = [&](int id, Eigen::Vector2d c, ObjectKind kind = ObjectKind::kFurniture) {
    objects::FurnitureObject o;
    o.id = id;
    o.kind = kind;
    o.box.center_m = c;
    objs.objects.push_back(o);
  };
  add(1, {1.5, 1.0});                        // in room 1
  add(2, {3.15, 0.3});                       // in the wall between the rooms, below the door
  add(3, {3.15, 2.5});                       // beyond the outer wall, 0.4 m from room 2's polygon
  add(4, {3.15, 1.9}, ObjectKind::kPillar);  // a pillar in the wall: kept
  add(5, {1.5, -0.15});                      // in the outer wall, 0.2 m below room 1
  EXPECT_EQ(rooms::wall_piece_objects(objs, r), (std::vector<int>{2, 5}));
  rooms::RoomsResult one = r;
  one.rooms.resize(1);
  EXPECT_TRUE(rooms::wall_piece_objects(objs, one).empty());
  rooms::RoomsParams p;
  p.wall_piece_reach_m = 0.05;
  EXPECT_TRUE(rooms::wall_piece_objects(objs, r, p).empty());
}

TEST(RoomsFormats, GeojsonRoundTripAndGraph) {
  const TwoRooms t;
  const auto r = rooms::find_rooms(t.nav, t.geometry);
  const auto dir = test::scratch_dir();
  formats::write_rooms_geojson(dir / "rooms.geojson", r);
  const formats::RoomsFile f = formats::read_rooms_geojson(dir / "rooms.geojson");
  ASSERT_EQ(f.rooms.size(), 2u);
  ASSERT_EQ(f.doors.size(), 1u);
  EXPECT_EQ(f.rooms[1].id, 2);
  EXPECT_EQ(f.rooms[0].polygon.size(), r.rooms[0].polygon_m.size());
  EXPECT_EQ(f.doors[0].a, 1);
  EXPECT_EQ(f.doors[0].b, 2);
  EXPECT_NEAR(f.doors[0].width_m, (r.doors[0].end1_m - r.doors[0].end0_m).norm(), 1e-9);
  const auto g = formats::rooms_graph_json(r, {7, 8}, {2, 0});
  EXPECT_EQ(g["count"], 2);
  EXPECT_EQ(g["rooms"][1]["objects"], nlohmann::json::array({7}));
  EXPECT_EQ(g["rooms"][0]["neighbours"], nlohmann::json::array({2}));
  EXPECT_EQ(g["doors"][0]["rooms"], nlohmann::json::array({1, 2}));
  // A malformed door names the file and the key.
  test::write_text(dir / "bad.geojson",
                   R"({"type": "FeatureCollection", "features": [{"type": "Feature",
      "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 0]]},
      "properties": {"kind": "door", "rooms": [1]}}]})");
  try {
    formats::read_rooms_geojson(dir / "bad.geojson");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("features[0].properties.rooms"), std::string::npos);
  }
}
