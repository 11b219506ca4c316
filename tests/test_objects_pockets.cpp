// Furniture objects next to what the scanner could not see: unseen pockets behind an object,
// stray returns in its shadow, a wall's face seen in the furniture band (furniture-extract.md,
// steps 4 and 5). Hand-made voxel grids of 5 cm cells with the scanner positions given.
#include <gtest/gtest.h>

#include "indoormap/cloud/voxel.hpp"
#include "indoormap/objects/objects.hpp"
#include "objects_fixtures.hpp"

using namespace indoormap;
using namespace indoormap::objects;
using namespace objects_fixtures;

namespace {

// Every object listed, however small: the rules under test decide alone.
ObjectParams every_size() {
  ObjectParams p;
  p.min_area_m2 = 0.0;
  p.min_seen_area_m2 = 0.0;
  return p;
}

// 40 x 16 cells: a bin (0.4 m, cells 20-23 x 3-6) with furniture cells of its unseen shadow
// behind it (24-29, fenced in by other obstacles in the layout, no data), the wall behind them
// (column 31, seen to 1.9 m), and the scanner at 1.3 m on the bin's other side.
struct BinWithShadow {
  static constexpr int w = 40, h = 16;
  Grid<Cell> layout{w, h, Cell::kFree};
  cloud::VoxelGrid grid = voxels(w, h, 40);
  GridGeometry geometry{{0.0, 0.0}, 0.05, w, h};
  std::vector<Eigen::Vector3d> scanner{{0.0, 0.4, 1.3}};
  BinWithShadow() {
    for (int r = 3; r <= 6; ++r) {
      for (int c = 20; c <= 29; ++c) layout.at(c, r) = Cell::kFurniture;
      for (int c = 20; c <= 23; ++c) fill_column(grid, c, r, 0.0, 0.4);
    }
    for (int r = 0; r < h; ++r) fill_column(grid, 31, r, 0.0, 1.9);
  }
  ObjectsResult extract(bool with_scanner = true,
                        std::optional<bool> dense_scan = std::nullopt) const {
    return extract_objects(layout, geometry, grid, flat_layers(), every_size(),
                           with_scanner ? scanner : std::vector<Eigen::Vector3d>{},
                           ScanTraits{dense_scan});
  }
};

}  // namespace

TEST(Objects, PocketsTheScannerSawIntoAreNotPartOfTheObject) {
  // The bin's shadow, whose far end shows the floor, and a shelf (1.8 m, above the scanner) with
  // its hidden body behind its front face. The scanner would have seen the bin's top over the
  // pocket: the pocket is not the bin. It cannot see a shelf's top: the body stays.
  BinWithShadow t;
  for (int r = 3; r <= 6; ++r)
    for (int c = 27; c <= 29; ++c) fill_column(t.grid, c, r, 0.0, 0.05);  // the floor seen there
  for (int r = 10; r <= 13; ++r) {
    for (int c = 20; c <= 23; ++c) t.layout.at(c, r) = Cell::kFurniture;
    fill_column(t.grid, 20, r, 0.0, 1.8);
  }
  const auto res = t.extract();
  ASSERT_EQ(res.objects.size(), 2u);
  EXPECT_EQ(res.objects[0].cells, 16);  // the bin alone
  EXPECT_EQ(res.objects[0].max_cell.col, 23);
  EXPECT_EQ(res.labels.at(25, 4), 0);
  EXPECT_EQ(res.objects[1].cells, 16);  // the shelf with its hidden body
  EXPECT_NEAR(res.objects[1].z_max_m, 1.775, 1e-9);
  // Without a scanner position there is no evidence about the unseen pocket cells; the cells
  // whose floor was seen still go.
  const auto blind = t.extract(false);
  ASSERT_EQ(blind.objects.size(), 2u);
  EXPECT_EQ(blind.objects[0].cells, 16 + 12);
  EXPECT_EQ(blind.labels.at(28, 4), 0);
}

TEST(Objects, AnEmptyPocketIsNoEvidenceWhereNoBeamPassed) {
  // A cabinet (1.0 m) against a wall, seen from 1.3 m by a sparse scan: its front face and one
  // row of its top, the rest of the top between the beams. The line from the scanner over the
  // top is clear, but continued beyond the pocket cells it meets nothing recorded (the wall's
  // foot is hidden behind the cabinet, and past the wall there is nothing): no beam passed there,
  // so the empty cells prove nothing and the cabinet keeps its depth. A bin's shadow, with the
  // wall behind it seen above the bin, goes (PocketsTheScannerSawIntoAreNotPartOfTheObject).
  const int w = 34, h = 12;
  Grid<Cell> L(w, h, Cell::kFree);
  auto g = voxels(w, h, 50);
  for (int r = 3; r <= 8; ++r) {
    for (int c = 20; c <= 29; ++c) L.at(c, r) = Cell::kFurniture;
    fill_column(g, 20, r, 0.0, 1.0);   // the front face
    fill_column(g, 21, r, 0.95, 1.0);  // one row of the top
  }
  for (int r = 0; r < h; ++r) {
    L.at(30, r) = L.at(31, r) = Cell::kWall;
    // The wall is seen from 1.2 m up only (the sparse rows above the cabinet's top).
    for (int c = 30; c <= 31; ++c) fill_column(g, c, r, 1.2, 2.4);
  }
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  const std::vector<Eigen::Vector3d> scanner{{0.0, 0.3, 1.3}};
  const auto res = extract_objects(L, geo, g, flat_layers(), every_size(), scanner);
  ASSERT_EQ(res.objects.size(), 1u);
  EXPECT_EQ(res.objects[0].cells, 60);
}

TEST(Objects, StrayReturnsInABinsShadowDoNotJoinTheShadowToTheBin) {
  // In the bin's shadow, single returns at 0.2 m (mixed pixels): without the rule they count as
  // data, the pocket between them and the bin is "a gap of missed samples" and joins the bin.
  // They lie where the scanner's ray passed under the bin's top carried over, so they leave the
  // object, and the pocket with them. A table top sampled with one return per cell at its own
  // level stays.
  BinWithShadow t;
  for (int r = 10; r <= 13; ++r) {
    for (int c = 20; c <= 23; ++c) t.layout.at(c, r) = Cell::kFurniture;
    for (int c = 20; c <= 21; ++c) fill_column(t.grid, c, r, 0.7, 0.75);
    for (int c = 22; c <= 23; ++c) fill_column(t.grid, c, r, 0.7, 0.75, 1);
  }
  // Without the stray returns the pocket goes (the pocket rule).
  EXPECT_EQ(t.extract().objects[0].cells, 16);
  fill_column(t.grid, 26, 4, 0.2, 0.25, 1);
  fill_column(t.grid, 26, 5, 0.2, 0.25, 1);
  const auto res = t.extract();
  ASSERT_EQ(res.objects.size(), 2u);
  EXPECT_EQ(res.objects[0].cells, 16);  // the bin alone
  EXPECT_EQ(res.objects[0].max_cell.col, 23);
  for (int c = 24; c <= 29; ++c) EXPECT_EQ(res.labels.at(c, 4), 0) << c;
  EXPECT_EQ(res.objects[1].cells, 16);  // the whole table top
}

TEST(Objects, ThinStripsAlongAWallAreItsFaceNotObjects) {
  // Walls on the border of a 40 x 30 room. Along the south wall a strip two cells (0.1 m) deep
  // and 16 long: the wall's face seen in the furniture band (a grazing view). A shelf 7 cells
  // (0.35 m) deep along the north wall and a bin of 5 x 5 cells in the south-east corner stay.
  const int w = 40, h = 30;
  Grid<Cell> L = walled_room(w, h);
  auto g = voxels(w, h, 50);
  put_block(L, g, 8, 23, 1, 2, 1.8);    // the face strip
  put_block(L, g, 8, 23, 22, 28, 1.8);  // the shelf
  put_block(L, g, 34, 38, 1, 5, 0.4);   // the bin in the corner
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  const auto res = extract_objects(L, geo, g, flat_layers(), every_size());
  ASSERT_EQ(res.objects.size(), 2u);
  EXPECT_EQ(res.objects[0].cells, 25);  // the bin (row 1 first)
  EXPECT_EQ(res.objects[1].cells, 7 * 16);
  EXPECT_EQ(res.labels.at(10, 1), 0);
  EXPECT_EQ(res.wall_cells.at(10, 1), 1);  // wall to the rooms of a floor
  EXPECT_EQ(res.wall_cells.at(10, 25), 0);
  EXPECT_EQ(res.left_over_cells, 32);  // the strip, counted as left over
  EXPECT_EQ(res.left_over_pieces, 1);
  EXPECT_NEAR(res.left_over_area_m2, 32 * 0.0025, 1e-12);
}

TEST(Objects, SpecksOfWallOnAShelfsTopDoNotMakeItAFace) {
  // A shelf 8 cells (0.4 m) deep along the north wall of a 40 x 30 room, whose top reached the
  // wall band in a few places: specks of wall cells on it. Within three cells of those specks
  // lies most of the shelf, but they are no wall: the shelf stays an object. The same specks
  // on a wall seen only in fragments (beside free floor) still make a thin strip a face.
  const int w = 40, h = 30;
  Grid<Cell> L = walled_room(w, h);
  auto g = voxels(w, h, 50);
  put_block(L, g, 8, 23, 21, 28, 1.9);
  for (const int c : {10, 15, 20})
    for (int r = 23; r <= 24; ++r) L.at(c, r) = L.at(c + 1, r) = Cell::kWall;
  // A wall in fragments across the room (row 12, every third pair of cells) and the face strip
  // south of it, two cells deep.
  for (int c = 8; c <= 23; c += 3) L.at(c, 12) = L.at(c + 1, 12) = Cell::kWall;
  put_block(L, g, 8, 23, 10, 11, 1.8);
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  const auto res = extract_objects(L, geo, g, flat_layers(), every_size());
  ASSERT_EQ(res.objects.size(), 1u);
  EXPECT_EQ(res.labels.at(12, 22), res.objects[0].id);  // the shelf
  EXPECT_EQ(res.objects[0].cells, 16 * 8 - 12);
  EXPECT_EQ(res.wall_cells.at(12, 22), 0);
  EXPECT_EQ(res.labels.at(12, 10), 0);  // the strip: the fragments' face
  EXPECT_EQ(res.wall_cells.at(12, 10), 1);
}

TEST(Objects, ThinStripsBesideTheUnseenWorldAreFacesNotWalls) {
  // A 40 x 30 room whose east part was never seen: columns 32-39 are unknown up to the map's
  // edge (the far end of a corridor, its wall band unseen). Along that edge a strip two cells
  // deep and 16 long is the end wall's face: it leaves the list (left over) but is no wall for
  // the rooms step, which finds the room's edge at the unknown. A shelf 7 cells (0.35 m) deep
  // along the same edge stays, and so does a strip of the same size beside an unknown pocket
  // inside the room (under a table: it does not reach the map's edge).
  const int w = 40, h = 30;
  Grid<Cell> L = walled_room(w, h);
  for (int r = 0; r < h; ++r)
    for (int c = 32; c < w; ++c) L.at(c, r) = Cell::kUnknown;
  for (int r = 10; r <= 20; ++r)
    for (int c = 10; c <= 14; ++c) L.at(c, r) = Cell::kUnknown;  // the pocket
  auto g = voxels(w, h, 50);
  put_block(L, g, 30, 31, 2, 17, 1.8);   // the face strip, beside the unseen world
  put_block(L, g, 25, 31, 20, 27, 1.8);  // the shelf
  put_block(L, g, 15, 16, 5, 20, 1.8);   // a strip beside the pocket
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  const auto res = extract_objects(L, geo, g, flat_layers(), every_size());
  ASSERT_EQ(res.objects.size(), 2u);
  EXPECT_EQ(res.labels.at(30, 10), 0);
  EXPECT_EQ(res.wall_cells.at(30, 10), 0);
  EXPECT_NE(res.labels.at(15, 10), 0);
  EXPECT_NE(res.labels.at(28, 25), 0);
  EXPECT_EQ(res.left_over_cells, 32);
}

TEST(Objects, ALowRoomsCeilingOverAShelfIsNoPartOfIt) {
  // A 40 x 30 room, furniture band up to 2.0 m (layer 40), the storey's ceiling at 3.5 m, this
  // room's own at 2.7 m: a return at layer 54 over every free cell. A shelf 1.8 m high along the
  // north wall: its front row holds the face from the floor up, the rows behind hold only the
  // ceiling above them (the scanner saw the ceiling, not the shelf's body). The ceiling lies over
  // the free floor too, so it gives those cells no height: one shelf, 1.8 m high, not a face and
  // a second object up to the ceiling. A tall cabinet's top at 2.1 m, seen over its body only,
  // stays its top.
  const int w = 40, h = 30;
  Grid<Cell> L = walled_room(w, h);
  auto g = voxels(w, h, 80);
  auto layers = flat_layers();
  layers.ceiling_layer = 70;
  layers.furniture_band.lo_layer = 2;
  layers.furniture_band.hi_layer = 40;
  for (int r = 1; r < h - 1; ++r)
    for (int c = 1; c < w - 1; ++c) g.counts[(54 * g.ny + r) * g.nx + c] = 3;
  for (int c = 5; c <= 20; ++c) {
    for (int r = 21; r <= 28; ++r) L.at(c, r) = Cell::kFurniture;
    fill_column(g, c, 21, 0.0, 1.8);
  }
  for (int c = 28; c <= 35; ++c) {  // the cabinet: face on row 5, its top over rows 5-10
    for (int r = 5; r <= 10; ++r) {
      L.at(c, r) = Cell::kFurniture;
      g.counts[(54 * g.ny + r) * g.nx + c] = 0;  // under the cabinet's top, no ceiling seen
      fill_column(g, c, r, 2.05, 2.1);
    }
    fill_column(g, c, 5, 0.0, 2.1);
  }
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  const auto res = extract_objects(L, geo, g, layers, every_size());
  std::vector<FurnitureObject> furniture;  // the low ceiling itself is listed as a lamp
  for (const auto& o : res.objects)
    if (o.kind == ObjectKind::kFurniture) furniture.push_back(o);
  ASSERT_EQ(furniture.size(), 2u);
  EXPECT_EQ(furniture[0].cells, 8 * 6);  // the cabinet (rows 5-10 first)
  EXPECT_NEAR(furniture[0].z_max_m, 2.1, 0.051);
  EXPECT_EQ(furniture[1].cells, 16 * 8);
  EXPECT_NEAR(furniture[1].z_max_m, 1.8, 0.051);
}

TEST(Objects, StrayReturnsNearerATallCabinetThanTheBinStillLeave) {
  // The bin's shadow ends at a tall cabinet (columns 28-29, 1.9 m, above the scanner), and the
  // single returns in the shadow (column 27) lie nearer the cabinet than the bin. The scanner
  // cannot have seen the cabinet's top carried over them, but its ray passed over the bin's top,
  // the lowest surface within 0.25 m: they leave the object, and the bin stays alone.
  BinWithShadow t;
  for (int r = 3; r <= 6; ++r)
    for (int c = 28; c <= 29; ++c) fill_column(t.grid, c, r, 0.0, 1.9);
  fill_column(t.grid, 27, 4, 0.2, 0.25, 1);
  fill_column(t.grid, 27, 5, 0.2, 0.25, 1);
  const auto res = t.extract();
  ASSERT_GE(res.objects.size(), 2u);
  EXPECT_EQ(res.objects[0].cells, 16);  // the bin alone
  EXPECT_EQ(res.objects[0].max_cell.col, 23);
  EXPECT_EQ(res.labels.at(24, 4), 0);
  EXPECT_NE(res.labels.at(28, 4), res.labels.at(21, 4));
  EXPECT_NE(res.labels.at(27, 4), res.labels.at(21, 4));
}

TEST(Objects, PairsOfStrayReturnsLeaveOnADenseScanOnly) {
  // The mixed pixels behind a bin's rim land one or two to a 5 cm cell. On a dense scan (the floor
  // sampled in most cells of its 0.2 m blocks: cloud::floor_fill >= 0.6) a surface leaves many
  // points per cell, so a cell of two below the bin's top, where the scanner could have seen that
  // top, is a stray too: as a surface it anchored the pocket between it and the bin, and the bin
  // grew to the wall (tuning buildings, 3DTK: 9 bins of 0.06-0.08 m2 written as 0.13-0.21 m2). On
  // a sparse scan (1 degree: one or two points per cell on every surface) two stay a surface.
  for (const bool dense : {true, false}) {
    BinWithShadow t;
    for (int r = 0; r < t.h; ++r)
      for (int c = 0; c < 31; ++c) {
        const bool shadow = c >= 20 && c <= 29 && r >= 3 && r <= 6;
        if (!shadow && (dense || (c % 2 == 0 && r % 2 == 0))) fill_column(t.grid, c, r, 0.0, 0.05);
      }
    ASSERT_EQ(cloud::floor_fill(t.grid, 0) >= 0.6, dense);
    fill_column(t.grid, 26, 4, 0.2, 0.25, 2);
    fill_column(t.grid, 27, 5, 0.25, 0.3, 2);
    const auto res = t.extract();
    ASSERT_GE(res.objects.size(), 1u);
    if (dense) {
      ASSERT_EQ(res.objects.size(), 1u);
      EXPECT_EQ(res.objects[0].cells, 16);  // the bin alone
      for (int c = 24; c <= 29; ++c) EXPECT_EQ(res.labels.at(c, 4), 0) << c;
    } else {
      EXPECT_GT(res.objects[0].cells, 16);  // the pairs and the gap between: the rule stands aside
    }
    // The caller's word (layout::MapResult::dense_scan, from layout.sparse_floor_fill) decides
    // over the floor fill: a user who moves that key moves this rule too.
    EXPECT_EQ(t.extract(true, !dense).objects[0].cells == 16, !dense);
  }
}

// A room of w x 20 cells (5 cm) with a wall across it at column 25 (seen up to 2.4 m) and a block
// of furniture cells without data against it (columns 12-24, rows 5-14): each test fills in what
// the scanner saw of the piece. The path a moving scanner about 1 m up took along the room's left
// side (map frame).
struct AgainstTheWall {
  static constexpr int h = 20;
  explicit AgainstTheWall(int w)
      : layout(walled_room(w, h)), grid(voxels(w, h, 50)), geo({0.0, 0.0}, 0.05, w, h) {
    for (int r = 1; r < h - 1; ++r) {
      layout.at(25, r) = Cell::kWall;
      fill_column(grid, 25, r, 0.0, 2.4);
    }
    for (int r = 5; r <= 14; ++r)
      for (int c = 12; c <= 24; ++c) layout.at(c, r) = Cell::kFurniture;
  }
  Grid<Cell> layout;
  cloud::VoxelGrid grid;
  GridGeometry geo;
};
const std::vector<Eigen::Vector3d> kLeftSidePath{{0.2, 0.3, 1.0}, {0.2, 0.5, 1.0}, {0.2, 0.7, 1.0}};

// A moving scanner about 1 m up sees a cabinet (1.1 m) against a wall as its front face only:
// its top is above the scanner, its body an unseen pocket, and the beams graze the wall above
// it in single returns (1.8 m) in the cells beside the wall. Along the path, a cell without data
// takes the top of the nearest surface within 0.8 m (the front face) before the nearer stray's:
// the cabinet is one object from its face to the strays' cells against the wall (those keep
// their own height). From fixed positions the nearest data decides as before, and the strays'
// height cuts the body along the wall off the cabinet.
TEST(Objects, AMovingScannersStraysOffTheWallDoNotCutTheCabinetsBody) {
  AgainstTheWall t(30);
  for (int r = 5; r <= 14; ++r) {
    for (int c = 12; c <= 13; ++c) fill_column(t.grid, c, r, 0.0, 1.1);  // the front face
    fill_column(t.grid, 24, r, 1.8, 1.85, 1);                            // a stray off the wall
  }
  const auto cabinet = [&](bool moving) {
    const auto res = extract_objects(t.layout, t.geo, t.grid, flat_layers(), every_size(),
                                     kLeftSidePath, {false, moving});
    int best = 0;
    double z = 0.0;
    for (const auto& o : res.objects)
      if (o.kind == ObjectKind::kFurniture && o.cells > best) best = o.cells, z = o.z_max_m;
    return std::pair{best, z};
  };
  const auto [moving_cells, moving_z] = cabinet(true);
  EXPECT_EQ(moving_cells, 12 * 10);
  EXPECT_NEAR(moving_z, 1.1, 0.06);
  EXPECT_LT(cabinet(false).first, 12 * 10 * 3 / 4);  // the body along the wall cut off
}

// A shelf (1.8 m) against a wall one cell thick, seen as its front face only: its body is an
// unseen pocket. Behind the wall, in the next room, a cabinet (0.8 m) seen whole. Along a path,
// the body's cells take the top of the nearest data reached through furniture cells (the
// shelf's face), not the cabinet's across the wall, nearer in a straight line: the shelf is one
// object and the cabinet another. From fixed positions the straight line decides as before, and
// the body goes with the cabinet (the join across the wall's one cell).
TEST(Objects, AShelfsUnseenBodyTakesItsOwnFacesTopNotTheOneAcrossTheWall) {
  AgainstTheWall t(34);
  for (int r = 5; r <= 14; ++r) {
    for (int c = 12; c <= 13; ++c) fill_column(t.grid, c, r, 0.0, 1.8);  // the shelf's face
    for (int c = 26; c <= 29; ++c) {                                     // the cabinet
      t.layout.at(c, r) = Cell::kFurniture;
      fill_column(t.grid, c, r, 0.0, 0.8);
    }
  }
  const auto cells_of = [&](bool moving) {
    const auto res = extract_objects(t.layout, t.geo, t.grid, flat_layers(), every_size(),
                                     kLeftSidePath, {false, moving});
    const auto object_at = [&](int c, int r) -> FurnitureObject {
      for (const auto& o : res.objects)
        if (o.id == res.labels.at(c, r)) return o;
      return {};
    };
    return std::pair{object_at(13, 10), object_at(27, 10)};
  };
  const auto [shelf, cabinet] = cells_of(true);
  EXPECT_EQ(shelf.cells, 13 * 10);
  EXPECT_NEAR(shelf.z_max_m, 1.8, 0.06);
  EXPECT_EQ(cabinet.cells, 4 * 10);
  EXPECT_NEAR(cabinet.z_max_m, 0.8, 0.06);
  EXPECT_LT(cells_of(false).first.cells, 13 * 10);
}

// A shelf (1.8 m) against a wall, seen by a moving scanner as its front face only. One row of the
// face (a cell the rotated face crosses at a corner) holds its lower samples only, up to 1.3 m.
// The body's cells behind that row take the face's top (the median of the face cells around the
// nearest one), not that cell's: the shelf is one object, not a strip cut off by the height rule.
TEST(Objects, AShelfsBodyTakesItsFacesTopNotThatOfACellItCrossesAtACorner) {
  AgainstTheWall t(30);
  for (int r = 5; r <= 14; ++r)
    for (int c = 12; c <= 13; ++c) fill_column(t.grid, c, r, 0.0, r == 9 ? 1.3 : 1.8);
  const auto res = extract_objects(t.layout, t.geo, t.grid, flat_layers(), every_size(),
                                   kLeftSidePath, {false, true});
  const int body = res.labels.at(20, 9);
  ASSERT_NE(body, 0);
  EXPECT_EQ(res.labels.at(20, 5), body);
  EXPECT_EQ(res.labels.at(20, 14), body);
  for (const auto& o : res.objects)
    if (o.id == body) {
      EXPECT_GE(o.cells, 13 * 10 - 2);  // the lower face cells may stand apart
      EXPECT_NEAR(o.z_max_m, 1.8, 0.06);
    }
}

// Without scanner positions (ScanTraits::peel_strays) on a dense scan: a cabinet (1.1 m) against
// a wall seen as its front face only, and beside the wall a strip of returns off the wall above
// it (1.8 m, 3 points a column: more than a stray's). The body's cells take the top of the nearest
// surface away from the wall (the front), not the nearer strip's: one object, 1.1 m high, and the
// strip keeps its own height.
TEST(Objects, WithoutPositionsAHiddenBodyTakesTheTopOfASurfaceAwayFromTheWall) {
  AgainstTheWall t(30);
  for (int r = 5; r <= 14; ++r) {
    for (int c = 12; c <= 13; ++c) fill_column(t.grid, c, r, 0.0, 1.1, 6);  // the front face
    fill_column(t.grid, 24, r, 1.8, 1.85, 3);                               // returns off the wall
  }
  for (int r = 0; r < t.h; ++r)
    for (int c = 0; c < t.layout.width; ++c)
      if (t.layout.at(c, r) == Cell::kFree) fill_column(t.grid, c, r, 0.0, 0.05, 6);  // the floor
  const auto cabinet = [&](bool peel) {
    const auto res = extract_objects(t.layout, t.geo, t.grid, flat_layers(), every_size(), {},
                                     {true, false, peel});
    const int id = res.labels.at(13, 9);
    for (const auto& o : res.objects)
      if (o.id == id) return std::pair{o.cells, o.z_max_m};
    return std::pair{std::int64_t{0}, 0.0};
  };
  const auto [cells, z] = cabinet(true);
  EXPECT_EQ(cells, 12 * 10);  // face and body; the strip along the wall apart
  EXPECT_NEAR(z, 1.1, 0.06);
  EXPECT_LT(cabinet(false).first, 12 * 10);  // the nearest data decides: the strip's top cuts it
}
