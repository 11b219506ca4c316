// The navigation map (body band, speck rule, free space from evidence) and the storeys, on small
// hand-built voxel grids.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "indoormap/core/errors.hpp"
#include "indoormap/layout/nav_map.hpp"
#include "indoormap/layout/nearest_origin.hpp"
#include "indoormap/layout/storeys.hpp"
#include "nav_map_fixtures.hpp"

using namespace indoormap;
using namespace indoormap::layout;

using test::at;
using test::put;
using test::room;
using test::room_with_seen_floor;

// A wall at x = 2.0 m with a door (rows 8-11) under a lintel at 2.0 m; left of the wall the
// floor is seen; a cord speck, a table leg and a sparse table top in the left room.
TEST(NavMap, BodyBandSpecksAndDoorUnderLintel) {
  auto g = room();
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) put(g, x, y, 0);  // floor, left room only
  for (int y = 0; y < 20; ++y)
    for (int z = 0; z < 30; ++z)
      if (y < 8 || y > 11 || z >= 20) put(g, 20, y, z);  // wall with a door below 2.0 m
  put(g, 5, 5, 8, 1);                                    // a cord's speck at 0.85 m
  for (int z = 1; z < 7; ++z) put(g, 10, 15, z, 1);      // a table leg, one point per voxel
  for (int x = 14; x < 17; ++x)
    for (int y = 2; y < 5; ++y) put(g, x, y, 7, 1);  // a sparse table top at 0.75 m
  NavParams p;
  const NavResult none = build_nav_map(g, 0.05, {}, p);
  EXPECT_EQ(at(none, 5, 5), Cell::kFree) << "the speck is no obstacle";
  EXPECT_EQ(at(none, 10, 15), Cell::kWall) << "the leg stands over 0.6 m";
  EXPECT_EQ(at(none, 15, 3), Cell::kWall) << "the table top is a surface";
  EXPECT_EQ(at(none, 14, 2), Cell::kWall);
  EXPECT_EQ(at(none, 20, 3), Cell::kWall);
  EXPECT_EQ(at(none, 20, 9), Cell::kUnknown) << "door: nothing in the body band, floor unseen";
  EXPECT_EQ(at(none, 30, 9), Cell::kUnknown) << "no scanner: the right room's floor is unseen";
  EXPECT_EQ(none.specks_dropped, 1);
  ASSERT_EQ(none.warnings.size(), 1u);
  EXPECT_NE(none.warnings[0].find("observed floor alone"), std::string::npos);

  // A point on the far wall (x = 3.9 m) seen through the door: the ray from a scanner at
  // (1.0, 1.0, 1.2) crosses the door and the right room's floor.
  for (int z = 0; z < 25; ++z) put(g, 39, 10, z);
  const NavResult rays = build_nav_map(g, 0.05, {{1.05, 1.05, 1.2}}, p);
  EXPECT_TRUE(rays.warnings.empty());
  EXPECT_EQ(rays.positions, 1u);
  EXPECT_EQ(at(rays, 20, 10), Cell::kFree) << "the door is open";
  EXPECT_EQ(at(rays, 30, 10), Cell::kFree) << "crossed by the ray through the door";
  EXPECT_EQ(at(rays, 30, 3), Cell::kUnknown) << "behind the wall: no evidence";
  EXPECT_EQ(at(rays, 39, 10), Cell::kWall);
  EXPECT_GT(rays.cells_ray_free, 0);
}

// The veil of mixed pixels in a doorway when no ghost filter ran: columns of three points at
// unrelated heights, none two within a layer, over a floor that was seen through them. Each
// would pass the speck rule alone (three layers); together, a scatter over seen floor, they are
// no obstacle. A leg seen every other layer (a sparse multi-beam scan) stands alone and stays.
TEST(NavMap, DoorwayVeilOverSeenFloorIsNoObstacle) {
  auto g = room_with_seen_floor(0.1, 40, 20);
  for (int x = 5; x < 10; ++x)
    for (int y = 8; y < 12; ++y) {
      const int a = (x + y) % 2 ? 1 : 3;  // a checkerboard of two sets of heights
      for (int z : {a, a + 4, a + 8}) put(g, x, y, z, 1);
    }
  for (int z : {1, 3, 5, 7, 9}) put(g, 30, 10, z, 1);  // the sparse leg
  // Two cells beside the veil, five mixed pixels at unrelated heights with no point in their
  // 3 x 3 neighbourhood: part of the sparse veil, not a leg.
  for (int z : {1, 4, 7, 9, 11}) put(g, 11, 10, z, 1);
  const NavResult r = build_nav_map(g, 0.05, {}, NavParams{});
  for (int x = 5; x < 10; ++x)
    for (int y = 8; y < 12; ++y) EXPECT_EQ(at(r, x, y), Cell::kFree) << x << "," << y;
  EXPECT_EQ(at(r, 11, 10), Cell::kFree) << "a stray column of the veil";
  EXPECT_EQ(at(r, 30, 10), Cell::kWall) << "a lone column of points is a leg";
  EXPECT_EQ(r.specks_dropped, 21);
  // When the ghost filter ran with every point's own origin it has cleared real veils before;
  // the rule stands aside.
  const NavResult with_position = build_nav_map(g, 0.05, {{2.05, 1.05, 1.0}}, NavParams{}, true);
  EXPECT_EQ(at(with_position, 7, 9), Cell::kWall);
  EXPECT_EQ(with_position.specks_dropped, 0);
}

// At 5 cm layers: a column of five mixed pixels three of which fill neighbouring layers (15 cm,
// less than nav.min_column_m) beside a doorway veil is part of it; a leg filling five
// neighbouring layers stands.
TEST(NavMap, VeilColumnWithAShortRunOfLayersIsNoLeg) {
  auto g = room_with_seen_floor(0.05, 20, 20);
  for (int x = 5; x < 10; ++x)
    for (int y = 8; y < 12; ++y) {
      const int a = (x + y) % 2 ? 3 : 5;
      for (int z : {a, a + 5, a + 10}) put(g, x, y, z, 1);
    }
  for (int z : {3, 10, 11, 12, 18}) put(g, 11, 10, z, 1);
  for (int z = 3; z < 8; ++z) put(g, 16, 10, z, 1);
  const NavResult r = build_nav_map(g, 0.025, {}, NavParams{});
  EXPECT_EQ(at(r, 11, 10), Cell::kFree) << "five points, but a veil's";
  EXPECT_EQ(at(r, 7, 9), Cell::kFree);
  EXPECT_EQ(at(r, 16, 10), Cell::kWall) << "the leg";
}

// A table top at 0.75 m over a floor seen beneath it (through its legs, from other positions),
// its edge columns also holding a mixed pixel each at unrelated heights (the depth jump from the
// top to the floor behind): a level surface, not a doorway's veil. Without the level-surface
// guard the edge columns are scatter at other heights, every top column beside two of them
// becomes veil, and the whole top is free.
TEST(NavMap, TableTopWithMixedPixelsAlongItsEdgeIsNoVeil) {
  auto g = room_with_seen_floor(0.05, 20, 20);
  for (int x = 6; x < 12; ++x)
    for (int y = 6; y < 10; ++y) {
      put(g, x, y, 15, 6);
      if (x == 6 || x == 11 || y == 6 || y == 9) put(g, x, y, (x + 2 * y) % 2 ? 4 : 9, 1);
    }
  const NavResult r = build_nav_map(g, 0.025, {}, NavParams{});
  for (int x = 6; x < 12; ++x)
    for (int y = 6; y < 10; ++y) EXPECT_EQ(at(r, x, y), Cell::kWall) << x << "," << y;
  EXPECT_EQ(at(r, 3, 3), Cell::kFree);
  EXPECT_EQ(r.specks_dropped, 0);
}

// A table top seen at a grazing angle: points in every third column of cells (x 6, 9, 12), the
// floor seen under all of it. The two empty columns between sampled ones are part of the top;
// the four between the top and a wall's end (x 13-16; the wall at x 17 is no raised obstacle)
// are not, nor are the six between the wall and another top (x 18-23; top at x 24).
TEST(NavMap, GapsInASparselySampledTableTopAreClosed) {
  auto g = room_with_seen_floor(0.05, 40, 20);
  for (int y = 6; y < 10; ++y) {
    for (int x : {6, 9, 12, 24}) put(g, x, y, 15);
    for (int z = 1; z < 25; ++z) put(g, 17, y, z);  // a wall's end
  }
  const NavResult r = build_nav_map(g, 0.025, {}, NavParams{});
  for (int y = 6; y < 10; ++y) {
    for (int x = 6; x <= 12; ++x) EXPECT_EQ(at(r, x, y), Cell::kWall) << x << "," << y;
    for (int x : {13, 14, 15, 16, 18, 23}) EXPECT_EQ(at(r, x, y), Cell::kFree) << x << "," << y;
  }
}

// Rays pass beneath a raised obstacle. A scanner at x 0.5 m sees the floor up to x 1.0 m, a table
// top at 0.75 m over x 1.5-1.7 m, y 0.6-1.7 m with the floor seen under it, and the far wall at
// x 3.9 m; the floor between the table and the wall was not seen. The rays to the wall's foot
// passed under the top: the floor behind the table is free, the table stays occupied. A cabinet
// (points from the floor up, y 0.1-0.4 m) stops its rays; with nav.ray_under_min_m above the top
// the table stops them too.
TEST(NavMap, RaysPassBeneathATableTopNotACabinet) {
  auto g = room();
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 10; ++x) put(g, x, y, 0);
    for (int z = 0; z < 25; ++z) put(g, 39, y, z);  // the far wall
  }
  for (int x = 15; x < 18; ++x)
    for (int y = 6; y < 17; ++y) {  // 1.1 m across: wider than a shadow (nav.shadow_max_width_m)
      put(g, x, y, 0);              // the floor under the table, seen between its legs
      put(g, x, y, 7);              // the top
    }
  for (int x = 15; x < 18; ++x)
    for (int y = 1; y < 4; ++y) {
      put(g, x, y, 0);
      for (int z = 1; z < 9; ++z) put(g, x, y, z);  // the cabinet
    }
  const std::vector<Eigen::Vector3d> scanner{{0.55, 1.05, 1.2}};
  const NavResult r = build_nav_map(g, 0.05, scanner, NavParams{});
  EXPECT_EQ(at(r, 16, 10), Cell::kWall) << "the table top";
  EXPECT_EQ(at(r, 25, 10), Cell::kFree) << "behind the table: crossed beneath its top";
  EXPECT_EQ(at(r, 16, 2), Cell::kWall) << "the cabinet";
  EXPECT_EQ(at(r, 25, 2), Cell::kUnknown) << "behind the cabinet: no ray";
  NavParams high;
  high.ray_under_min_m = 0.8;
  const NavResult off = build_nav_map(g, 0.05, scanner, high);
  EXPECT_EQ(at(off, 16, 10), Cell::kWall);
  EXPECT_EQ(at(off, 25, 10), Cell::kUnknown);
}

// A table top seen by a mobile lidar's beams: three arcs of two points each at 0.75 m (x 10, 14
// and 18, y 5-12: 0.4 m apart), the floor seen everywhere, under the top too. Each arc alone is
// a line of specks; joined across their gaps they are the top: occupied from the first arc to
// the last, not beyond. Three points at that height elsewhere (fewer than a surface needs) and
// a doorway's veil (one point per column, neighbours at other heights) stay free.
TEST(NavMap, ArcsAcrossASparseTableTopAreOneTop) {
  auto g = room_with_seen_floor(0.1, 40, 20);
  for (const int x : {10, 14, 18})
    for (int y = 5; y <= 12; ++y) put(g, x, y, 7, 2);
  put(g, 30, 15, 7, 1);
  put(g, 31, 15, 7, 1);
  put(g, 30, 16, 7, 1);
  for (int y = 1; y <= 6; ++y)  // the veil: nine points at each of four heights
    for (int x = 30; x <= 35; ++x) put(g, x, y, 3 + 2 * ((x + 2 * y) % 4), 1);
  const NavResult r = build_nav_map(g, 0.05, {}, NavParams{});
  for (const int x : {11, 12, 13, 15, 16, 17})
    EXPECT_EQ(at(r, x, 8), Cell::kWall) << "between the arcs, x " << x;
  EXPECT_EQ(at(r, 22, 8), Cell::kFree) << "beyond the last arc";
  EXPECT_EQ(at(r, 14, 15), Cell::kFree) << "beside the top";
  EXPECT_EQ(at(r, 30, 15), Cell::kFree) << "three points are no top";
  EXPECT_EQ(at(r, 32, 3), Cell::kFree) << "the veil";
}

// Floor holes: a walled room (walls at x 0 and 39, y 0 and 19) with its floor seen but for a
// ring gap (x 8-10, wall to wall across the room: two thirds of its border is free floor), a
// scanner's blind disc (radius 3 cells round (30, 10)), a cabinet (occupied sides round an
// unseen inside) and a shaft (no floor, points 1 m below it). The gap and the disc become free;
// the cabinet's inside (bordered by occupied cells) and the shaft (a drop) stay unknown. Above
// floor_hole_max_m2 a hole stays unknown.
TEST(NavMap, FloorHolesBetweenRingsFilledCabinetAndShaftNot) {
  cloud::VoxelGrid g = room();
  g.origin_m = {0.0, 0.0,
                -1.0};  // layer 10 holds z 0.0-0.1: the floor; the shaft's points lie below
  const auto in_disc = [](int x, int y) { return (x - 30) * (x - 30) + (y - 10) * (y - 10) <= 9; };
  const auto in_cabinet = [](int x, int y) { return x >= 15 && x <= 19 && y >= 3 && y <= 6; };
  const auto in_shaft = [](int x, int y) { return x >= 23 && x <= 25 && y >= 13 && y <= 15; };
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) {
      if (x == 0 || x == 39 || y == 0 || y == 19) {
        for (int z = 10; z < 25; ++z) put(g, x, y, z);  // the walls
      } else if (in_cabinet(x, y)) {
        if (x == 15 || x == 19 || y == 3 || y == 6)
          for (int z = 11; z < 18; ++z) put(g, x, y, z);
      } else if (in_shaft(x, y)) {
        put(g, x, y, 0);  // the floor below
      } else if ((x < 8 || x > 10) && !in_disc(x, y)) {
        put(g, x, y, 10);
      }
    }
  const NavResult r = build_nav_map(g, 0.05, {}, NavParams{});
  EXPECT_EQ(at(r, 9, 1), Cell::kFree) << "the ring gap, by the wall";
  EXPECT_EQ(at(r, 9, 10), Cell::kFree);
  EXPECT_EQ(at(r, 30, 10), Cell::kFree) << "the blind disc";
  EXPECT_EQ(at(r, 17, 4), Cell::kUnknown) << "inside the cabinet";
  EXPECT_EQ(at(r, 24, 14), Cell::kUnknown) << "the shaft";
  // The gap's 54 cells and the disc's 29 less its four tips, one-cell notches that the floor's
  // 3 x 3 closing fills before.
  EXPECT_EQ(r.cells_hole_filled, 3 * 18 + 29 - 4);
  NavParams small;
  small.floor_hole_max_m2 = 0.3;  // the disc (29 cells of 0.01 m2) fits, the gap (54) does not
  const NavResult s = build_nav_map(g, 0.05, {}, small);
  EXPECT_EQ(at(s, 9, 10), Cell::kUnknown);
  EXPECT_EQ(at(s, 30, 10), Cell::kFree);
  NavParams off;
  off.floor_hole_max_m2 = 0;
  EXPECT_EQ(build_nav_map(g, 0.05, {}, off).cells_hole_filled, 0);
}

// Without any position, a gap along a wall (rows 15-18, x 10-29: the wall above it, floor below
// and at its ends; the floor's 3 x 3 closing takes a row off it, so about half its border is
// free) is a floor hole; at the share asked with rays (0.75) it is not.
TEST(NavMap, FloorHoleAlongAWallWithoutPositions) {
  cloud::VoxelGrid g = room();
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) {
      if (x == 0 || x == 39 || y == 0 || y == 19)
        for (int z = 0; z < 25; ++z) put(g, x, y, z);
      else if (!(y >= 15 && x >= 10 && x <= 29))
        put(g, x, y, 0);
    }
  const NavResult r = build_nav_map(g, 0.05, {}, NavParams{});
  EXPECT_EQ(at(r, 20, 16), Cell::kFree);
  EXPECT_EQ(at(r, 20, 18), Cell::kFree);
  EXPECT_GT(r.cells_hole_filled, 40);
  NavParams strict;
  strict.floor_hole_min_free_share_no_rays = strict.floor_hole_min_free_share;
  EXPECT_EQ(at(build_nav_map(g, 0.05, {}, strict), 20, 18), Cell::kUnknown);
}

// Two positions 10 m apart: each point goes to its nearest (the other is more than 1.5 m
// farther), none lost, the cloud untouched. Positions 0.5 m apart: a point may take any of those
// within 1.5 m of its nearest, never a farther one. With stride 3 a third of the points is taken.
TEST(NearestOrigin, TerrestrialNearestTrajectoryAmongTheNear) {
  PointCloud c;
  c.scanners = {{0, 0, 1}, {10, 0, 1}};
  for (float x : {1.0f, 9.0f, 2.0f, 8.5f, 0.5f}) c.points.emplace_back(x, 0.3f, 0.5f);
  const auto r = sample_by_nearest_origin(c, 1);
  ASSERT_TRUE(r.applied);
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_EQ(r.positions_used, 2u);
  EXPECT_EQ(r.points[0], (std::vector<Eigen::Vector3f>{c.points[0], c.points[2], c.points[4]}));
  EXPECT_EQ(r.points[1], (std::vector<Eigen::Vector3f>{c.points[1], c.points[3]}));
  const auto every_third = sample_by_nearest_origin(c, 3);  // points 0 and 3
  EXPECT_EQ(every_third.points[0], std::vector<Eigen::Vector3f>{c.points[0]});
  EXPECT_EQ(every_third.points[1], std::vector<Eigen::Vector3f>{c.points[3]});

  PointCloud t;
  for (int k = 0; k <= 40; ++k) t.scanners.emplace_back(0.5 * k, 0.0, 1.0);  // 0..20 m
  for (int i = 0; i < 400; ++i) t.points.emplace_back(0.05f * static_cast<float>(i), 1.0f, 0.2f);
  const auto rt = sample_by_nearest_origin(t, 1);
  ASSERT_TRUE(rt.applied);
  std::size_t covered = 0;
  for (std::size_t k = 0; k < rt.points.size(); ++k) {
    covered += rt.points[k].size();
    for (const auto& p : rt.points[k]) {
      const double near =
          std::hypot(std::clamp(std::round(p.x() / 0.5) * 0.5, 0.0, 20.0) - p.x(), 1.0);
      const auto& s = t.scanners[k];
      // 1.5 m margin, plus the 0.25 m lookup cell (candidates are per cell centre).
      EXPECT_LE(std::hypot(s.x() - p.x(), s.y() - p.y()), near + 1.5 + 0.4);
    }
  }
  EXPECT_EQ(covered, t.points.size());
  EXPECT_GT(rt.positions_used, 20u) << "the points spread over many positions";
  PointCloud one;
  one.scanners = {{0, 0, 0}};
  one.points = {{1, 1, 1}};
  EXPECT_FALSE(sample_by_nearest_origin(one, 1).applied) << "one position: nothing to estimate";
}

// A wall at x = 2.0 m between two rooms, points high on both far walls. From a position in the
// left room half the points lie behind the wall: no origin of that cloud (a mobile scan's
// VIEWPOINT). The left room's points alone are all visible. A point just beyond a voxel in its
// own layer (grazing) is not counted hidden.
TEST(ViewpointCheck, PointsBehindAWallAreHiddenFromTheOnePosition) {
  auto g = room();
  for (int y = 0; y < 20; ++y)
    for (int z = 0; z < 30; ++z) put(g, 20, y, z);
  std::vector<Eigen::Vector3f> left, both;
  for (int y = 0; y < 20; ++y) {
    left.emplace_back(0.15f, 0.05f + 0.1f * static_cast<float>(y), 2.55f);
    both.push_back(left.back());
    both.emplace_back(3.95f, 0.05f + 0.1f * static_cast<float>(y), 2.55f);
  }
  for (const auto& p : both)
    put(g, static_cast<int>(p.x() / 0.1f), static_cast<int>(p.y() / 0.1f), 25);
  const Eigen::Vector3d s{1.05, 1.05, 1.2};
  ViewpointCheckParams p;
  const ViewpointCheck all = check_viewpoint(g, both, s, p);
  EXPECT_EQ(all.sampled, 40u);
  EXPECT_EQ(all.occluded, 20u);
  EXPECT_DOUBLE_EQ(all.share(), 0.5);
  EXPECT_EQ(check_viewpoint(g, left, s, p).occluded, 0u);
  const std::vector<Eigen::Vector3f> grazing{{3.95f, 1.05f, 1.25f}};  // the wall in the ray's layer
  EXPECT_EQ(check_viewpoint(g, grazing, s, p).occluded, 0u);
  p.max_occluded_share = 2;
  EXPECT_THROW(validate(p), UsageError);
}

TEST(NavMap, ParametersAreValidated) {
  auto g = room();
  NavParams p;
  p.height_m = 0.05;
  EXPECT_THROW(build_nav_map(g, 0.0, {}, p), UsageError);
  p = {};
  p.min_neighbours = 9;
  EXPECT_THROW(validate(p), UsageError);
  p = {};
  p.floor_hole_min_free_share = 1.5;
  EXPECT_THROW(validate(p), UsageError);
  p = {};
  p.floor_hole_max_m2 = -1;
  EXPECT_THROW(validate(p), UsageError);
  p = {};
  p.ray_under_min_m = -0.1;
  EXPECT_THROW(validate(p), UsageError);
  p = {};
  p.over_low_max_m = 1.5;  // above robot.height_m
  EXPECT_THROW(validate(p), UsageError);
}

// Occupied cells per layer of a two-storey building: floors at layers 2 and 32, ceilings at
// 27 and 57, a slab 28-31 where nothing is seen, walls (5 cells) in every other layer.
TEST(Storeys, TwoStoreysFromTheSurfaceHistogram) {
  VoxelGeometry g;
  g.cell_m = 0.1;
  g.nx = g.ny = 10;
  g.nz = 60;
  std::vector<std::int64_t> occ(60, 5);
  occ[2] = occ[27] = occ[32] = occ[57] = 100;
  for (int z = 28; z < 32; ++z) occ[z] = 1;  // inside the slab: next to nothing
  occ[9] = 20;  // table tops: not a surface at 0.3 of the fullest layer
  const auto s = detect_storeys(occ, g);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_NEAR(s[0].floor_z_m, 0.25, 1e-9);
  EXPECT_NEAR(s[0].ceiling_z_m, 2.75, 1e-9);
  EXPECT_NEAR(s[1].floor_z_m, 3.25, 1e-9);
  EXPECT_NEAR(s[1].ceiling_z_m, 5.75, 1e-9);
  EXPECT_NEAR(s[0].hi_z_m, 3.0, 1e-9);  // the middle of the slab
  EXPECT_NEAR(s[1].lo_z_m, 3.0, 1e-9);

  // One room, its walls in every layer: no slab. A gap too thin, or with too little above it,
  // is no slab either.
  std::vector<std::int64_t> one(40, 5);
  one[1] = one[27] = one[31] = 100;
  one[29] = 0;  // one empty layer: thinner than min_slab_m (0.1 m = 1 layer here: make it 0.2)
  StoreyParams thick;
  thick.min_slab_m = 0.2;
  EXPECT_EQ(detect_storeys(one, VoxelGeometry{{0, 0, 0}, 0.1, 10, 10, 40}, thick).size(), 1u);
  EXPECT_EQ(detect_storeys(one, VoxelGeometry{{0, 0, 0}, 0.1, 10, 10, 40}).size(), 1u)
      << "10 layers above the gap: less than min_height_m";
  StoreyParams off;
  off.enabled = false;
  EXPECT_EQ(detect_storeys(occ, g, off).size(), 1u);
}

// Shadows (NavParams::shadow_max_width_m): a walled room, a scanner at (0.55, 1.05) m and the
// front face of a pillar (3 cells, 0.3 m) 0.45 m in front of it; the floor is seen everywhere but
// in the pillar's shadow, the far wall through it (from elsewhere). Floor holes off, so only the
// shadow rule can free the floor behind the pillar. The pillar's unseen inside (one width behind
// its face) stays unknown. Joined to a wall, the same face is no free-standing obstacle.
TEST(NavMap, ShadowOfAFreeStandingPillarIsFreeNotItsInside) {
  const double sx = 5.5, sy = 10.5;  // the scanner, in cells
  const auto shadowed = [&](int x, int y) {
    const double a = std::atan2(y + 0.5 - sy, x + 0.5 - sx);
    return x > 10 && std::abs(a) < std::atan2(1.6, 4.5);
  };
  auto build = [&](bool joined) {
    auto g = room();
    for (int y = 1; y < 19; ++y)
      for (int x = 1; x < 39; ++x)
        if (!shadowed(x, y)) put(g, x, y, 0);
    for (int z = 0; z < 25; ++z) {
      for (int x = 0; x < 40; ++x) put(g, x, 0, z), put(g, x, 19, z);
      for (int y = 0; y < 20; ++y) put(g, 0, y, z), put(g, 39, y, z);
      for (int y = 9; y <= 11; ++y) put(g, 10, y, z);  // the pillar's face
      if (joined)
        for (int y = 12; y < 19; ++y) put(g, 10, y, z);  // a wall from it to the room's wall
    }
    return g;
  };
  NavParams p;
  p.floor_hole_max_m2 = 0;
  const std::vector<Eigen::Vector3d> scanner{{0.55, 1.05, 1.2}};
  const NavResult r = build_nav_map(build(false), 0.05, scanner, p);
  EXPECT_EQ(at(r, 10, 10), Cell::kWall);
  EXPECT_EQ(at(r, 11, 10), Cell::kUnknown) << "the pillar's inside";
  // Up to the line joining the side rays' ends: they meet the side walls at x = 3.6 m.
  for (int x : {15, 20, 30}) EXPECT_EQ(at(r, x, 10), Cell::kFree) << x << ": behind the pillar";
  EXPECT_GT(r.cells_shadow_filled, 100);
  NavParams off = p;
  off.shadow_max_width_m = 0;
  const NavResult none = build_nav_map(build(false), 0.05, scanner, off);
  EXPECT_EQ(at(none, 30, 10), Cell::kUnknown);
  EXPECT_EQ(none.cells_shadow_filled, 0);
  const NavResult joined = build_nav_map(build(true), 0.05, scanner, p);
  EXPECT_EQ(at(joined, 30, 10), Cell::kUnknown) << "a wall's end is no pillar";
  NavParams bad;
  bad.shadow_min_depth_m = -1;
  EXPECT_THROW(validate(bad), UsageError);
}
