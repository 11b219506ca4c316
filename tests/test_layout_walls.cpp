// M_r's walls between rooms and its flood on a floor (issue 16): the inside of a wall between two
// rooms, a wall with one face in the furniture band, the rooms of a floor scanned without
// positions, the unseen body of a shelf taller than the scanner.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "indoormap/layout/layout.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "indoormap/sim/scene.hpp"
#include "indoormap/sim/simulate.hpp"
#include "layout_fixtures.hpp"

// Issue 16: two rooms with a wall 0.4 m thick between them (faces seen, inside not) and a
// pillar in one room, 0.1 m cells. The wall's inside becomes wall; the pillar's inside (0.2 m)
// is left as it is (unknown); with wall_max_thickness_m 0 the wall's inside stays unknown.
TEST(Layout, InsideOfAWallBetweenRoomsIsWallAPillarsIsLeft) {
  std::vector<std::string> rows(14, "#..........#..#........#");
  rows.front() = rows.back() = std::string(24, '#');
  for (int r = 5; r <= 8; ++r) rows[r].replace(3, 4, r == 5 || r == 8 ? "####" : "#..#");
  const auto walls = parse(rows);
  const Grid<std::uint8_t> furn(walls.width, walls.height, 0);
  const GridGeometry geo({0.0, 0.0}, 0.1, walls.width, walls.height);
  const std::vector<Eigen::Vector2d> scanners{{0.85, 0.25}, {1.85, 0.65}};
  LayoutParams on;
  ASSERT_EQ(on.wall_max_thickness_m, 0.5);  // the default
  const LayoutResult r = build_layout(walls, furn, geo, scanners, on);
  for (int row = 1; row <= 12; ++row)
    for (int col = 12; col <= 13; ++col)
      EXPECT_EQ(r.layout.at(col, row), Cell::kWall) << col << "," << row;
  for (int row = 6; row <= 7; ++row)  // grid rows of the pillar's inside (picture rows 6-7)
    for (int col = 4; col <= 5; ++col) EXPECT_NE(r.layout.at(col, row), Cell::kWall);
  EXPECT_EQ(r.layout.at(8, 2), Cell::kFree);
  EXPECT_EQ(r.layout.at(18, 6), Cell::kFree);
  LayoutParams off;
  off.wall_max_thickness_m = 0.0;
  const LayoutResult o = build_layout(walls, furn, geo, scanners, off);
  for (int row = 1; row <= 12; ++row)
    for (int col = 12; col <= 13; ++col) EXPECT_EQ(o.layout.at(col, row), Cell::kUnknown);
}

// A slab seen from both sides, its wall band on one face only: 'F' furniture band, 'W' wall
// band, '.' seen free, ' ' unseen; 0.1 m cells, walls at most 0.5 m thick. Only the first block
// is a wall: a face in each band, 0.4 m from seen floor to seen floor. The second is a wall with
// both faces in M_w and a cabinet against it (two wall faces in the run), the third a shelf 0.4 m
// deep against a wall seen from the far side (0.7 m), the fourth a table (no wall face).
TEST(WallSlabs, OneFaceInEachBandIsAWall) {
  // Rows of unseen cells keep the blocks apart (no line ends on seen floor between them).
  const std::vector<std::string> rows = {"..F  W.....", "..F  W.....", "..F  W.....", "           ",
                                         "..W  WF....", "..W  WF....", "..W  WF....", "           ",
                                         "..FFFF  W..", "..FFFF  W..", "..FFFF  W..", "           ",
                                         "..FFF......", "..FFF......", "..FFF......"};
  const auto walls = parse(rows, 'W'), furn = parse(rows, 'F'), seen = parse(rows, '.');
  const auto slabs = wall_slabs(walls, furn, seen, 0.1, 0.5);
  std::vector<std::string> expected(rows.size(), "...........");
  for (int r = 0; r <= 2; ++r) expected[r] = "..####.....";
  EXPECT_EQ(render01(slabs), render01(parse(expected)));
  // 0.3 m: the first block's run (0.4 m) is too long.
  const auto thin = wall_slabs(walls, furn, seen, 0.1, 0.3);
  EXPECT_EQ(render01(thin), render01(parse(std::vector<std::string>(rows.size(), "..........."))));
}

// The inside of a wall against the gap between the two faces of a room's corner: 'W' wall, 'o'
// open (flooded or seen), 'F' furniture band, ' ' neither; 0.1 m cells, walls at most 0.5 m
// thick; rows six apart, so only rows hold runs. First row: a wall between two rooms, open past
// its faces. Second: a line through a room's corner hidden behind a shelf, from the face of one
// wall to the face of the other; past each face lies its wall's inside, which is filled, the
// corner gap is not (it was, and the room's polygon ran 0.2 m inside the faces). Third: a
// wall with a shelf against each face, its bodies unseen: neither face has open space past it,
// nor a second wall's inside; filled. Without `open` every gap is filled, as before.
TEST(WallInside, TheFacesOfARoomsCornerHoldNoWallBetweenThem) {
  const std::vector<std::string> rows = {
      "ooW   Woooooooooooooo", "                     ", "                     ",
      "                     ", "                     ", "                     ",
      "oW  W   W  Wooooooooo", "                     ", "                     ",
      "                     ", "                     ", "                     ",
      "oF     W   W     Fooo"};
  const auto walls = parse(rows, 'W'), furn = parse(rows, 'F'), open = parse(rows, 'o');
  const auto inside = wall_inside(walls, 0.1, 0.5, &open, &furn);
  std::vector<std::string> expected(rows.size(), ".....................");
  expected[0] = "...###...............";
  expected[6] = "..##.....##..........";
  expected[12] = "........###..........";
  EXPECT_EQ(render01(inside), render01(parse(expected)));
  const auto all = wall_inside(walls, 0.1, 0.5);
  expected[6] = "..##.###.##..........";
  EXPECT_EQ(render01(all), render01(parse(expected)));
}

// Two rooms, 0.1 m cells, and a wall 0.3 m thick between them whose left face only the
// furniture band holds (a mobile scanner's beams end below the wall band there): with the seen
// map it is wall in M_r from face to face, not a furniture strip along the left room.
TEST(Layout, AWallWithOneFaceInTheFurnitureBandIsWall) {
  std::vector<std::string> rows(14, "#..........F W..........#");
  rows.front() = rows.back() = std::string(25, '#');
  const auto walls = parse(rows, '#'), furn = parse(rows, 'F');
  auto wall_face = parse(rows, 'W');
  Grid<std::uint8_t> all_walls = walls;
  for (std::size_t i = 0; i < all_walls.size(); ++i) all_walls.data[i] |= wall_face.data[i];
  const auto seen = parse(rows, '.');
  const GridGeometry geo({0.0, 0.0}, 0.1, all_walls.width, all_walls.height);
  const std::vector<Eigen::Vector2d> scanners{{0.55, 0.65}, {1.95, 0.65}};
  const LayoutResult r = build_layout(all_walls, furn, geo, scanners, {}, nullptr, nullptr, &seen);
  for (int row = 1; row <= 12; ++row)
    for (int col = 11; col <= 13; ++col)
      EXPECT_EQ(r.layout.at(col, row), Cell::kWall) << col << "," << row;
  EXPECT_EQ(r.layout.at(5, 6), Cell::kFree);
  EXPECT_EQ(r.layout.at(18, 6), Cell::kFree);
  LayoutParams off;
  off.wall_max_thickness_m = 0.0;
  const LayoutResult o = build_layout(all_walls, furn, geo, scanners, off, nullptr, nullptr, &seen);
  EXPECT_EQ(o.layout.at(11, 6), Cell::kFurniture);
}

// Two rooms 2 m x 1.2 m apart behind a closed wall, 0.1 m cells, scanned without positions: the
// farthest free cell seeds one room, the floor seen in the other seeds it too (a floor mapped
// without its trajectory). A piece of seen floor under 2 m2 (the right room's, cut down) does not.
TEST(Layout, WithoutPositionsEveryRoomWithSeenFloorIsFlooded) {
  std::vector<std::string> rows(14, "#...................#....................#");
  rows.front() = rows.back() = std::string(42, '#');
  const auto walls = parse(rows);
  const Grid<std::uint8_t> furn(walls.width, walls.height, 0);
  Grid<std::uint8_t> seen(walls.width, walls.height, 0);
  for (std::size_t i = 0; i < seen.size(); ++i) seen.data[i] = !walls.data[i];
  const GridGeometry geo({0.0, 0.0}, 0.1, walls.width, walls.height);
  const LayoutResult r = build_layout(walls, furn, geo, {}, {}, nullptr, nullptr, &seen);
  EXPECT_TRUE(r.seeds_estimated);
  EXPECT_EQ(r.layout.at(10, 6), Cell::kFree);
  EXPECT_EQ(r.layout.at(30, 6), Cell::kFree);
  // Seen floor in the right room: 19 cells (0.19 m2), under 2 m2.
  for (int col = 21; col < 41; ++col)
    for (int row = 1; row < 13; ++row) seen.at(col, row) = row == 6 && col < 40;
  const LayoutResult s = build_layout(walls, furn, geo, {}, {}, nullptr, nullptr, &seen);
  EXPECT_EQ(s.layout.at(10, 6) == Cell::kFree, s.layout.at(30, 6) != Cell::kFree);
}

namespace {

// p turned by yaw_deg about the origin (counter-clockwise).
Eigen::Vector2d turned(const Eigen::Vector2d& p, double yaw_deg) {
  return Eigen::Rotation2Dd(yaw_deg * M_PI / 180.0) * p;
}

// A 4 m x 3 m room (walls 0.2 m, ceiling 2.5 m) scanned from (1.0, 1.0, 1.2) at 0.5 degrees,
// with a shelf 1.8 m tall, 0.4 m deep and 1.2 m long against the east wall (x 3.58 - 3.98,
// y 1.3 - 2.5) and a cabinet 1.8 m tall standing free 1 m from the walls, whose shadow hides the
// shelf's face north of y = 2; no noise, no tilt, no mixed pixels. The scanner sees the shelf's
// face south of that and its south end, never its north end nor its top. yaw_deg turns the
// whole scene about the origin; without `positions` the cloud carries none.
layout::MapResult room_with_a_tall_shelf(double hidden_body_max_depth_m,
                                         double sparse_floor_fill = 0.6, bool positions = true,
                                         double yaw_deg = 0.0) {
  sim::Scene s;
  sim::Room room;
  room.name = "room";
  for (const Eigen::Vector2d& corner :
       {Eigen::Vector2d(0, 0), Eigen::Vector2d(4, 0), Eigen::Vector2d(4, 3), Eigen::Vector2d(0, 3)})
    room.polygon.push_back(turned(corner, yaw_deg));
  room.wall_thickness_m = 0.2;
  room.ceiling.height_m = 2.5;
  s.rooms.push_back(room);
  sim::ScannerPose pose;
  const Eigen::Vector2d eye = turned({1.0, 1.0}, yaw_deg);
  pose.position_m = {eye.x(), eye.y(), 1.2};
  s.scanners.push_back(pose);
  s.scanner.range_sigma_m = 0;
  s.scanner.mixed_pixel_probability = 0;
  s.scanner.azimuth_step_deg = 0.5;
  s.scanner.elevation_step_deg = 0.5;
  for (const auto& [c, size] : {std::pair{Eigen::Vector2d(3.78, 1.9), Eigen::Vector2d(0.4, 1.2)},
                                std::pair{Eigen::Vector2d(2.6, 1.95), Eigen::Vector2d(0.3, 0.3)}}) {
    sim::Furniture f;
    f.type = sim::FurnitureType::kShelf;
    f.center_m = turned(c, yaw_deg);
    f.size_m = size;
    f.yaw_deg = yaw_deg;
    f.height_m = 1.8;
    s.furniture.push_back(f);
  }
  const sim::SimResult r = sim::simulate(sim::normalised(s));
  layout::MapParams p;
  p.layout.hidden_body_max_depth_m = hidden_body_max_depth_m;
  p.layout.sparse_floor_fill = sparse_floor_fill;
  return layout::make_map(
      PointCloud{r.points, positions ? r.scanner_positions_m : std::vector<Eigen::Vector3d>{}, {}},
      p);
}

Cell cell_at(const layout::MapResult& m, double x, double y) {
  return m.layout.layout.at(m.geometry.cell_of({x, y}));
}

// How many of the sampled cells of the shelf's body (x 3.65 - 3.9, y 1.4 - 1.85 in the scene
// before its turn by yaw_deg) are `kind`, and how many were sampled.
std::pair<int, int> body_cells(const layout::MapResult& m, Cell kind, double yaw_deg = 0.0) {
  int of_kind = 0, cells = 0;
  for (double y = 1.4; y <= 1.85; y += 0.05)
    for (double x = 3.65; x <= 3.9; x += 0.05, ++cells)
      of_kind += m.layout.layout.at(m.geometry.cell_of(turned({x, y}, yaw_deg))) == kind;
  return {of_kind, cells};
}

}  // namespace

// A dense scan sees a shelf taller than the scanner as its front face only. The paper's flood ran
// in through the cabinet's shadow, round the unseen part of the face, and called the shelf's body
// free; the body between the seen face and the wall behind it, whose floor the scan never saw, is
// the shelf's (a pocket: furniture). The cabinet's shadow, farther from the walls, stays as it
// was: the scan cannot tell that cabinet's depth.
TEST(Layout, TheUnseenBodyOfATallShelfAgainstAWallIsFurniture) {
  const layout::MapResult on = room_with_a_tall_shelf(0.7);
  const layout::MapResult off = room_with_a_tall_shelf(0.0);
  ASSERT_EQ(on.geometry, off.geometry);
  const auto [body_on, cells] = body_cells(on, Cell::kFurniture);
  EXPECT_EQ(body_on, cells);
  EXPECT_LT(body_cells(off, Cell::kFurniture).first, cells / 2);  // the leak the rule closes
  // The cabinet's shadow is not made furniture.
  for (const auto& [x, y] : {std::pair{3.1, 2.3}, std::pair{3.3, 2.6}}) {
    EXPECT_EQ(cell_at(on, x, y), cell_at(off, x, y));
    EXPECT_NE(cell_at(on, x, y), Cell::kFurniture);
  }
  // layout.sparse_floor_fill sets what a dense scan is, for the flood and the objects' stray test
  // (MapResult::dense_scan) alike.
  EXPECT_TRUE(on.dense_scan);
  EXPECT_FALSE(on.free_from_evidence);
  const layout::MapResult strict = room_with_a_tall_shelf(0.7, 0.99);
  EXPECT_LT(strict.floor_fill, 0.99);
  EXPECT_FALSE(strict.dense_scan);
  EXPECT_TRUE(strict.free_from_evidence);
}

// Without the scanner's position the layout cannot tell which tops were seen: every furniture
// cell counts as one whose top no scanner saw, and the shelf's body is furniture as above. The
// cabinet standing free keeps its shadow floodable.
TEST(Layout, WithoutPositionsTheUnseenBodyOfAShelfAgainstAWallIsFurnitureToo) {
  const layout::MapResult on = room_with_a_tall_shelf(0.7, 0.6, false);
  const layout::MapResult off = room_with_a_tall_shelf(0.0, 0.6, false);
  ASSERT_EQ(on.geometry, off.geometry);
  ASSERT_TRUE(on.dense_scan);
  const auto [body_on, cells] = body_cells(on, Cell::kFurniture);
  EXPECT_EQ(body_on, cells);
  EXPECT_LT(body_cells(off, Cell::kFurniture).first, cells / 2);
  for (const auto& [x, y] : {std::pair{3.1, 2.3}, std::pair{3.3, 2.6}})
    EXPECT_NE(cell_at(on, x, y), Cell::kFurniture);
}

// The same room turned by 30 degrees, without positions: the lines from the shelf's face cells
// to their nearest wall cells are staircases that diverge, and the flood ran in between them.
// Each line counts three cells wide: no cell of the body is free.
TEST(Layout, TheUnseenBodyOfATurnedShelfLeavesNoGapsBetweenItsLines) {
  const layout::MapResult m = room_with_a_tall_shelf(0.7, 0.6, false, 30.0);
  ASSERT_TRUE(m.dense_scan);
  EXPECT_EQ(body_cells(m, Cell::kFree, 30.0).first, 0);
  const auto [furniture, cells] = body_cells(m, Cell::kFurniture, 30.0);
  EXPECT_GE(furniture, cells * 9 / 10);
}

// The veils of mixed pixels a door jamb throws into a doorway: columns of a few points at
// unrelated heights over floor the scan saw, which the navigation map leaves free (its scatter
// rule) and M_f took for furniture. 'F' furniture band, 'W' wall band too, 'n' a furniture-band
// cell the navigation map calls occupied, '.' seen floor; cells of 'F' over seen floor that the
// navigation map calls free leave M_f, the others stay (a cabinet's face: occupied in the
// navigation map; a cell whose floor was not seen, ' ').
TEST(Layout, VeilsOverSeenFloorThatTheNavigationMapLeavesFreeAreNoFurniture) {
  const std::vector<std::string> rows = {"..F..nn..", ".F...nn.W", "..F. nn.W"};
  const auto furn_only = parse(rows, 'F'), nav_obstacle = parse(rows, 'n'), wall = parse(rows, 'W'),
             unseen = parse(rows, ' ');
  Grid<std::uint8_t> furniture = furn_only, observed(furn_only.width, furn_only.height, 1);
  Grid<Cell> nav(furn_only.width, furn_only.height, Cell::kFree);
  for (std::size_t i = 0; i < furniture.size(); ++i) {
    furniture.data[i] |= nav_obstacle.data[i] | wall.data[i];
    if (nav_obstacle.data[i] || wall.data[i]) nav.data[i] = Cell::kWall;
    if (unseen.data[i]) observed.data[i] = 0;
  }
  // The column over the unseen cell is a veil too, but the scan did not see the floor under it.
  furniture.at(4, 0) = 1;
  std::int64_t dropped = -1;
  const auto out = without_veils(furniture, wall, nav, observed, &dropped);
  EXPECT_EQ(dropped, 3);
  const std::vector<std::string> expected = {".....##..", ".....##.#", "....###.#"};
  EXPECT_EQ(render01(out), render01(parse(expected)));
}
