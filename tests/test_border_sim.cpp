// Room border closure (lib/border): accuracy on simulated scenes (lib/sim), and the border
// analysis's other components in the object list.
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

// Accuracy on simulated scenes (lib/sim): 20 random furnished rooms (some L-shaped, rotated,
// with doors to a corridor), scanned from inside without tilt so the map frame is the scene frame.
// The targets: Hausdorff <= 0.15 m to the true polygon (wall faces), area error <= 3 %,
// every door of the room found as an opening. The figures are printed and listed in
// docs/border-closure.md. Every scene closes, every door is found and no other opening is
// reported; the targets are met on every scene whose layout (lib/layout) covers the room (asserted
// per scene) and, since the polygon bridges the shadows objects in the room cast on a wall, on all
// 20. On 2 of the 20 the layout leaves 4-5 % of the room unknown (seed 9, an L with a sloped
// ceiling; seed 17, the shadow of a pillar): those are counted, not asserted one by one.
//
// INDOORMAP_BORDER_DEBUG=DIR prints the figures of every scene and writes DIR/sim_<seed>.png
// (INDOORMAP_BORDER_DEBUG_SEED=N: only that scene; INDOORMAP_BORDER_DEBUG_BOX=x0,y0,x1,y1: a
// close-up of that box in map metres).
namespace {

// The figures of the border closure on the random scenes of seeds [first, last].
struct SimBorderFigures {
  int scenes = 0, closed = 0, doors = 0, doors_found = 0, within_h = 0, within_a = 0;
  int covered = 0;             // scenes whose layout leaves less than 1 % of the room unknown
  int spurious = 0;            // openings more than 0.4 m from every door of the room
  std::vector<double> hs, as;  // Hausdorff [m] and |area error| of the closed scenes, sorted
  double median_h() const { return hs.empty() ? 1e9 : hs[hs.size() / 2]; }
  double median_a() const { return as.empty() ? 1e9 : as[as.size() / 2]; }
};

// With assert_covered, the targets are asserted on each scene whose layout covers the room.
SimBorderFigures border_on_sim_scenes(std::uint64_t first, std::uint64_t last,
                                      bool assert_covered) {
  SimBorderFigures f;
  for (std::uint64_t seed = first; seed <= last; ++seed) {
    sim::Scene scene = sim::random_scene(seed, {.rooms = 1, .scanner_in_corridor = false});
    scene.tilt = {};
    scene.scanner.azimuth_step_deg = scene.scanner.elevation_step_deg = 0.4;
    const sim::SimResult s = sim::simulate(scene);
    PointCloud cloud;
    cloud.points = s.points;
    cloud.scanners = s.scanner_positions_m;
    const auto m = layout::make_map(std::move(cloud), {});
    const auto r = border::close_border(m);
    ++f.scenes;
    const sim::Scene norm = sim::normalised(scene);
    const sim::Room* room = nullptr;
    for (const auto& rm : norm.rooms)
      if (rm.kind == sim::RoomKind::kRoom) room = &rm;
    if (room == nullptr) {
      ADD_FAILURE() << "seed " << seed << ": no room in the scene";
      continue;
    }
    // The share of the true room that the layout leaves unknown (not wall, furniture or free).
    std::int64_t in_room = 0, unknown = 0;
    for (int row = 0; row < m.geometry.height(); ++row)
      for (int col = 0; col < m.geometry.width(); ++col)
        if (indoormap::contains(room->polygon, m.geometry.center_of({col, row}))) {
          ++in_room;
          unknown += m.layout.layout.at(col, row) == Cell::kUnknown;
        }
    const double unknown_share = in_room ? static_cast<double>(unknown) / in_room : 1.0;
    const char* debug_dir = std::getenv("INDOORMAP_BORDER_DEBUG");
    const char* debug_seed = std::getenv("INDOORMAP_BORDER_DEBUG_SEED");
    if (debug_dir && (!debug_seed || std::to_string(seed) == debug_seed))
      debug_picture(std::string(debug_dir) + "/sim_" + std::to_string(seed) + ".png",
                    m.layout.layout, m.geometry, r, room->polygon);
    if (!r.closed) {
      std::cout << "[ sim ] seed " << seed << ": not closed: " << r.reason << "\n";
      continue;
    }
    ++f.closed;
    const auto match = sim::evaluate_rooms({{room->name, "room", room->polygon}}, {r.polygon_m});
    if (match.size() != 1u) {
      ADD_FAILURE() << "seed " << seed << ": " << match.size() << " room matches";
      continue;
    }
    f.hs.push_back(match[0].hausdorff_m);
    f.as.push_back(std::abs(match[0].area_error_rel));
    f.within_h += match[0].hausdorff_m <= 0.15;
    f.within_a += std::abs(match[0].area_error_rel) <= 0.03;
    if (unknown_share < 0.01) {
      ++f.covered;
      if (assert_covered) {
        EXPECT_LE(match[0].hausdorff_m, 0.15) << "seed " << seed;
        EXPECT_LE(std::abs(match[0].area_error_rel), 0.03) << "seed " << seed;
        EXPECT_TRUE(r.warnings.empty()) << "seed " << seed << ": " << r.warnings[0];
      }
    }
    if (debug_dir) {
      const auto chain_match =
          sim::evaluate_rooms({{room->name, "room", room->polygon}}, {r.chain_polygon_m});
      std::cout << "[ sim ] seed " << seed << ": Hausdorff " << match[0].hausdorff_m
                << " m, area error " << 100 * match[0].area_error_rel << " % (chain polygon "
                << chain_match[0].hausdorff_m << " m, " << 100 * chain_match[0].area_error_rel
                << " %), " << room->polygon.size() << " corners, " << r.polygon_m.size()
                << " vertices, " << 100 * unknown_share << " % of the room unknown"
                << (r.warnings.empty() ? "" : "; " + r.warnings[0]) << "; edge offsets"
                << edge_offsets_mm(room->polygon, r.polygon_m) << " mm\n";
      for (const auto& o : r.openings)
        std::cout << "[ sim ]   opening " << fmt(o.a_m) << " - " << fmt(o.b_m) << ", " << o.width_m
                  << " m" << (o.is_door_candidate ? ", door candidate" : "") << "\n";
    }
    const auto& poly = room->polygon;
    std::vector<std::uint8_t> at_door(r.openings.size(), 0);
    for (const auto& d : room->doors) {
      ++f.doors;
      const Eigen::Vector2d a = poly[static_cast<std::size_t>(d.edge)],
                            b = poly[(static_cast<std::size_t>(d.edge) + 1) % poly.size()];
      const Eigen::Vector2d mid = a + (b - a).normalized() * d.at_m;
      bool found = false;
      for (std::size_t i = 0; i < r.openings.size(); ++i)
        if ((0.5 * (r.openings[i].a_m + r.openings[i].b_m) - mid).norm() < 0.4) {
          found = true;
          at_door[i] = 1;
        }
      f.doors_found += found;
    }
    f.spurious += static_cast<int>(std::count(at_door.begin(), at_door.end(), 0));
  }
  std::sort(f.hs.begin(), f.hs.end());
  std::sort(f.as.begin(), f.as.end());
  std::cout << "[ sim ] seeds " << first << "-" << last << ": " << f.scenes << " scenes, "
            << f.closed << " closed; Hausdorff <= 0.15 m: " << f.within_h
            << ", area error <= 3 %: " << f.within_a << " (layout covers the room in " << f.covered
            << "); median Hausdorff " << f.median_h() << " m, median area error "
            << 100 * f.median_a() << " %; worst " << (f.hs.empty() ? 0.0 : f.hs.back()) << " m, "
            << 100 * (f.as.empty() ? 0.0 : f.as.back()) << " %; doors found " << f.doors_found
            << " / " << f.doors << ", other openings " << f.spurious << "\n";
  return f;
}

}  // namespace

TEST(BorderSim, AccuracyOnSimulatedScenes) {
  const SimBorderFigures f = border_on_sim_scenes(1, 20, /*assert_covered=*/true);
  EXPECT_EQ(f.scenes, 20);
  EXPECT_EQ(f.closed, 20);
  EXPECT_EQ(f.doors_found, f.doors);  // every door of every room
  EXPECT_EQ(f.doors, 20);
  // Openings other than doors: before the polygon bridged shadows, the edges of the shadows of
  // a pillar (seed 17: a 1.11 m door candidate) and of a round object (seed 9: 0.47 and 0.52 m).
  EXPECT_EQ(f.spurious, 0);
  EXPECT_GE(f.covered, 18);   // the targets hold on each of them (above)
  EXPECT_EQ(f.within_h, 20);  // 19 before the polygon bridged shadows (seed 17: 0.61 m)
  EXPECT_EQ(f.within_a, 20);  // 19 before (seed 17: -3.3 %)
  EXPECT_LE(f.median_h(), 0.05);
  EXPECT_LE(f.median_a(), 0.02);
}

// The same on 20 further scenes (seeds 21-40), as a check against overfitting the first 20.
// Measured first with the code tuned on seeds 1-20: 19 of 20 within the targets, every door
// found; seed 29 missed (1.12 m, -11.5 %, and one opening at a shadow's edge): a pillar's shadow
// hid a corner of the room. The polygon now takes the walls to their crossing across such a
// shadow (corner_shadow_bridge; seed 29: 0.10 m, -1.8 %), so these scenes are no longer unseen;
// seeds 41-60 (next test) were measured only after that change.
TEST(BorderSim, AccuracyOnFurtherScenes) {
  const SimBorderFigures f = border_on_sim_scenes(21, 40, /*assert_covered=*/true);
  EXPECT_EQ(f.scenes, 20);
  EXPECT_EQ(f.closed, 20);
  EXPECT_EQ(f.doors_found, f.doors);
  EXPECT_EQ(f.spurious, 0);   // 1 before the corner bridge (seed 29)
  EXPECT_EQ(f.within_h, 20);  // 19 before (seed 29)
  EXPECT_EQ(f.within_a, 20);  // 19 before (seed 29)
  EXPECT_LE(f.median_h(), 0.05);
  EXPECT_LE(f.median_a(), 0.02);
}

// Seeds 41-60, first measured with today's code (2026-12-01): 20 of 20 within the targets
// (median 0.019 m, 0.84 %; worst 0.043 m, 1.8 %), every door found, no other opening.
TEST(BorderSim, AccuracyOnUnseenScenes) {
  const SimBorderFigures f = border_on_sim_scenes(41, 60, /*assert_covered=*/true);
  EXPECT_EQ(f.scenes, 20);
  EXPECT_EQ(f.closed, 20);
  EXPECT_EQ(f.doors_found, f.doors);
  EXPECT_EQ(f.spurious, 0);
  EXPECT_EQ(f.within_h, 20);
  EXPECT_EQ(f.within_a, 20);
  EXPECT_LE(f.median_h(), 0.05);
  EXPECT_LE(f.median_a(), 0.02);
}

// Issue 5: the border analysis's other components feed the object list (pcd-to-map's
// objects.json). Inside the room and not already listed: added; outside, or covered by a listed
// object (a pillar found from the layout): not.
TEST(BorderObjects, InteriorComponentsInsideTheRoomJoinTheObjectList) {
  border::BorderResult r;
  r.closed = true;
  r.polygon_m = {{0, 0}, {5, 0}, {5, 4}, {0, 4}};
  const GridGeometry geo({0.0, 0.0}, 0.1, 80, 50);  // 0.1 m cells from the map origin
  auto interior = [&](Eigen::Vector2d lo, Eigen::Vector2d hi, border::ComponentKind k) {
    border::InteriorObject o;
    o.min_m = lo;
    o.max_m = hi;
    o.min = geo.cell_of(lo + Eigen::Vector2d(0.05, 0.05));
    o.max = geo.cell_of(hi - Eigen::Vector2d(0.05, 0.05));
    o.cells = 10;
    o.kind = k;
    return o;
  };
  r.interior_objects = {interior({2.0, 2.0}, {2.4, 2.6}, border::ComponentKind::kRing),
                        interior({3.0, 1.0}, {3.2, 1.2}, border::ComponentKind::kObject),
                        interior({6.0, 1.0}, {6.5, 1.5}, border::ComponentKind::kRing),
                        interior({1.0, 3.0}, {1.2, 3.2}, border::ComponentKind::kObject)};
  objects::ObjectsResult objs;
  objects::FurnitureObject pillar;
  pillar.id = 1;
  pillar.kind = ObjectKind::kPillar;
  pillar.min_m = {0.9, 2.9};
  pillar.max_m = {1.3, 3.3};
  objs.objects.push_back(pillar);
  {  // nothing below objects.min_area_m2: the 0.2 x 0.2 m installation is too small for 0.05
    objects::ObjectsResult big_only = objs;
    app::add_border_objects(big_only, r, 0.05);
    ASSERT_EQ(big_only.objects.size(), 2u);
    EXPECT_EQ(big_only.objects[1].kind, ObjectKind::kColumn);
  }
  app::add_border_objects(objs, r, objects::ObjectParams{}.min_area_m2);
  ASSERT_EQ(objs.objects.size(), 3u);
  EXPECT_EQ(objs.objects[1].id, 2);
  EXPECT_EQ(objs.objects[1].kind, ObjectKind::kColumn);
  EXPECT_NEAR(objs.objects[1].area_m2, 0.4 * 0.6, 1e-9);
  EXPECT_NEAR(objs.objects[1].box.length_m, 0.6, 1e-9);
  EXPECT_NEAR(objs.objects[1].box.angle_deg, 90.0, 1e-9);
  EXPECT_EQ(objs.objects[1].footprint_m.size(), 4u);
  EXPECT_FALSE(objs.objects[1].has_height);
  EXPECT_EQ(objs.objects[2].kind, ObjectKind::kInstallation);
  // Its crop is its box at every height: on a hand-made cloud, exactly the points in the box.
  EXPECT_EQ(objs.objects[1].own_cells.size(), 4u * 6u);
  std::vector<Eigen::Vector3f> pts;
  std::vector<std::size_t> want;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> ux(0.0f, 7.9f), uy(0.0f, 4.9f), uz(-0.5f, 3.5f);
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3f p(ux(rng), uy(rng), uz(rng));
    const CellIndex c = geo.cell_of({p.x(), p.y()});
    if (c.col >= 20 && c.col <= 23 && c.row >= 20 && c.row <= 25) want.push_back(pts.size());
    pts.push_back(p);
  }
  objs.labels = Grid<std::int32_t>(geo.width(), geo.height(), 0);  // the pillar: no cells here
  const auto crops = objects::crop_indices(objs, geo, pts, 0.0);
  ASSERT_EQ(crops.size(), 3u);
  EXPECT_EQ(crops[1], want);
  EXPECT_GT(want.size(), 100u);
  r.closed = false;  // no room polygon: nothing to place them in
  objects::ObjectsResult none;
  app::add_border_objects(none, r, 0.0);
  EXPECT_TRUE(none.objects.empty());
}
