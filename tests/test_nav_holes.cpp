// The navigation map's floor holes (docs/pipeline.md, "Floor holes"): the barrier of the layout's
// wall band (not a doorway's lintel), and points below the floor under a seen floor; small
// hand-built voxel grids of 0.1 m (nav_map_fixtures.hpp).
#include <gtest/gtest.h>

#include <vector>

#include "indoormap/layout/nav_map.hpp"
#include "nav_map_fixtures.hpp"

using namespace indoormap;
using namespace indoormap::layout;
using test::at;
using test::put;
using test::room;

namespace {

// An empty grid of g's cells: build_nav_map's `walls` (the layout's wall band cells, M_w).
Grid<std::uint8_t> cells_of(const cloud::VoxelGrid& g) {
  return Grid<std::uint8_t>(static_cast<int>(g.nx), static_cast<int>(g.ny), 0);
}

}  // namespace

// A room walled at x 0, y 0 and y 19; its east wall (x 39, the map's edge) seen only above 1.3 m
// at y 5-9, where a cabinet hid its foot. A gap between the floor's rings (x 35-37) and, at y
// 5-9, the ring along the wall too, are unseen: through the wall's foot they reach the map's edge
// and are no hole. With the wall band's cells as the holes' barrier (the layout's M_w) the gap is
// a hole, mostly bordered by seen floor: free (no position known).
TEST(NavMap, RingGapBesideAWallWhoseFootWasHiddenIsAHole) {
  cloud::VoxelGrid g = room();
  Grid<std::uint8_t> walls = cells_of(g);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) {
      const bool wall = x == 0 || y == 0 || y == 19 || x == 39;
      if (wall) {
        const bool hidden_foot = x == 39 && y >= 5 && y <= 9;
        for (int z = hidden_foot ? 13 : 0; z < 25; ++z) put(g, x, y, z);
        walls.at(x, y) = 1;
      } else if (x < 35 || (x == 38 && (y < 5 || y > 9))) {
        put(g, x, y, 0);  // the floor seen
      }
    }
  const NavResult plain = build_nav_map(g, 0.05, {}, NavParams{});
  EXPECT_EQ(at(plain, 36, 12), Cell::kUnknown) << "joined to the map's edge";
  const NavResult r = build_nav_map(g, 0.05, {}, NavParams{}, false, &walls);
  EXPECT_EQ(at(r, 36, 12), Cell::kFree);
  EXPECT_EQ(at(r, 38, 7), Cell::kFree) << "the ring's gap by the hidden foot";
  EXPECT_EQ(at(r, 39, 7), Cell::kUnknown) << "the wall's foot itself";
}

// An upper storey's grid begins below its floor, between the lower storey's ceilings: a taller
// room's ceiling shows 0.8 m below this floor (x 20-30, y 3-16), where this floor was seen but
// for a ring gap (x 24-25). Points below a seen floor are no hole in it: the gap is free. A shaft
// (no floor over its points below) stays unknown.
TEST(NavMap, PointsBelowASeenFloorAreNoHoleInIt) {
  cloud::VoxelGrid g = room();
  g.origin_m = {0.0, 0.0, -1.0};  // layer 10 holds z 0.0-0.1: the floor
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) {
      if (x == 0 || x == 39 || y == 0 || y == 19) {
        for (int z = 10; z < 25; ++z) put(g, x, y, z);
        continue;
      }
      const bool ceiling_below = x >= 20 && x <= 30 && y >= 3 && y <= 16;
      const bool shaft = x >= 5 && x <= 7 && y >= 5 && y <= 7;
      if (ceiling_below || shaft) put(g, x, y, 2);
      if (!shaft && !(x >= 24 && x <= 25 && y >= 3 && y <= 16)) put(g, x, y, 10);
    }
  const NavResult r = build_nav_map(g, 0.05, {}, NavParams{});
  EXPECT_EQ(at(r, 24, 9), Cell::kFree) << "the ring gap over the lower ceiling";
  EXPECT_EQ(at(r, 6, 6), Cell::kUnknown) << "the shaft";
}

// Two rooms, a wall at x 2.0 m with a doorway (y 8-11) under a lintel from 2.0 m; the floor is
// seen everywhere but in the doorway. The wall band (M_w) holds the lintel too, but a lintel is
// open below door height: no barrier. The doorway is a hole of the floor, free, the door open.
TEST(NavMap, ADoorwaysLintelIsNoBarrierOfTheHoles) {
  cloud::VoxelGrid g = room();
  Grid<std::uint8_t> walls = cells_of(g);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) {
      const bool door = y >= 8 && y <= 11;
      if (x == 0 || x == 39 || y == 0 || y == 19 || x == 20) {
        for (int z = x == 20 && door ? 20 : 0; z < 25; ++z) put(g, x, y, z);
        walls.at(x, y) = 1;
      } else if (!(door && x >= 19 && x <= 21)) {
        put(g, x, y, 0);
      }
    }
  const NavResult r = build_nav_map(g, 0.05, {}, NavParams{}, false, &walls);
  EXPECT_EQ(at(r, 20, 9), Cell::kFree);
  EXPECT_EQ(at(r, 19, 10), Cell::kFree);
}
