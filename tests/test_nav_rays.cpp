// The navigation map's rays over low obstacles (docs/pipeline.md, "Beams over low obstacles"), on
// small hand-built voxel grids.
#include <gtest/gtest.h>

#include <vector>

#include "indoormap/layout/nav_map.hpp"
#include "nav_map_fixtures.hpp"

using namespace indoormap;
using namespace indoormap::layout;
using test::at;
using test::put;
using test::room;

// A low box (top 0.6 m, x 1.5-1.8 m, 1.8 m wide: no shadow of a free-standing obstacle) seen
// from a scanner at 1.2 m, x 0.55 m; the far wall at x 3.9 m. The beams that saw the wall passed
// over the box's far edge along a line that reaches 0.3 m above the floor 2.3 m from the scanner
// and the floor at 3.05 m: behind the box the floor is free from there on, unknown nearer (a thing
// up to 0.5 m high could hide at x 2.0 m). The box stays occupied. nav.over_low_max_m 0: unknown.
TEST(NavMap, RaysGoOverALowBoxToTheFloorFarBehindIt) {
  auto g = room();
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 10; ++x) put(g, x, y, 0);
    for (int z = 0; z < 25; ++z) put(g, 39, y, z);
    for (int x = 15; x < 18; ++x)
      if (y >= 1 && y <= 18)
        for (int z = 1; z <= 5; ++z) put(g, x, y, z);
  }
  const std::vector<Eigen::Vector3d> scanner{{0.55, 1.0, 1.2}};
  const NavResult r = build_nav_map(g, 0.05, scanner, NavParams{});
  EXPECT_EQ(at(r, 16, 10), Cell::kWall) << "the box";
  EXPECT_EQ(at(r, 20, 10), Cell::kUnknown) << "just behind it: the line is 0.5 m high";
  EXPECT_EQ(at(r, 27, 10), Cell::kFree) << "where the line is 0.17 m high";
  EXPECT_EQ(at(r, 35, 10), Cell::kFree) << "beyond the line's foot";
  NavParams off;
  off.over_low_max_m = 0.0;
  EXPECT_EQ(at(build_nav_map(g, 0.05, scanner, off), 27, 10), Cell::kUnknown);
  NavParams low_scanner;  // a box as high as the position stops its rays
  EXPECT_EQ(at(build_nav_map(g, 0.05, {{0.55, 1.0, 0.6}}, low_scanner), 35, 10), Cell::kUnknown);
}

// A counter 1.3 m high (taller than the body band, robot.height_m 1.2 m), 2.1 m deep, seen from
// a scanner at 1.6 m: its face (x 1.0 m) holds points from the floor up, its top plate (x 1.0 -
// 3.0 m) lies above the band and hides the inside, which holds no body-band point. Beyond the
// plate's far edge the line over it stays above 1.3 m: the floor there (x 3.1 - 3.8 m) is hidden.
// Taken from the face alone, the line would reach the floor at x 3.6 m.
TEST(NavMap, ACounterTallerThanTheBandHidesTheFloorBehindIt) {
  auto g = room();
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 10; ++x) put(g, x, y, 0);
    for (int z = 0; z < 25; ++z) put(g, 39, y, z);
    for (int z = 1; z <= 13; ++z) put(g, 10, y, z);
    for (int x = 10; x <= 30; ++x) put(g, x, y, 13);
  }
  const NavResult r = build_nav_map(g, 0.05, {{0.55, 1.0, 1.6}}, NavParams{});
  EXPECT_EQ(at(r, 10, 10), Cell::kWall) << "the face";
  EXPECT_EQ(at(r, 20, 10), Cell::kUnknown) << "inside";
  EXPECT_EQ(at(r, 36, 10), Cell::kUnknown) << "behind the counter";
}
