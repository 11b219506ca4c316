// Furniture objects: the paper's two-pass labelling against OpenCV, per-object geometry and
// heights on hand-made grids, height splitting, lamps, exact point crops, object kinds and
// parameter checks (pockets, stray returns and wall faces: test_objects_pockets.cpp; pillars:
// test_objects_pillars.cpp).
#include <gtest/gtest.h>

#include <map>
#include <opencv2/imgproc.hpp>
#include <random>
#include <set>

#include "indoormap/core/errors.hpp"
#include "indoormap/objects/objects.hpp"
#include "objects_fixtures.hpp"

using namespace indoormap;
using namespace indoormap::objects;
using namespace objects_fixtures;

TEST(Label, MatchesOpenCvOnRandomMasks) {
  std::mt19937 rng(21);
  for (int trial = 0; trial < 60; ++trial) {
    const int w = 1 + trial % 37, h = 1 + (trial * 7) % 29;
    std::bernoulli_distribution on(0.3 + 0.4 * (trial % 3) / 2.0);
    Grid<std::uint8_t> m(w, h);
    for (auto& v : m.data) v = on(rng);
    for (auto conn : {Connectivity::k4, Connectivity::k8}) {
      const Labels ours = label_components(m, conn);
      cv::Mat ref;
      const int n = cv::connectedComponents(cv::Mat(h, w, CV_8U, m.data.data()), ref,
                                            conn == Connectivity::k4 ? 4 : 8, CV_32S);
      ASSERT_EQ(ours.count, n - 1);
      // Same partition: a bijection between our labels and OpenCV's.
      std::map<int, int> fwd, back;
      for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
          const int a = ours.labels.at(c, r), b = ref.at<int>(r, c);
          ASSERT_EQ(a == 0, b == 0);
          if (!a) continue;
          auto [it, fresh] = fwd.emplace(a, b);
          ASSERT_EQ(it->second, b);
          auto [it2, fresh2] = back.emplace(b, a);
          ASSERT_EQ(it2->second, a);
        }
      // Raster order: label k first appears before label k + 1.
      int seen = 0;
      for (int v : ours.labels.data) {
        if (v > seen) {
          ASSERT_EQ(v, ++seen);
        }
      }
    }
  }
}

TEST(Label, DiagonalNeighboursJoinOnlyWithEightConnectivity) {
  Grid<std::uint8_t> m(3, 3, 0);
  m.at(0, 0) = m.at(1, 1) = m.at(2, 2) = 1;
  EXPECT_EQ(label_components(m, Connectivity::k4).count, 3);
  EXPECT_EQ(label_components(m, Connectivity::k8).count, 1);
  EXPECT_EQ(label_components(Grid<std::uint8_t>(), Connectivity::k4).count, 0);  // empty: no crash
}

TEST(Objects, GeometryHeightsAndWallContactOnAHandMadeRoom) {
  // 24 x 16 cells of 5 cm; walls on the border. A cabinet 4x2 against the west wall (0.9 m high;
  // 0.2 m deep: a thinner piece along a wall is the wall's face), a table 4x3 in the middle (top
  // 0.75 m, legs only at its corners) with a lamp 1.6 m above.
  const int w = 24, h = 16;
  Grid<Cell> L = walled_room(w, h);
  auto g = voxels(w, h, 60);
  for (int r = 7; r <= 8; ++r)
    for (int c = 1; c <= 4; ++c) {
      L.at(c, r) = Cell::kFurniture;
      fill_column(g, c, r, 0.0, 0.9);
    }
  for (int r = 6; r <= 8; ++r)
    for (int c = 12; c <= 15; ++c) {
      L.at(c, r) = Cell::kFurniture;
      fill_column(g, c, r, 0.70, 0.75);
      fill_column(g, c, r, 2.30, 2.40);  // lamp above: not part of the table
    }
  fill_column(g, 12, 6, 0.0, 0.7);  // one leg
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  ObjectParams p;
  p.min_area_m2 = 0.0;
  p.min_seen_area_m2 = 0.0;
  ObjectsResult res = extract_objects(L, geo, g, flat_layers(), p);
  ASSERT_EQ(res.objects.size(), 2u);
  const auto& table = res.objects[0];  // raster order: row 6 comes first
  const auto& cabinet = res.objects[1];
  EXPECT_EQ(table.id, 1);
  EXPECT_EQ(table.cells, 12);
  EXPECT_EQ(table.start_cell, (CellIndex{12, 6}));
  EXPECT_EQ(table.min_cell, (CellIndex{12, 6}));
  EXPECT_EQ(table.max_cell, (CellIndex{15, 8}));
  EXPECT_NEAR(table.area_m2, 12 * 0.0025, 1e-12);
  EXPECT_NEAR(table.min_m.x(), 0.60, 1e-9);
  EXPECT_NEAR(table.max_m.y(), 0.45, 1e-9);
  EXPECT_NEAR(table.z_max_m, 0.725, 1e-9);  // the top layer's centre, not the lamp
  EXPECT_TRUE(table.on_floor);              // the leg reaches the floor
  EXPECT_FALSE(table.touches_wall);
  // The footprint runs 1/8 cell outside the boundary cells' centres: 4 x 3 cells give
  // (4 - 3/4) x (3 - 3/4) cells.
  EXPECT_NEAR(table.box.length_m, 3.25 * 0.05, 1e-6);
  EXPECT_NEAR(table.box.width_m, 2.25 * 0.05, 1e-6);
  EXPECT_NEAR(table.box.angle_deg, 0.0, 1.0);
  EXPECT_EQ(cabinet.cells, 8);
  EXPECT_TRUE(cabinet.touches_wall);
  EXPECT_NEAR(cabinet.z_max_m, 0.875, 1e-9);
  EXPECT_EQ(cabinet.point_count,
            8u * 2u * 18u);  // 8 columns x 2 points x layers 0..17 (z_min = floor)
  double area2 = 0.0;
  for (std::size_t i = 0; i < table.footprint_m.size(); ++i) {
    const auto& a = table.footprint_m[i];
    const auto& b = table.footprint_m[(i + 1) % table.footprint_m.size()];
    area2 += a.x() * b.y() - b.x() * a.y();
  }
  EXPECT_GT(area2, 0.0);  // counter-clockwise
  EXPECT_NEAR(area2 / 2, 3.25 * 2.25 * 0.0025, 1e-9);
  // A label the inset would split (cells joined at a corner only, 8-connectivity) keeps its cell
  // outline: one polygon around both cells.
  Grid<Cell> diag(6, 6, Cell::kFree);
  diag.at(2, 2) = diag.at(3, 3) = Cell::kFurniture;
  ObjectParams p8;
  p8.connectivity = Connectivity::k8;
  p8.min_area_m2 = 0.0;
  p8.min_seen_area_m2 = 0.0;
  const auto d =
      extract_objects(diag, GridGeometry({0, 0}, 0.05, 6, 6), voxels(6, 6, 30), flat_layers(), p8);
  ASSERT_EQ(d.objects.size(), 1u);
  EXPECT_NEAR(d.objects[0].box.length_m, std::hypot(0.1, 0.1), 0.02);
}

TEST(Objects, ObjectsHighAboveTheFloorAreHanging) {
  // A lamp low enough to reach the furniture band (1.6-1.8 m, nothing below it) and a cupboard
  // standing on the floor: only the lamp is kind "hanging"; the threshold is configurable.
  Grid<Cell> L(12, 6, Cell::kFree);
  auto g = voxels(12, 6, 50);
  for (int r = 2; r <= 3; ++r)
    for (int c = 1; c <= 3; ++c) {
      L.at(c, r) = L.at(c + 6, r) = Cell::kFurniture;
      fill_column(g, c, r, 1.6, 1.8);
      fill_column(g, c + 6, r, 0.0, 1.8);
    }
  const GridGeometry geo({0, 0}, 0.05, 12, 6);
  ObjectParams p;
  p.min_area_m2 = 0.0;
  p.min_seen_area_m2 = 0.0;
  auto res = extract_objects(L, geo, g, flat_layers(), p);
  ASSERT_EQ(res.objects.size(), 2u);
  EXPECT_EQ(res.objects[0].kind, ObjectKind::kHanging);
  EXPECT_FALSE(res.objects[0].on_floor);
  EXPECT_NEAR(res.objects[0].z_min_m, 1.6, 1e-9);
  EXPECT_EQ(res.objects[1].kind, ObjectKind::kFurniture);
  p.hanging_min_clearance_m = 1.7;
  res = extract_objects(L, geo, g, flat_layers(), p);
  EXPECT_EQ(res.objects[0].kind, ObjectKind::kFurniture);
}

namespace {

// A lamp 1.2 x 0.3 m at 1.95-2.05 m, its end against a wall whose face (two cells, floor to
// 2.05 m) joins its piece; a shelf with face and sides to the floor, top-only cells over its
// hidden floor. The floor is seen elsewhere, under the lamp when floor_under_lamp.
struct LampScene {
  Grid<Cell> L{40, 20, Cell::kFree};
  cloud::VoxelGrid g = voxels(40, 20, 50);
  explicit LampScene(bool floor_under_lamp) {
    for (int r = 0; r < L.height; ++r)
      for (int c = 0; c < L.width; ++c)
        if (floor_under_lamp || c < 2 || c > 25 || r < 4 || r > 9) fill_column(g, c, r, 0.0, 0.05);
    for (int c = 2; c <= 25; ++c)
      for (int r = 4; r <= 9; ++r) {
        L.at(c, r) = Cell::kFurniture;
        fill_column(g, c, r, 1.95, 2.05);
      }
    for (int r = 4; r <= 9; ++r)
      for (int c = 0; c <= 1; ++c) {
        L.at(c, r) = c == 0 ? Cell::kWall : Cell::kFurniture;
        fill_column(g, c, r, 0.05, 2.05);
      }
    for (int c = 30; c <= 37; ++c)
      for (int r = 12; r < L.height; ++r) {
        L.at(c, r) = Cell::kFurniture;
        for (int z = 0; z < 50; ++z) g.counts[(z * g.ny + r) * g.nx + c] = 0;
        fill_column(g, c, r, r == 12 || c == 30 || c == 37 ? 0.0 : 1.75, 1.8);
      }
  }
  std::vector<FurnitureObject> objects(const std::vector<Eigen::Vector3d>& scanners = {}) const {
    const ObjectParams p{.min_area_m2 = 0.0, .min_seen_area_m2 = 0.0};
    const GridGeometry geo({0, 0}, 0.05, L.width, L.height);
    return extract_objects(L, geo, g, flat_layers(), p, scanners).objects;
  }
};

}  // namespace

TEST(Objects, ALampWithSomeCellsOfTheWallFaceItTouchesIsHanging) {
  // Most of the lamp's cells hang: "hanging" from 1.95 m, not furniture on the floor with the
  // wall's face in its piece. The shelf's top over a hidden floor is no lamp.
  const auto objs = LampScene(true).objects();
  ASSERT_EQ(objs.size(), 2u);
  EXPECT_EQ(objs[0].kind, ObjectKind::kHanging);
  EXPECT_EQ(objs[0].cells, 25 * 6);
  EXPECT_FALSE(objs[0].on_floor);
  EXPECT_NEAR(objs[0].z_min_m, 1.95, 1e-9);
  EXPECT_EQ(objs[1].kind, ObjectKind::kFurniture);
  EXPECT_TRUE(objs[1].on_floor);
}

TEST(Objects, ALampOverTheScannerIsHangingThoughItsFloorWasNotSeen) {
  // The scanner stands under the lamp (1.2 m): the floor beneath lies in its blind cone. It had
  // that floor in sight, so the lamp hangs; without its position nothing says the floor is there,
  // and the piece stands on the floor. The shelf's face and sides block the line to its floor.
  const LampScene scene(false);
  const auto with = scene.objects({{0.7, 0.35, 1.2}});
  ASSERT_EQ(with.size(), 2u);
  EXPECT_EQ(with[0].kind, ObjectKind::kHanging);
  EXPECT_NEAR(with[0].z_min_m, 1.95, 1e-9);
  EXPECT_EQ(with[1].kind, ObjectKind::kFurniture);
  const auto without = scene.objects();
  ASSERT_EQ(without.size(), 2u);
  EXPECT_EQ(without[0].kind, ObjectKind::kFurniture);
  EXPECT_TRUE(without[0].on_floor);
}

TEST(Objects, TouchingObjectsOfDifferentHeightsAreSplit) {
  const int w = 10, h = 6;
  Grid<Cell> L(w, h, Cell::kFree);
  auto g = voxels(w, h, 40);
  for (int r = 1; r <= 4; ++r)
    for (int c = 1; c <= 8; ++c) {
      L.at(c, r) = Cell::kFurniture;
      fill_column(g, c, r, 0.0, c <= 5 ? 0.75 : 0.45);  // table | chair
    }
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  ObjectParams p;
  p.min_area_m2 = 0.0;
  p.min_seen_area_m2 = 0.0;
  auto res = extract_objects(L, geo, g, flat_layers(), p);
  ASSERT_EQ(res.objects.size(), 2u);
  EXPECT_NEAR(res.objects[0].z_max_m, 0.725, 1e-9);
  EXPECT_NEAR(res.objects[1].z_max_m, 0.425, 1e-9);
  p.split_height_step_m = 0.0;  // the paper's plain 2D labelling
  EXPECT_EQ(extract_objects(L, geo, g, flat_layers(), p).objects.size(), 1u);
}

TEST(Objects, RotatedRectangleGivesItsOrientedBox) {
  const int w = 80, h = 80;
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  Grid<Cell> L(w, h, Cell::kFree);
  auto g = voxels(w, h, 20);
  const double ang = 30.0 * M_PI / 180.0;
  const Eigen::Vector2d centre(2.0, 2.0), u(std::cos(ang), std::sin(ang)),
      v(-std::sin(ang), std::cos(ang));
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const Eigen::Vector2d d = geo.center_of({c, r}) - centre;
      if (std::abs(d.dot(u)) <= 0.6 && std::abs(d.dot(v)) <= 0.25) {
        L.at(c, r) = Cell::kFurniture;
        fill_column(g, c, r, 0.0, 0.5);
      }
    }
  auto res = extract_objects(L, geo, g, flat_layers(), {});
  ASSERT_EQ(res.objects.size(), 1u);
  const auto& b = res.objects[0].box;
  EXPECT_NEAR(b.angle_deg, 30.0, 3.0);
  EXPECT_NEAR(b.length_m, 1.2, 0.08);
  EXPECT_NEAR(b.width_m, 0.5, 0.08);
  EXPECT_NEAR(b.center_m.x(), 2.0, 0.05);
  EXPECT_NEAR(b.center_m.y(), 2.0, 0.05);
}

TEST(Objects, NoFurnitureIsAnEmptyListAndSmallObjectsAreDropped) {
  Grid<Cell> L(5, 5, Cell::kFree);
  auto g = voxels(5, 5, 10);
  const GridGeometry geo({0.0, 0.0}, 0.05, 5, 5);
  EXPECT_TRUE(extract_objects(L, geo, g, flat_layers(), {}).objects.empty());
  L.at(2, 2) = Cell::kFurniture;  // 0.0025 m2 < the default minimum area
  auto res = extract_objects(L, geo, g, flat_layers(), {});
  EXPECT_TRUE(res.objects.empty());
  EXPECT_EQ(res.labels.at(2, 2), 0);
  EXPECT_TRUE(extract_objects(Grid<Cell>(), GridGeometry({0, 0}, 0.05, 0, 0), voxels(0, 0, 0),
                              flat_layers(), {})
                  .objects.empty());
  EXPECT_THROW(extract_objects(L, GridGeometry({0, 0}, 0.05, 4, 4), g, flat_layers(), {}), Error);
}

TEST(Objects, LampsHangBelowTheCeilingWithSpaceUnderThem) {
  // Ceiling at 2.6 m (layer 52), furniture band up to 2.0 m. A lamp (2.3-2.35 m) over free
  // cells, a second one over a table (the cells are shared: the lamp is not in `labels`), the top
  // of a wardrobe that reaches 2.3 m (continuous from the floor: not a lamp), and a lamp within
  // three cells of a wall (the wall's face: left out).
  const int w = 60, h = 30;
  Grid<Cell> L(w, h, Cell::kFree);
  auto g = voxels(w, h, 54);
  cloud::LayerAnalysis layers = flat_layers();
  layers.furniture_band.lo_layer = 2;
  layers.furniture_band.hi_layer = 39;
  layers.ceiling_layer = 52;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) fill_column(g, c, r, 2.60, 2.65);  // the ceiling
  for (int r = 0; r < h; ++r) {
    L.at(0, r) = Cell::kWall;
    fill_column(g, 0, r, 0.0, 2.65);
  }
  auto lamp = [&](int c0, int r0, int cw, int rh) {
    for (int r = r0; r < r0 + rh; ++r)
      for (int c = c0; c < c0 + cw; ++c) fill_column(g, c, r, 2.31, 2.36);  // layer 46
  };
  lamp(10, 5, 12, 4);  // 0.6 x 0.2 m over free cells
  for (int r = 15; r < 25; ++r)
    for (int c = 10; c < 30; ++c) {
      L.at(c, r) = Cell::kFurniture;
      fill_column(g, c, r, 0.70, 0.75);
    }
  lamp(14, 18, 12, 4);  // over the table
  for (int r = 5; r < 10; ++r)
    for (int c = 40; c < 48; ++c) {
      L.at(c, r) = Cell::kFurniture;
      fill_column(g, c, r, 0.0, 2.30);
    }
  lamp(1, 20, 3, 6);  // next to the wall
  const GridGeometry geo({0.0, 0.0}, 0.05, w, h);
  const auto res = extract_objects(L, geo, g, layers, {});
  std::vector<const FurnitureObject*> lamps;
  for (const auto& o : res.objects)
    if (o.kind == ObjectKind::kLamp) lamps.push_back(&o);
  ASSERT_EQ(lamps.size(), 2u);
  for (const auto* o : lamps) {
    EXPECT_FALSE(o->on_floor);
    EXPECT_NEAR(o->z_min_m, 2.30, 1e-9);
    EXPECT_NEAR(o->z_max_m, 2.35, 1e-9);
    EXPECT_EQ(o->own_cells.size(), 48u);
    EXPECT_NEAR(o->box.length_m, 0.55, 1e-6);  // through the boundary cells' centres
    EXPECT_NEAR(o->box.width_m, 0.15, 1e-6);
    for (const auto& c : o->own_cells) EXPECT_NE(res.labels.at(c), o->id);
  }
  EXPECT_EQ(lamps[0]->min_cell, (CellIndex{10, 5}));
  EXPECT_EQ(lamps[1]->min_cell, (CellIndex{14, 18}));
  // The table is still one object under its lamp; the crop of the lamp holds its own points.
  std::vector<Eigen::Vector3f> pts{{0.8f, 1.0f, 2.32f}, {0.8f, 1.0f, 0.72f}, {0.8f, 1.0f, 2.62f}};
  const auto crops = crop_indices(res, geo, pts, 0.0);
  const std::size_t k = static_cast<std::size_t>(lamps[1]->id - 1);
  ASSERT_LT(k, crops.size());
  EXPECT_EQ(crops[k], std::vector<std::size_t>{0});
  const int table = res.labels.at(20, 20);
  ASSERT_GT(table, 0);
  EXPECT_EQ(res.objects[static_cast<std::size_t>(table - 1)].cells, 200);
  EXPECT_EQ(crops[static_cast<std::size_t>(table - 1)], std::vector<std::size_t>{1});
  ObjectParams off;
  off.lamp_max_extent_m = 0.0;
  for (const auto& o : extract_objects(L, geo, g, layers, off).objects)
    EXPECT_NE(o.kind, ObjectKind::kLamp);
}

TEST(Objects, CropHoldsExactlyThePointsOfTheRegion) {
  const int w = 20, h = 20;
  const GridGeometry geo({-0.5, -0.5}, 0.05, w, h);
  Grid<Cell> L(w, h, Cell::kFree);
  auto g = voxels(w, h, 30);
  for (int r = 5; r <= 8; ++r)
    for (int c = 5; c <= 9; ++c) {
      L.at(c, r) = Cell::kFurniture;
      fill_column(g, c, r, 0.0, 0.60);  // heights 0.1 .. 0.6 -> z_min = floor, z_max = 0.575
    }
  ObjectParams p;
  p.min_area_m2 = 0.0;
  p.min_seen_area_m2 = 0.0;
  auto res = extract_objects(L, geo, g, flat_layers(), p);
  ASSERT_EQ(res.objects.size(), 1u);
  const auto& o = res.objects[0];
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> ux(-0.5f, 0.5f), uz(-0.2f, 1.2f);
  std::vector<Eigen::Vector3f> pts(20000);
  for (auto& q : pts) q = {ux(rng), ux(rng), uz(rng)};
  const double margin = 0.05;
  auto crops = crop_indices(res, geo, pts, margin);
  ASSERT_EQ(crops.size(), 1u);
  // Brute force: cell within one cell (the margin) of a footprint cell, z within the margin.
  std::set<std::size_t> expected;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const CellIndex c = geo.cell_of({pts[i].x(), pts[i].y()});
    bool near = false;
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc)
        near |= res.labels.contains(c.col + dc, c.row + dr) &&
                res.labels.at(c.col + dc, c.row + dr) == o.id;
    if (near && pts[i].z() >= o.z_min_m - margin && pts[i].z() <= o.z_max_m + margin)
      expected.insert(i);
  }
  EXPECT_EQ(std::set<std::size_t>(crops[0].begin(), crops[0].end()), expected);
  EXPECT_GT(expected.size(), 100u);
}

TEST(ObjectKind, NamesRoundTripAndUnknownNamesAreNullopt) {
  for (const ObjectKind k : kObjectKinds) EXPECT_EQ(parse_object_kind(to_string(k)), k);
  EXPECT_EQ(to_string(ObjectKind::kFurniture), "furniture");
  EXPECT_EQ(to_string(ObjectKind::kInstallation), "installation");
  EXPECT_FALSE(parse_object_kind("sofa"));
  EXPECT_FALSE(stands_on_floor(ObjectKind::kHanging));
  EXPECT_FALSE(stands_on_floor(ObjectKind::kLamp));
  EXPECT_TRUE(stands_on_floor(ObjectKind::kPillar));
}

TEST(ObjectParams, ValidatedByExtractObjects) {
  EXPECT_NO_THROW(validate(ObjectParams{}));
  ObjectParams bad;
  bad.top_percentile = 101;
  EXPECT_THROW(validate(bad), UsageError);
  for (auto set : {+[](ObjectParams& q) { q.neck_width_m = -0.1; },
                   +[](ObjectParams& q) { q.neck_min_part_m2 = 0.0; }}) {
    ObjectParams q;
    set(q);
    try {
      validate(q);
      ADD_FAILURE() << "expected UsageError";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("objects.neck_"), std::string::npos) << e.what();
    }
  }
  const Grid<Cell> layout(2, 2, Cell::kFree);
  const GridGeometry geo({0.0, 0.0}, 0.1, 2, 2);
  EXPECT_THROW(extract_objects(layout, geo, cloud::VoxelGrid{}, cloud::LayerAnalysis{}, bad),
               UsageError);  // checked first, before the sizes
}
