// Room border closure (lib/border): the heavy border and its ring, properties of the chain
// and polygon on generated rooms, door gaps, the choice among several rings, open scans,
// broken preconditions, and the real Jacobs scan.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <set>

#include "border_fixtures.hpp"
#include "indoormap/border/border.hpp"
#include "indoormap/cloud_io/load.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "indoormap/sim/eval.hpp"
#include "indoormap/sim/random_scene.hpp"
#include "indoormap/sim/simulate.hpp"
#include "objects_outputs.hpp"
#include "test_support.hpp"

using namespace indoormap;
using indoormap::Polygon;
using namespace border_fixtures;

TEST(BorderPolygon, HelpersOnHandCheckableShapes) {
  const Polygon sq{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_DOUBLE_EQ(indoormap::signed_area(sq), 4.0);
  EXPECT_DOUBLE_EQ(indoormap::perimeter(sq), 8.0);
  EXPECT_TRUE(indoormap::contains(sq, {1, 1}));
  EXPECT_FALSE(indoormap::contains(sq, {3, 1}));
  EXPECT_TRUE(indoormap::is_simple(sq));
  EXPECT_FALSE(indoormap::is_simple({{0, 0}, {2, 2}, {2, 0}, {0, 2}}));  // bow tie
  EXPECT_NEAR(border::min_area_rect_area(sq), 4.0, 1e-6);
}

TEST(Border, HeavyBorderOfASquareIsARingAroundIt) {
  Grid<Cell> lay(30, 30, Cell::kUnknown);
  for (int r = 10; r < 20; ++r)
    for (int c = 10; c < 20; ++c)
      lay.at(c, r) = (r == 10 || r == 19 || c == 10 || c == 19) ? Cell::kWall : Cell::kFree;
  const auto heavy = border::heavy_border(lay);
  // 5x5 + cross dilation reaches 3 cells out; two 5x5 erosions take 4 back: the ring spans
  // [7, 22] outside and stops one cell inside the marked square.
  EXPECT_TRUE(heavy.at(7, 15));
  EXPECT_TRUE(heavy.at(10, 15));
  EXPECT_FALSE(heavy.at(11, 15));
  EXPECT_FALSE(heavy.at(6, 15));
  EXPECT_FALSE(heavy.at(15, 15));
  const auto mk = border::mark_border_components(lay, heavy);
  ASSERT_EQ(mk.components.size(), 1u);
  EXPECT_EQ(mk.components[0].label, border::kFirstLeeLabel);
  EXPECT_EQ(mk.components[0].switches, 2);
  EXPECT_EQ(mk.components[0].kind, border::ComponentKind::kRing);
  EXPECT_EQ(mk.lee.at(15, 15), border::lee_value(border::LeeMark::kRoom));
  EXPECT_EQ(mk.lee.at(0, 0), border::lee_value(border::LeeMark::kVirgin));
  EXPECT_TRUE(border::is_lee_label(mk.lee.at(7, 15)));
  // Tracing writes the opening lines on the mid-line (row 14 of the ring's rows 7 .. 22) and the
  // wave into the ring.
  Grid<std::int32_t> lee = mk.lee;
  const border::RingTrace t = border::trace_ring(lee, mk.components[0]);
  ASSERT_TRUE(t) << t.why;
  EXPECT_TRUE(t.why.empty());
  EXPECT_GE(t.chain.size(), 4u);
  EXPECT_EQ(lee.at(7, 14), border::lee_value(border::LeeMark::kOpenStart));
  EXPECT_EQ(lee.at(7, 13), border::lee_value(border::LeeMark::kOpenEnd));
  EXPECT_EQ(lee.at(7, 15), 1);  // the wave starts beside the opening line
  EXPECT_TRUE(border::is_lee_distance(lee.at(15, 22)));
}

TEST(Border, TraceRingGivesTheReasonWhenTheRingIsBroken) {
  Grid<Cell> lay(30, 30, Cell::kUnknown);
  for (int r = 10; r < 20; ++r)
    for (int c = 10; c < 20; ++c)
      lay.at(c, r) = (r == 10 || r == 19 || c == 10 || c == 19) ? Cell::kWall : Cell::kFree;
  auto mk = border::mark_border_components(lay, border::heavy_border(lay));
  ASSERT_EQ(mk.components.size(), 1u);
  for (int r = 15; r < 30; ++r)  // cut the ring's top side (rows 19 .. 22) at column 15
    if (mk.lee.at(15, r) == mk.components[0].label)
      mk.lee.at(15, r) = border::lee_value(border::LeeMark::kVirgin);
  const border::RingTrace t = border::trace_ring(mk.lee, mk.components[0]);
  EXPECT_FALSE(t);
  EXPECT_TRUE(t.chain.empty());
  EXPECT_NE(t.why.find("broken"), std::string::npos) << t.why;
}

TEST(Border, FaceFitThresholdsInMetresAreTheTunedCellCountsAtTheDefaultCell) {
  const border::BorderParams p;
  const GridGeometry geo({0, 0}, 0.05, 1, 1);
  EXPECT_EQ(geo.to_cells(p.face_out_reach_m), 4.0);
  EXPECT_EQ(geo.to_cells(p.chamfer_margin_m), 4.0);
  EXPECT_EQ(geo.to_cells(p.recess_margin_m), 4.0);
  // 1.5 cells: no double gives exactly 1.5 at 0.05 m; 0.075 m gives the double just below.
  for (const double v : {p.face_in_margin_m, p.face_tol_m, p.shadow_chain_tol_m})
    EXPECT_DOUBLE_EQ(geo.to_cells(v), 1.5);
}

TEST(Border, PropertiesOnManyGeneratedRooms) {
  int checked = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const bool l_shape = seed % 2 == 0;
    const Room room = make_room(seed, l_shape, static_cast<int>(seed % 3));
    const auto r = border::close_border(room.layout, room.geo, {room.scanner});
    const std::string what = "seed " + std::to_string(seed) + (l_shape ? " (L)" : " (rect)");
    expect_valid_chain(r, what);
    EXPECT_TRUE(indoormap::contains(r.polygon_m, room.scanner)) << what;
    ++checked;
  }
  EXPECT_EQ(checked, 40);
}

TEST(Border, DoorGapsAreFoundWithTheirWidth) {
  int doors = 0, good_width = 0;
  for (std::uint64_t seed = 100; seed < 120; ++seed) {
    const Room room = make_room(seed, seed % 2 == 1, 2);
    const auto r = border::close_border(room.layout, room.geo, {room.scanner});
    ASSERT_TRUE(r.closed) << r.reason;
    for (const auto& d : room.doors) {
      ++doors;
      const Eigen::Vector2d mid = 0.5 * (d.a + d.b);
      const border::Opening* found = nullptr;
      for (const auto& o : r.openings)
        if ((0.5 * (o.a_m + o.b_m) - mid).norm() < 0.3) found = &o;
      std::string seen;
      for (const auto& o : r.openings) {
        const Eigen::Vector2d om = 0.5 * (o.a_m + o.b_m);
        seen += " (" + std::to_string(om.x()) + ", " + std::to_string(om.y()) + ")";
      }
      ASSERT_NE(found, nullptr) << "seed " << seed << ": door at (" << mid.x() << ", " << mid.y()
                                << ") not found; openings at" << seen;
      if (std::abs(found->width_m - d.width_m) <= 0.12 && found->is_door_candidate) ++good_width;
    }
    EXPECT_EQ(r.openings.size(), room.doors.size()) << "seed " << seed << ": spurious openings";
  }
  EXPECT_GE(doors, 30);
  // Every door is found, a door candidate within 0.12 m of its width (before the hand-built walls
  // marked the cell holding the face, 3 of 39 doors with a furniture block or a corner as a jamb
  // measured wider).
  EXPECT_EQ(good_width, doors) << good_width << " of " << doors;
  std::cout << "[ doors ] " << doors << " doors found, " << good_width
            << " with width within 0.12 m\n";
}

TEST(Border, ScannerChoosesAmongSeveralRings) {
  // Two closed rooms side by side: each scanner picks its own room; the other is a ring.
  Grid<Cell> lay(100, 50, Cell::kUnknown);
  auto box = [&](int c0, int c1) {
    for (int r = 10; r < 40; ++r)
      for (int c = c0; c < c1; ++c)
        lay.at(c, r) = (r == 10 || r == 39 || c == c0 || c == c1 - 1) ? Cell::kWall : Cell::kFree;
  };
  box(5, 40);
  box(55, 95);
  const GridGeometry geo({0, 0}, kCell, 100, 50);
  const auto left = border::close_border(lay, geo, {geo.center_of({20, 25})});
  const auto right = border::close_border(lay, geo, {geo.center_of({75, 25})});
  expect_valid_chain(left, "left");
  expect_valid_chain(right, "right");
  EXPECT_LT(left.polygon_m[0].x(), 2.0);
  EXPECT_GT(right.polygon_m[0].x(), 2.5);
  ASSERT_EQ(left.interior_objects.size(), 1u);
  EXPECT_EQ(left.interior_objects[0].kind, border::ComponentKind::kRing);
  // A scanner outside both rooms: no closed border containing it.
  const auto none = border::close_border(lay, geo, {geo.center_of({47, 5})});
  EXPECT_FALSE(none.closed);
  EXPECT_NE(none.reason.find("contains the scanner"), std::string::npos) << none.reason;
}

TEST(Border, RingInsideARoomIsAnInteriorRing) {
  // A room with a large unobserved block in the middle (an installation): its border is a ring
  // inside the room; the scanner beside it picks the room border.
  Grid<Cell> lay(80, 80, Cell::kUnknown);
  for (int r = 5; r < 75; ++r)
    for (int c = 5; c < 75; ++c)
      lay.at(c, r) = (r == 5 || r == 74 || c == 5 || c == 74) ? Cell::kWall : Cell::kFree;
  for (int r = 30; r < 50; ++r)
    for (int c = 30; c < 50; ++c) lay.at(c, r) = Cell::kUnknown;
  const GridGeometry geo({0, 0}, kCell, 80, 80);
  const auto res = border::close_border(lay, geo, {geo.center_of({15, 15})});
  expect_valid_chain(res, "room with installation");
  EXPECT_NEAR(res.area_m2, 3.4 * 3.4, 0.35);
  ASSERT_FALSE(res.interior_objects.empty());
  bool ring = false;
  for (const auto& o : res.interior_objects) ring |= o.kind == border::ComponentKind::kRing;
  EXPECT_TRUE(ring);
}

TEST(Border, OpenScanIsReportedNotThrown) {
  // Two walls of a corner and free space beyond what the walls enclose (an open scan).
  Grid<Cell> lay(60, 60, Cell::kUnknown);
  for (int r = 10; r < 50; ++r)
    for (int c = 10; c < 50; ++c) lay.at(c, r) = (r == 10 || c == 10) ? Cell::kWall : Cell::kFree;
  const GridGeometry geo({0, 0}, kCell, 60, 60);
  const auto res = border::close_border(lay, geo, {geo.center_of({30, 30})});
  EXPECT_FALSE(res.closed);
  EXPECT_FALSE(res.reason.empty());
  EXPECT_NE(res.reason.find("open"), std::string::npos) << res.reason;
  const auto empty = border::close_border(Grid<Cell>(10, 10, Cell::kUnknown),
                                          GridGeometry({0, 0}, kCell, 10, 10), {});
  EXPECT_FALSE(empty.closed);
  EXPECT_NE(empty.reason.find("no marked cells"), std::string::npos);
}

TEST(Border, BrokenPreconditionsThrowTypedErrors) {
  Grid<Cell> lay(10, 10, Cell::kFree);
  EXPECT_THROW(border::close_border(lay, GridGeometry({0, 0}, kCell, 11, 10), {}), Error);
  border::BorderParams p;
  p.dilate_full_size = 4;
  EXPECT_THROW(border::close_border(lay, GridGeometry({0, 0}, kCell, 10, 10), {}, p), UsageError);
  p = {};
  p.door_min_m = 2.0;
  p.door_max_m = 1.0;
  EXPECT_THROW(p.validate(), UsageError);
  p = {};
  p.face_tol_m = 0;
  try {
    p.validate();
    ADD_FAILURE() << "face_tol_m = 0 passed";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("border.face_tol_m"), std::string::npos) << e.what();
  }
  p = {};
  p.corner_shadow_min_turn_deg = 130;  // above the maximum
  EXPECT_THROW(border::close_border(lay, GridGeometry({0, 0}, kCell, 10, 10), {}, p), UsageError);
  p = {};
  p.max_cells = 50;
  EXPECT_THROW(border::close_border(lay, GridGeometry({0, 0}, kCell, 10, 10), {}, p), BudgetError);
}

TEST(BorderJacobs, OneClosedRoughlyRectangularPolygonWithTheDoor) {
  INDOORMAP_REQUIRE_DATA(dir, "jacobs-thermocolorlab");
  auto loaded = cloud_io::load_clouds({dir.string()}, {});
  const auto m = layout::make_map(std::move(loaded.cloud), {});
  const auto r = border::close_border(m);
  expect_valid_chain(r, "jacobs");
  ASSERT_FALSE(m.cloud_map.scanners.empty());
  const Eigen::Vector2d s(m.cloud_map.scanners[0].x(), m.cloud_map.scanners[0].y());
  EXPECT_TRUE(indoormap::contains(r.polygon_m, s));
  const double rect = border::min_area_rect_area(r.polygon_m);
  EXPECT_GT(r.area_m2, 0.85 * rect) << "area " << r.area_m2 << " vs min-area rectangle " << rect;
  EXPECT_GT(r.area_m2, 25.0);
  EXPECT_LT(r.area_m2, 60.0);
  // The door to the corridor: a door-sized opening through which the corridor is seen.
  int doors = 0;
  for (const auto& o : r.openings) doors += o.is_door_candidate ? 1 : 0;
  EXPECT_GE(doors, 1);
  std::cout << "[ jacobs ] area " << r.area_m2 << " m2, perimeter " << r.perimeter_m << " m, "
            << r.openings.size() << " opening(s)\n";
}
