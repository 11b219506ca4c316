// Furniture objects without fragments (issue 17): pieces of one object a cell or two apart are
// joined, pieces below the minimum area are never listed, and every furniture cell belongs to an
// object or is counted as left over.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "indoormap/objects/objects.hpp"
#include "objects_fixtures.hpp"

using namespace indoormap;
using namespace indoormap::objects;
using namespace objects_fixtures;

namespace {

// A furniture block of cells [c0, c1] x [r0, r1] with its top at top_m.
void block(Grid<Cell>& L, cloud::VoxelGrid& g, int c0, int c1, int r0, int r1, double top_m) {
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      L.at(c, r) = Cell::kFurniture;
      fill_column(g, c, r, 0.0, top_m);
    }
}

std::int64_t furniture_cells(const Grid<Cell>& L) {
  std::int64_t n = 0;
  for (auto v : L.data) n += v == Cell::kFurniture;
  return n;
}

// Every furniture cell is in a furniture-class object or counted as left over; nothing listed is
// below the minimum area.
void expect_accounted(const Grid<Cell>& L, const ObjectsResult& res, const ObjectParams& p) {
  std::int64_t in_objects = 0;
  for (const auto& o : res.objects) {
    EXPECT_GE(o.area_m2, p.min_area_m2 - 1e-12) << "object " << o.id;
    if (o.kind == ObjectKind::kFurniture || o.kind == ObjectKind::kHanging) in_objects += o.cells;
  }
  EXPECT_EQ(in_objects + res.left_over_cells, furniture_cells(L));
  EXPECT_NEAR(res.left_over_area_m2, res.left_over_cells * 0.05 * 0.05, 1e-12);
}

}  // namespace

TEST(ObjectFragments, ADeskCutByAShadowIsOneObject) {
  const int w = 40, h = 16;
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  for (int gap : {1, 2, 3}) {
    Grid<Cell> L(w, h, Cell::kFree);
    auto g = voxels(w, h, 30);
    block(L, g, 2, 15, 3, 12, 0.75);
    block(L, g, 16 + gap, 30, 3, 12, 0.76);  // same desk beyond a shadow `gap` cells wide
    const auto res = extract_objects(L, geo, g, flat_layers(), {});
    expect_accounted(L, res, {});
    // join_gap_m 0.05 m = 1 cell: a gap of one cell is a shadow, two or more are two desks.
    ASSERT_EQ(res.objects.size(), gap <= 1 ? 1u : 2u) << "gap " << gap;
    if (gap <= 1) {
      EXPECT_EQ(res.objects[0].cells, (14 + 15 - gap) * 10);
      // The footprint spans the shadow: the desk's whole length.
      EXPECT_NEAR(res.objects[0].box.length_m, (31 - 2) * 0.05, 0.1);
    }
  }
}

// Two shelves end to end along a rotated wall, the floor seen between them: on the grid's
// staircase their corners come within the gap at a single pair of cells. A contact that short is
// no shadow across one piece; they stay two objects (pieces one cell apart along a whole edge
// are one desk cut by a shadow: ADeskCutByAShadowIsOneObject).
TEST(ObjectFragments, PiecesMeetingAtACornerStaySeparate) {
  const int w = 40, h = 24;
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  Grid<Cell> L(w, h, Cell::kFree);
  auto g = voxels(w, h, 50);
  block(L, g, 2, 15, 3, 9, 1.9);
  block(L, g, 17, 30, 11, 17, 1.9);  // corner (17, 11) two cells from (15, 9) on both axes
  const auto res = extract_objects(L, geo, g, flat_layers(), {});
  expect_accounted(L, res, {});
  ASSERT_EQ(res.objects.size(), 2u);
  for (const auto& o : res.objects) EXPECT_EQ(o.cells, 14 * 7);
}

TEST(ObjectFragments, DifferentHeightsAGapApartStaySeparate) {
  const int w = 40, h = 16;
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  Grid<Cell> L(w, h, Cell::kFree);
  auto g = voxels(w, h, 30);
  block(L, g, 2, 15, 3, 12, 0.75);   // a table
  block(L, g, 17, 26, 3, 12, 0.45);  // a chair one cell away
  const auto res = extract_objects(L, geo, g, flat_layers(), {});
  ASSERT_EQ(res.objects.size(), 2u);
  expect_accounted(L, res, {});
  EXPECT_EQ(res.left_over_cells, 0);
}

TEST(ObjectFragments, SmallPiecesJoinTheirObjectOrAreLeftOver) {
  const int w = 40, h = 20;
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  Grid<Cell> L(w, h, Cell::kFree);
  auto g = voxels(w, h, 30);
  block(L, g, 2, 15, 3, 12, 0.75);
  block(L, g, 17, 18, 5, 6, 0.30);   // a 4-cell sliver under the desk's edge, one cell away
  block(L, g, 30, 31, 15, 16, 0.5);  // a 4-cell speck far from everything
  ObjectParams p;
  const auto res = extract_objects(L, geo, g, flat_layers(), p);
  ASSERT_EQ(res.objects.size(), 1u);
  EXPECT_EQ(res.objects[0].cells, 14 * 10 + 4);
  EXPECT_EQ(res.labels.at(17, 5), res.objects[0].id);
  EXPECT_EQ(res.labels.at(30, 15), 0);
  EXPECT_EQ(res.left_over_cells, 4);
  EXPECT_EQ(res.left_over_pieces, 1);
  expect_accounted(L, res, p);
  p.join_gap_m = 0.0;  // no joining: the sliver is left over too
  const auto apart = extract_objects(L, geo, g, flat_layers(), p);
  ASSERT_EQ(apart.objects.size(), 1u);
  EXPECT_EQ(apart.left_over_cells, 8);
  expect_accounted(L, apart, p);
}

// The count identity on random clutter: blocks of random sizes and heights, some touching.
TEST(ObjectFragments, EveryFurnitureCellIsInAnObjectOrLeftOver) {
  std::mt19937 rng(7);
  const int w = 60, h = 50;
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  for (int trial = 0; trial < 10; ++trial) {
    Grid<Cell> L(w, h, Cell::kFree);
    auto g = voxels(w, h, 40);
    for (int k = 0; k < 25; ++k) {
      const int c0 = static_cast<int>(rng() % (w - 8)), r0 = static_cast<int>(rng() % (h - 8));
      const int cw = 1 + static_cast<int>(rng() % 7), rh = 1 + static_cast<int>(rng() % 7);
      block(L, g, c0, c0 + cw - 1, r0, r0 + rh - 1, 0.2 + 0.1 * static_cast<double>(rng() % 15));
    }
    ObjectParams p;
    p.min_area_m2 = 0.01 * static_cast<double>(trial % 5);
    expect_accounted(L, extract_objects(L, geo, g, flat_layers(), p), p);
  }
}

// Mixed pixels and range noise that no ray evidence removed (a moving scan without positions):
// a patch of columns holding one return each is no surface on a scan whose floor cells hold
// several returns; a cabinet and a small bin whose near half holds several returns per column
// stay. drop_stray_pieces leaves the patch over and keeps the count identity. On a cloud
// resampled to the cell size (one floor point per cell) a count tells nothing: the patch stays.
TEST(ObjectFragments, APatchOfStrayReturnsIsNoObject) {
  const int w = 50, h = 30;
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  for (const std::uint16_t floor_points : {6, 1}) {
    Grid<Cell> L(w, h, Cell::kFree);
    auto g = voxels(w, h, 40);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) fill_column(g, c, r, 0.0, 0.05, floor_points);
    block(L, g, 2, 15, 3, 10, 1.2);  // a cabinet: every column a surface
    std::mt19937 rng(11);
    for (int r = 15; r <= 24; ++r)  // a 10 x 10 patch of single returns between 0.5 and 0.65 m
      for (int c = 30; c <= 39; ++c) {
        L.at(c, r) = Cell::kFurniture;
        const double z = 0.5 + 0.05 * static_cast<double>(rng() % 3);
        fill_column(g, c, r, z, z + 0.05, 1);
      }
    // A bin of 6 x 6 cells: 12 columns of its near side hold its wall (surface), 8 more a return
    // each, the rest none (its hidden back): 12 surface cells of 20 seen, below the 16 of
    // min_seen_area_m2 but most of what was seen.
    int k = 0;
    for (int r = 20; r <= 25; ++r)
      for (int c = 5; c <= 10; ++c, ++k) {
        L.at(c, r) = Cell::kFurniture;
        if (k < 12) {
          fill_column(g, c, r, 0.0, 0.4);
        } else if (k < 20) {
          fill_column(g, c, r, 0.3, 0.35, 1);
        }
      }
    const ObjectParams p;
    const ScanTraits dense{true, false};
    auto res = extract_objects(L, geo, g, flat_layers(), p, {}, dense);
    ASSERT_EQ(res.objects.size(), 3u);  // listed: a step that needs every piece sees them
    expect_accounted(L, res, p);
    const std::int32_t patch = res.labels.at(30, 15), bin = res.labels.at(5, 20);
    ASSERT_GT(patch, 0);
    ASSERT_GT(bin, 0);
    const bool counts_tell = floor_points > 1;
    for (const auto& o : res.objects) {
      if (o.id == patch) {
        EXPECT_EQ(o.surface_cells, counts_tell ? 0 : 100);
      }
      if (o.id == bin) {
        EXPECT_EQ(o.seen_cells, 20);
        EXPECT_EQ(o.surface_cells, counts_tell ? 12 : 20);
      }
    }
    const std::int64_t left_before = res.left_over_cells;
    drop_stray_pieces(res, geo, p);
    ASSERT_EQ(res.objects.size(), counts_tell ? 2u : 3u) << "floor points " << floor_points;
    EXPECT_EQ(res.labels.at(30, 15), counts_tell ? 0 : patch);
    EXPECT_EQ(res.labels.at(5, 20), bin);
    EXPECT_EQ(res.left_over_cells, left_before + (counts_tell ? 100 : 0));
    expect_accounted(L, res, p);
  }
}

// Without scanner positions no ghost filter removes the mixed pixels behind an object's edges:
// a fringe of single returns around a cabinet widens it. With ScanTraits::peel_strays the
// fringe is left over and the cabinet keeps its own cells; without, the fringe is part of it.
TEST(ObjectFragments, PeelingStrayReturnsLeavesTheCabinetItsFaces) {
  const int w = 40, h = 30;
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  Grid<Cell> L(w, h, Cell::kFree);
  auto g = voxels(w, h, 40);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) fill_column(g, c, r, 0.0, 0.05, 6);
  block(L, g, 10, 25, 10, 17, 1.0);  // 16 x 8 cells
  for (int r = 7; r <= 20; ++r)      // a fringe three cells wide, one return per column
    for (int c = 7; c <= 28; ++c)
      if (L.at(c, r) != Cell::kFurniture) {
        L.at(c, r) = Cell::kFurniture;
        fill_column(g, c, r, 0.95, 1.0, 1);
      }
  const ObjectParams p;
  for (const bool peel : {false, true}) {
    const auto res =
        extract_objects(L, geo, g, flat_layers(), p, {}, ScanTraits{true, false, peel});
    ASSERT_EQ(res.objects.size(), 1u) << "peel " << peel;
    EXPECT_EQ(res.objects[0].cells, peel ? 16 * 8 : 22 * 14) << "peel " << peel;
    EXPECT_EQ(res.left_over_cells, peel ? 22 * 14 - 16 * 8 : 0);
    expect_accounted(L, res, p);
  }
}

namespace {

// A slab of furniture cells [c0, c1] x [r0, r1] between z0_m and z1_m (a seat, a table top), on
// legs in its four corners when `legs`.
void slab(Grid<Cell>& L, cloud::VoxelGrid& g, int c0, int c1, int r0, int r1, double z0_m,
          double z1_m, bool legs) {
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      L.at(c, r) = Cell::kFurniture;
      fill_column(g, c, r, z0_m, z1_m);
      if (legs && (c == c0 || c == c1) && (r == r0 || r == r1)) fill_column(g, c, r, 0.0, z0_m);
    }
}

}  // namespace

// A chair: the height rule cuts its backrest (top 0.9 m) off its seat (top 0.45 m); the backrest
// starts at the seat's underside, 0.4 m above the floor: it rests on the seat, one object.
TEST(ObjectFragments, ABackrestRestingOnItsSeatIsOneChair) {
  const int w = 30, h = 30;
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  Grid<Cell> L(w, h, Cell::kFree);
  auto g = voxels(w, h, 30);
  slab(L, g, 5, 13, 5, 13, 0.401, 0.451, true);    // the seat, 9 x 9 cells
  slab(L, g, 5, 13, 14, 15, 0.401, 0.901, false);  // the backrest, 9 x 2 cells along its edge
  const auto res = extract_objects(L, geo, g, flat_layers(), {});
  ASSERT_EQ(res.objects.size(), 1u);
  EXPECT_EQ(res.objects[0].cells, 9 * 11);
  expect_accounted(L, res, {});
  // Without the resting rule's evidence (the backrest standing on the floor, a shelf beside a
  // stool) they stay two objects.
  Grid<Cell> L2(w, h, Cell::kFree);
  auto g2 = voxels(w, h, 30);
  slab(L2, g2, 5, 13, 5, 13, 0.401, 0.451, true);
  slab(L2, g2, 5, 13, 14, 15, 0.0, 0.901, false);
  EXPECT_EQ(extract_objects(L2, geo, g2, flat_layers(), {}).objects.size(), 2u);
}

// A table (top 0.70-0.75 m) touching a chair's seat (0.40-0.45 m): the table's underside is above
// the seat, it does not rest on it; a cabinet from the floor beside the table stands by itself.
TEST(ObjectFragments, ATableBesideASeatOrACabinetStaysSeparate) {
  const int w = 50, h = 30;
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  Grid<Cell> L(w, h, Cell::kFree);
  auto g = voxels(w, h, 30);
  slab(L, g, 5, 24, 5, 20, 0.701, 0.751, true);   // the table
  slab(L, g, 25, 33, 8, 16, 0.401, 0.451, true);  // a seat pushed against it
  slab(L, g, 10, 19, 21, 26, 0.0, 0.951, false);  // a cabinet touching its other side
  const auto res = extract_objects(L, geo, g, flat_layers(), {});
  ASSERT_EQ(res.objects.size(), 3u);
  expect_accounted(L, res, {});
}

namespace {

// A room's wall along the top rows with a window: wall cells in rows [h-2, h-1] except columns
// [wc0, wc1], where the wall below the sill (0.85 m) shows as furniture and the lintel (from 2.2 m
// to the grid's top, 3 m) stands over its face row (h - 3). A `depth`-row piece of furniture in
// front of the face, its top at top_m, when depth > 0.
void window_wall(Grid<Cell>& L, cloud::VoxelGrid& g, int wc0, int wc1, int parapet_rows, int depth,
                 double top_m) {
  const int h = L.height;
  for (int c = 0; c < L.width; ++c)
    for (int r = h - 2; r < h; ++r)
      if (c < wc0 || c > wc1) {
        L.at(c, r) = Cell::kWall;
        fill_column(g, c, r, 0.0, 3.0);
      }
  for (int c = wc0; c <= wc1; ++c) {
    for (int r = h - 1 - parapet_rows; r < h; ++r) {
      L.at(c, r) = Cell::kFurniture;
      fill_column(g, c, r, 0.0, 0.851);
    }
    fill_column(g, c, h - 1 - parapet_rows, 2.2, 3.0);  // the lintel's face
    for (int r = h - 1 - parapet_rows - depth; r < h - 1 - parapet_rows; ++r) {
      L.at(c, r) = Cell::kFurniture;
      fill_column(g, c, r, 0.0, top_m);
    }
  }
}

}  // namespace

// The wall under a window is not an object: a lintel stands over its whole length.
TEST(ObjectFragments, TheWallUnderAWindowIsNoObject) {
  const int w = 40, h = 30;
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  Grid<Cell> L(w, h, Cell::kFree);
  auto g = voxels(w, h, 60);
  window_wall(L, g, 8, 31, 4, 0, 0.0);  // parapet 24 x 5 cells, lintel over its inner row
  const auto res = extract_objects(L, geo, g, flat_layers(), {});
  EXPECT_TRUE(res.objects.empty());
  expect_accounted(L, res, {});
  // Its cells are kept as the wall under a window (the rooms of a floor stop there), and no other.
  ASSERT_EQ(res.wall_cells.width, w);
  int parapet = 0;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      parapet += res.wall_cells.at(c, r);
      if (res.wall_cells.at(c, r)) {
        EXPECT_EQ(L.at(c, r), Cell::kFurniture) << c << "," << r;
      }
    }
  EXPECT_EQ(parapet, 24 * 5);
  // The same cells with nothing above them (a low cabinet along the wall) are an object.
  Grid<Cell> L2(w, h, Cell::kFree);
  auto g2 = voxels(w, h, 60);
  window_wall(L2, g2, 8, 31, 4, 0, 0.0);
  for (int c = 8; c <= 31; ++c)
    for (std::int64_t z = 0; z < g2.nz; ++z)
      if (z * g2.cell_m > 2.0) g2.counts[(z * g2.ny + (h - 5)) * g2.nx + c] = 0;
  const auto res2 = extract_objects(L2, geo, g2, flat_layers(), {});
  EXPECT_EQ(res2.objects.size(), 1u);
  EXPECT_EQ(std::count(res2.wall_cells.data.begin(), res2.wall_cells.data.end(), 1), 0);
}

// A cabinet under a window (0.5 m deep, touching the wall below the sill) keeps its place: the
// lintel stands over a tenth of its cells only.
TEST(ObjectFragments, ACabinetUnderAWindowIsAnObject) {
  const int w = 40, h = 30;
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  Grid<Cell> L(w, h, Cell::kFree);
  auto g = voxels(w, h, 60);
  window_wall(L, g, 8, 31, 0, 10, 0.851);  // no wall thickness shown, a cabinet as high as the sill
  const auto res = extract_objects(L, geo, g, flat_layers(), {});
  ASSERT_EQ(res.objects.size(), 1u);
  EXPECT_EQ(res.objects[0].cells, 24 * 11);
}

TEST(Objects, PiecesJoinedByANeckWithoutAFaceAreSplit) {
  // Two shelves 40 x 8 cells along a wall, joined across cols 23-26 by a neck two cells deep
  // (rows 20-21). Two pieces of furniture a gap apart: the neck's cells hold no surface (mixed
  // pixels, a pocket), so each shelf is its own object. One shelf with a notch behind its front
  // face: the face (row 20) runs on across the neck, so it stays one object. With neck_width_m
  // 0 nothing is split.
  auto scene = [](bool face_across) {
    const int w = 60, h = 40;
    Grid<Cell> L = walled_room(w, h);
    auto g = voxels(w, h, 50);
    block(L, g, 5, 44, 20, 27, 1.8);
    for (int r = 20; r <= 27; ++r)
      for (int c = 23; c <= 26; ++c) {
        for (std::int64_t z = 0; z < g.nz; ++z) g.counts[(z * g.ny + r) * g.nx + c] = 0;
        if (r >= 22)
          L.at(c, r) = Cell::kFree;
        else if (face_across)
          fill_column(g, c, r, 0.0, 1.8);
      }
    return std::pair{L, g};
  };
  ObjectParams p;
  const GridGeometry geo({0.0, 0.0}, 0.05, 60, 40);
  const auto [gap_L, gap_g] = scene(false);
  const auto two = extract_objects(gap_L, geo, gap_g, flat_layers(), p);
  ASSERT_EQ(two.objects.size(), 2u);
  EXPECT_NE(two.labels.at(10, 24), two.labels.at(40, 24));
  EXPECT_EQ(two.objects[0].cells + two.objects[1].cells, 2 * 18 * 8 + 4 * 2);
  for (const auto& o : two.objects) EXPECT_NEAR(o.z_max_m, 1.775, 0.051);
  const auto [notch_L, notch_g] = scene(true);
  EXPECT_EQ(extract_objects(notch_L, geo, notch_g, flat_layers(), p).objects.size(), 1u);
  p.neck_width_m = 0.0;
  EXPECT_EQ(extract_objects(gap_L, geo, gap_g, flat_layers(), p).objects.size(), 1u);
}
