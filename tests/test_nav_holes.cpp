// The navigation map's floor holes (docs/pipeline.md, "Floor holes"): the barrier of the layout's
// wall and furniture bands, and points below the floor under a seen floor; small hand-built
// voxel grids of 0.1 m (nav_map_fixtures.hpp).
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

// The layout bands' cells for build_nav_map's `above`.
Grid<std::uint8_t> above_of(const cloud::VoxelGrid& g) {
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
  Grid<std::uint8_t> above = above_of(g);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) {
      const bool wall = x == 0 || y == 0 || y == 19 || x == 39;
      if (wall) {
        const bool hidden_foot = x == 39 && y >= 5 && y <= 9;
        for (int z = hidden_foot ? 13 : 0; z < 25; ++z) put(g, x, y, z);
        above.at(x, y) = kAboveWall;
      } else if (x < 35 || (x == 38 && (y < 5 || y > 9))) {
        put(g, x, y, 0);  // the floor seen
      }
    }
  const NavResult plain = build_nav_map(g, 0.05, {}, NavParams{});
  EXPECT_EQ(at(plain, 36, 12), Cell::kUnknown) << "joined to the map's edge";
  const NavResult r = build_nav_map(g, 0.05, {}, NavParams{}, false, &above);
  EXPECT_EQ(at(r, 36, 12), Cell::kFree);
  EXPECT_EQ(at(r, 38, 7), Cell::kFree) << "the ring's gap by the hidden foot";
  EXPECT_EQ(at(r, 39, 7), Cell::kUnknown) << "the wall's foot itself";
}

// A pocket (x 10-12, y 5-14) with seen floor all round, whose columns hold points at 1.5 m only
// (above the body band: no obstacle to the robot, in the furniture band: something stands
// there, its lower part unseen). With a position known (rays cross the pockets beside furniture)
// it is a hole; without, the furniture band's cells bound the holes and it stays unknown.
TEST(NavMap, WithoutPositionsAPocketUnderFurnitureIsNoHole) {
  cloud::VoxelGrid g = room();
  Grid<std::uint8_t> above = above_of(g);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) {
      if (x == 0 || x == 39 || y == 0 || y == 19) {
        for (int z = 0; z < 25; ++z) put(g, x, y, z);
        above.at(x, y) = kAboveWall;
      } else if (x >= 10 && x <= 12 && y >= 5 && y <= 14) {
        put(g, x, y, 15);
        above.at(x, y) = kAboveFurniture;
      } else {
        put(g, x, y, 0);
      }
    }
  EXPECT_EQ(at(build_nav_map(g, 0.05, {}, NavParams{}, false, &above), 11, 9), Cell::kUnknown);
  EXPECT_EQ(at(build_nav_map(g, 0.05, {}, NavParams{}), 11, 9), Cell::kFree) << "no bands given";
  // A position far from the pocket, behind a wall, casts no ray over it: the hole rule alone.
  cloud::VoxelGrid walled = g;
  for (int y = 1; y < 19; ++y)
    for (int z = 0; z < 25; ++z) put(walled, 30, y, z);
  const NavResult with_rays =
      build_nav_map(walled, 0.05, {{3.45, 1.0, 1.2}}, NavParams{}, false, &above);
  EXPECT_EQ(at(with_rays, 11, 9), Cell::kFree);
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
