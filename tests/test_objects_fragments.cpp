// Furniture objects without fragments (issue 17): pieces of one object a cell or two apart are
// joined, pieces below the minimum area are never listed, and every furniture cell belongs to an
// object or is counted as left over.
#include <gtest/gtest.h>

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
