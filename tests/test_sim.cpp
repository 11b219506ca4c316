// Tests of the scene simulator (lib/sim, apps/scene-sim): ray-casting geometry on scenes checked
// by hand, the scanner model, determinism, the ground-truth layout (files: test_sim_output.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "indoormap/core/errors.hpp"
#include "indoormap/sim/eval.hpp"
#include "indoormap/sim/ground_truth.hpp"
#include "indoormap/sim/output.hpp"
#include "indoormap/sim/random_scene.hpp"
#include "indoormap/sim/simulate.hpp"
#include "indoormap/sim/world.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using namespace indoormap::sim;

namespace {

/// A 4 m x 3 m room (x in [0, 4], y in [0, 3]), ceiling 2.5 m, walls 0.2 m, one scanner at
/// (2, 1.5, 1.5); no noise, no mixed pixels, no tilt.
Scene box_room() {
  Scene s;
  Room r;
  r.name = "box";
  r.polygon = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  r.wall_thickness_m = 0.2;
  r.ceiling.height_m = 2.5;
  s.rooms.push_back(r);
  ScannerPose p;
  p.position_m = {2, 1.5, 1.5};
  s.scanners.push_back(p);
  s.scanner.range_sigma_m = 0;
  s.scanner.mixed_pixel_probability = 0;
  s.scanner.azimuth_step_deg = 1;
  s.scanner.elevation_step_deg = 1;
  s.scanner.range_min_m = 0.1;
  return s;
}

Furniture make(FurnitureType type, Eigen::Vector2d c, Eigen::Vector2d size, double height,
               std::string id = "") {
  Furniture f;
  f.id = std::move(id);
  f.type = type;
  f.center_m = c;
  f.size_m = size;
  f.height_m = height;
  return f;
}

std::optional<RayCaster::Hit> cast(const Scene& scene, Eigen::Vector3d o, Eigen::Vector3d d) {
  const SceneGeometry g = build_geometry(normalised(scene));
  RayCaster rc(g);
  return rc.cast(o, d.normalized(), 100.0);
}

bool point_in_solid(const Solid& s, const Eigen::Vector3d& p, double shrink) {
  if (p.z() <= s.z0_m + shrink || p.z() >= s.z1_m - shrink) return false;
  if (s.shape == Solid::Shape::kCylinder)
    return (p.head<2>() - s.center_m).norm() < s.radius_m - shrink;
  const auto& F = s.footprint;
  for (std::size_t k = 0; k < F.size(); ++k) {
    const Eigen::Vector2d e = F[(k + 1) % F.size()] - F[k];
    const Eigen::Vector2d n = Eigen::Vector2d(e.y(), -e.x()).normalized();
    if (n.dot(p.head<2>() - F[k]) > -shrink) return false;
  }
  return true;
}

}  // namespace

// ---- Ray casting on hand-checkable scenes
// ---------------------------------------------------------

TEST(SimRayCast, HitsWallsFloorAndCeilingAtKnownRanges) {
  const Scene s = box_room();
  const Eigen::Vector3d o(2, 1.5, 1.5);
  auto h = cast(s, o, {1, 0, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 2.0, 1e-9);  // inner face of the east wall, x = 4
  EXPECT_GE(h->solid, 0);
  h = cast(s, o, {0, -1, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 1.5, 1e-9);
  h = cast(s, o, {0, 0, 1});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 1.0, 1e-9);  // ceiling at 2.5
  EXPECT_GE(h->cap, 0);
  h = cast(s, o, {0, 0, -1});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 1.5, 1e-9);  // floor
  // Oblique: towards the corner (4, 3) at scanner height: distance sqrt(2^2 + 1.5^2) = 2.5.
  h = cast(s, o, {2, 1.5, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 2.5, 1e-9);
  // 30 degrees down towards the west wall: floor at 1.5 / sin(30) = 3 > 2 / cos(30) = 2.309.
  const double a = 30 * std::numbers::pi / 180;
  h = cast(s, o, {-std::cos(a), 0, -std::sin(a)});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 2.0 / std::cos(a), 1e-9);
}

TEST(SimRayCast, BoxOccludesTheWallBehindIt) {
  Scene s = box_room();
  s.furniture.push_back(make(FurnitureType::kCabinet, {3.0, 1.5}, {0.4, 0.6}, 1.7));
  const Eigen::Vector3d o(2, 1.5, 1.5);
  auto h = cast(s, o, {1, 0, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 0.8, 1e-9);  // front face at x = 2.8
  const SceneGeometry g = build_geometry(normalised(s));
  EXPECT_EQ(g.solids[h->solid].furniture, 0);
  // Over the cabinet (top at 1.7; the ray is at 1.86 above its front edge) to the wall.
  h = cast(s, o, Eigen::Vector3d(4, 1.5, 2.4) - o);
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, (Eigen::Vector3d(4, 1.5, 2.4) - o).norm(), 1e-9);
  // Aimed lower, at (4, 1.5, 2.0), it hits the cabinet's front face x = 2.8 at z = 1.7.
  h = cast(s, o, Eigen::Vector3d(4, 1.5, 2.0) - o);
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 0.4 * (Eigen::Vector3d(4, 1.5, 2.0) - o).norm(), 1e-9);
  // A bin (cylinder r = 0.2 at (2, 2.5)) in front of the north wall.
  Furniture bin;
  bin.type = FurnitureType::kBin;
  bin.center_m = {2, 2.5};
  bin.radius_m = 0.2;
  bin.height_m = 1.6;
  s.furniture.push_back(bin);
  h = cast(s, o, {0, 1, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 0.8, 1e-9);
}

TEST(SimRayCast, TableIsATopOnLegsSoRaysPassBelowIt) {
  Scene s = box_room();
  s.furniture.push_back(make(FurnitureType::kTable, {3.0, 1.5}, {1.0, 1.0}, 0.75));
  // Horizontal ray at 0.4 m height passes between the legs and hits the east wall.
  auto h = cast(s, {2, 1.5, 0.4}, {1, 0, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 2.0, 1e-9);
  // Straight down onto the table top (z = 0.75) from above.
  h = cast(s, {3, 1.5, 1.5}, {0, 0, -1});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 0.75, 1e-9);
}

TEST(SimRayCast, DoorLeadsIntoTheCorridorAndWindowsLetRaysOut) {
  Scene s = box_room();
  Room& r = s.rooms[0];
  r.doors.push_back({0, 2.0, 1.0, 0.0, 2.0});    // south wall, x in [1.5, 2.5]
  r.windows.push_back({2, 2.0, 1.0, 1.0, 2.0});  // north edge (4,3)->(0,3): x in [1.5, 2.5]
  Room corridor;
  corridor.name = "corridor";
  corridor.kind = RoomKind::kCorridor;
  corridor.polygon = {{-1, -2.2}, {5, -2.2}, {5, -0.2}, {-1, -0.2}};
  corridor.ceiling.height_m = 2.4;
  s.rooms.push_back(corridor);
  const Eigen::Vector3d o(2, 1.5, 1.5);
  // Through the door at 1.5 m height to the corridor's far wall at y = -2.2.
  auto h = cast(s, o, {0, -1, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 3.7, 1e-9);
  // Above the door (top 2.0) the lintel stops the ray at the room's wall face y = 0.
  h = cast(s, o, Eigen::Vector3d(2, 0, 2.3) - o);
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, (Eigen::Vector3d(2, 0, 2.3) - o).norm(), 1e-9);
  // Out through the window (sill 1.0, top 2.0): no return.
  EXPECT_FALSE(cast(s, o, {0, 1, 0}));
  // Below the sill: the wall.
  h = cast(s, o, Eigen::Vector3d(2, 3, 0.8) - o);
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, (Eigen::Vector3d(2, 3, 0.8) - o).norm(), 1e-9);
}

TEST(SimRayCast, SlopedCeilingAndLShapedRoom) {
  Scene s = box_room();
  // L shape: the north-east quarter x > 2, y > 1.5 is cut away.
  s.rooms[0].polygon = {{0, 0}, {4, 0}, {4, 1.5}, {2, 1.5}, {2, 3}, {0, 3}};
  s.rooms[0].ceiling = {2.5, 10.0, 0.0};  // rises towards +x from 2.5 m at x = 0
  s.scanners[0].position_m = {1, 1, 1.5};
  require_valid(s);
  // Straight up at x = 1: ceiling at 2.5 + tan(10 deg) * 1.
  auto h = cast(s, {1, 1, 1.5}, {0, 0, 1});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 1.0 + std::tan(10 * std::numbers::pi / 180), 1e-9);
  // Towards +y from (3, 0.5): the inner wall of the L at y = 1.5.
  h = cast(s, {3, 0.5, 1.0}, {0, 1, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 1.0, 1e-9);
}

TEST(SimScanner, KnownWallPointAppearsInTheCloud) {
  Scene s = box_room();
  const SimResult r = simulate(s);
  // Azimuth 0, elevation 0 -> (4, 1.5, 1.5); azimuth 90, elevation 0 -> (2, 3, 1.5).
  auto has = [&](Eigen::Vector3f q) {
    for (const auto& p : r.points)
      if ((p - q).norm() < 1e-5f) return true;
    return false;
  };
  EXPECT_TRUE(has({4, 1.5f, 1.5f}));
  EXPECT_TRUE(has({2, 3, 1.5f}));
  EXPECT_EQ(r.rays, 360u * 101u);
  EXPECT_EQ(r.points.size(), r.rays);  // a closed room returns every ray
  EXPECT_EQ(r.mixed_pixels, 0u);
}

TEST(SimScanner, TiltRotatesPointsAndScannerAboutTheOrigin) {
  Scene s = box_room();
  s.tilt = {0.6, -0.8};
  const SimResult r = simulate(s);
  const Eigen::Matrix3d R = tilt_rotation(s.tilt);
  EXPECT_NEAR((r.scanner_positions_m[0] - R * s.scanners[0].position_m).norm(), 0, 1e-12);
  // Every point, rotated back, lies on a surface of the box room.
  for (std::size_t i = 0; i < r.points.size(); i += 7) {
    const Eigen::Vector3d p = R.transpose() * r.points[i].cast<double>();
    const double d = std::min({std::abs(p.x()), std::abs(p.x() - 4), std::abs(p.y()),
                               std::abs(p.y() - 3), std::abs(p.z()), std::abs(p.z() - 2.5)});
    ASSERT_LT(d, 1e-4) << "point " << i << " = " << p.transpose();
  }
  // The scanner's own frame is the tilted one: its horizontal ray at azimuth 0 is level there.
  bool found = false;
  const Eigen::Vector3f sp = r.scanner_positions_m[0].cast<float>();
  for (const auto& p : r.points)
    if (std::abs(p.z() - sp.z()) < 1e-5f && std::abs(p.y() - sp.y()) < 1e-5f && p.x() > sp.x())
      found = true;
  EXPECT_TRUE(found);
}

TEST(SimScanner, NoPointInsideASolidOfTheOffice) {
  // The office from scenes/office.yaml is exercised through the app; here the same kind of
  // furnished room is built in code, noise-free, and every point is checked against every solid.
  Scene s = random_scene(11, {});
  s.scanner.range_sigma_m = 0;
  s.scanner.mixed_pixel_probability = 0;
  s.scanner.azimuth_step_deg = s.scanner.elevation_step_deg = 0.5;
  s.tilt = {};
  const SimResult r = simulate(s);
  ASSERT_GT(r.points.size(), 10000u);
  const SceneGeometry g = build_geometry(normalised(s));
  for (std::size_t i = 0; i < r.points.size(); i += 3) {
    const Eigen::Vector3d p = r.points[i].cast<double>();
    ASSERT_GT(p.z(), -1e-4);
    for (std::size_t k = 0; k < g.solids.size(); ++k)
      ASSERT_FALSE(point_in_solid(g.solids[k], p, 1e-4))
          << "point " << p.transpose() << " inside solid " << k;
  }
}

TEST(SimScanner, NoiseMixedPixelsAndRangeLimits) {
  Scene s = box_room();
  s.furniture.push_back(make(FurnitureType::kCabinet, {3.0, 1.5}, {0.4, 0.6}, 2.0));
  s.scanner.range_sigma_m = 0.01;
  s.scanner.mixed_pixel_probability = 1.0;
  s.scanner.mixed_pixel_min_jump_m = 0.3;
  s.scanner.range_max_m = 2.2;
  const SimResult r = simulate(s);
  EXPECT_GT(r.mixed_pixels, 0u);
  EXPECT_LT(r.mixed_pixels, r.points.size() / 10);
  for (const auto& p : r.points)
    ASSERT_LE((p.cast<double>() - s.scanners[0].position_m).norm(), 2.2 + 1e-6);
  EXPECT_LT(r.points.size(), r.rays);  // the far corners are out of range
}

TEST(SimScanner, SectorsSplitEveryPosition) {
  Scene s = box_room();
  s.scanners.push_back(s.scanners[0]);
  s.scanners[1].position_m = {1, 1, 1.2};
  SimOptions o;
  o.sector_deg = 40;
  const SimResult r = simulate(s, o);
  ASSERT_EQ(r.scans.size(), 18u);
  std::size_t next = 0;
  for (const auto& b : r.scans) {
    EXPECT_EQ(b.begin, next);
    next = b.end;
  }
  EXPECT_EQ(next, r.points.size());
  EXPECT_EQ(r.scans[9].scanner, 1);
  EXPECT_DOUBLE_EQ(r.scans[1].azimuth_begin_deg, 40.0);
}

TEST(SimScanner, DeterministicForAFixedSeed) {
  Scene s = random_scene(5, {});
  s.scanner.azimuth_step_deg = s.scanner.elevation_step_deg = 0.5;
  const SimResult a = simulate(s), b = simulate(s);
  ASSERT_EQ(a.points.size(), b.points.size());
  EXPECT_EQ(
      std::memcmp(a.points.data(), b.points.data(), a.points.size() * sizeof(Eigen::Vector3f)), 0);
  s.seed = 6;  // another noise seed, same scene
  const SimResult c = simulate(s);
  EXPECT_NE(std::memcmp(a.points.data(), c.points.data(),
                        std::min(a.points.size(), c.points.size()) * 12),
            0);
}

TEST(SimScanner, RefusesScenesAboveTheRayBudget) {
  Scene s = box_room();
  s.scanner.azimuth_step_deg = s.scanner.elevation_step_deg = 0.01;
  SimOptions o;
  o.max_rays = 1'000'000;
  EXPECT_THROW(simulate(s, o), BudgetError);
}

// ---- Scenes
// -----------------------------------------------------------------------------------------

TEST(SimScene, CheckFindsBrokenScenes) {
  Scene s = box_room();
  EXPECT_TRUE(check_scene(s).empty());
  s.rooms[0].doors.push_back({0, 3.9, 1.0, 0.0, 2.0});  // runs past the edge's end
  auto p = check_scene(s);
  ASSERT_FALSE(p.empty());
  EXPECT_EQ(p[0].key, "rooms[0].doors[0].at_m");
  s = box_room();
  s.rooms[0].polygon = {{0, 0}, {4, 3}, {4, 0}, {0, 3}};  // a bow tie
  EXPECT_FALSE(check_scene(s).empty());
  s = box_room();
  s.scanners[0].position_m = {9, 9, 1};
  p = check_scene(s);
  ASSERT_FALSE(p.empty());
  EXPECT_EQ(p[0].key, "scanners[0].position");
  s = box_room();
  s.furniture.push_back(
      make(FurnitureType::kCabinet, {1, 1}, {0.5, 0.5}, 3.0));  // above the ceiling
  EXPECT_FALSE(check_scene(s).empty());
}

TEST(SimScene, ClockwisePolygonsKeepTheirDoors) {
  Scene s = box_room();
  s.rooms[0].polygon = {{0, 0}, {0, 3}, {4, 3}, {4, 0}};  // clockwise; edge 2 = (4,3)->(4,0)... no:
  // edges: 0 (0,0)->(0,3), 1 (0,3)->(4,3), 2 (4,3)->(4,0), 3 (4,0)->(0,0). Door on edge 3 at 1 m
  // from (4,0), i.e. centred at x = 3 on the south wall.
  s.rooms[0].doors.push_back({3, 1.0, 0.8, 0.0, 2.0});
  Room corridor;
  corridor.polygon = {{-1, -2.2}, {5, -2.2}, {5, -0.2}, {-1, -0.2}};
  s.rooms.push_back(corridor);
  ASSERT_TRUE(check_scene(s).empty());
  auto h = cast(s, {3, 1.5, 1.0}, {0, -1, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 3.7, 1e-9);  // through the door
  h = cast(s, {1, 1.5, 1.0}, {0, -1, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t_m, 1.5, 1e-9);  // wall elsewhere
}

TEST(SimScene, RandomScenesAreValidAndReproducible) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    RandomSceneParams p;
    p.rooms = 1 + static_cast<int>(seed % 6);
    const Scene s = random_scene(seed, p);
    const auto problems = check_scene(s);
    EXPECT_TRUE(problems.empty()) << "seed " << seed << ": " << problems.front().key << ": "
                                  << problems.front().problem;
    EXPECT_EQ(s.rooms.size(), static_cast<std::size_t>(p.rooms + 1));
    const Scene t = random_scene(seed, p);
    ASSERT_EQ(s.furniture.size(), t.furniture.size());
    for (std::size_t i = 0; i < s.furniture.size(); ++i)
      EXPECT_EQ(s.furniture[i].center_m, t.furniture[i].center_m);
  }
  EXPECT_THROW(random_scene(1, {.rooms = 0}), UsageError);
}

// ---- Ground truth
// -----------------------------------------------------------------------------------

TEST(SimTruth, LayoutMatchesTheScene) {
  Scene s = box_room();
  s.rooms[0].doors.push_back({0, 2.0, 1.0, 0.0, 2.0});    // x in [1.5, 2.5] on the south wall
  s.rooms[0].windows.push_back({2, 1.0, 1.0, 1.0, 2.0});  // north wall, x in [2.5, 3.5]
  s.furniture.push_back(make(FurnitureType::kCabinet, {1.0, 2.5}, {0.6, 0.4}, 1.2, "cab"));
  s.furniture.push_back(make(FurnitureType::kTable, {3.0, 1.5}, {1.0, 0.8}, 0.75, "tab"));
  Furniture lamp = make(FurnitureType::kLamp, {1.0, 1.0}, {1.2, 0.3}, 0, "lamp");
  s.furniture.push_back(lamp);
  const Scene n = normalised(s);
  const SceneGeometry g = build_geometry(n);
  const TruthLayout t = truth_layout(n, g, 0.1, 0.5);
  EXPECT_DOUBLE_EQ(t.geometry.origin_m().x(), -0.7);
  EXPECT_DOUBLE_EQ(t.geometry.cell_m(), 0.1);
  auto at = [&](double x, double y) { return t.cells.at(t.geometry.cell_of({x, y})); };
  EXPECT_EQ(at(2.05, 1.55), Cell::kFree);
  EXPECT_EQ(at(1.05, 2.45), Cell::kFurniture);  // cabinet
  EXPECT_EQ(at(2.95, 1.45), Cell::kFurniture);  // table footprint, although one sees under it
  EXPECT_EQ(at(1.05, 1.05), Cell::kFree);       // under the lamp
  EXPECT_EQ(at(-0.05, 1.55), Cell::kWall);      // west wall, x in [-0.2, 0]
  EXPECT_EQ(at(4.15, 3.15), Cell::kWall);       // mitred north-east corner
  EXPECT_EQ(at(2.05, -0.05), Cell::kFree);      // door opening
  EXPECT_EQ(at(1.05, -0.05), Cell::kWall);      // beside the door
  EXPECT_EQ(at(3.05, 3.05), Cell::kWall);       // window: wall below the sill
  EXPECT_EQ(at(-0.45, 1.55), Cell::kUnknown);   // outside
  // Item list.
  const auto items = furniture_truth(n);
  ASSERT_EQ(items.size(), 3u);
  EXPECT_DOUBLE_EQ(items[0].z_min_m, 0.0);
  EXPECT_DOUBLE_EQ(items[0].z_max_m, 1.2);
  EXPECT_NEAR(std::abs(signed_area(items[1].footprint)), 0.8, 1e-12);
  EXPECT_FALSE(items[2].on_floor);
  EXPECT_NEAR(items[2].z_max_m, 2.5 - 0.5, 1e-12);
}

// ---- Files: PCD, 3DTK, the app
// -------------------------------------------------------------------------
