// Tests of the whole-floor simulator parts (lib/sim building.hpp, seen.hpp, mobile.hpp) and the
// TUM trajectory file (lib/formats): storeys on slabs, the seen mask on a scene checked by hand,
// the mobile path and its determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "indoormap/core/errors.hpp"
#include "indoormap/formats/trajectory.hpp"
#include "indoormap/sim/building.hpp"
#include "indoormap/sim/floor_scene.hpp"
#include "indoormap/sim/ground_truth.hpp"
#include "indoormap/sim/mobile.hpp"
#include "indoormap/sim/random_scene.hpp"
#include "indoormap/sim/seen.hpp"
#include "indoormap/sim/world.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using namespace indoormap::sim;

namespace {

/// A coarse, noise-free scanner: cheap scenes.
void coarse(Scene& s, double step_deg = 2.0) {
  s.scanner.azimuth_step_deg = s.scanner.elevation_step_deg = step_deg;
  s.scanner.range_sigma_m = 0;
  s.scanner.mixed_pixel_probability = 0;
}

/// Room A (x in [0, 4], y in [0, 3]) with the scanner at (2, 1.5, 1.3), and room B (x in
/// [4.2, 6.2]) beside it behind A's east wall, with no door: B is free but no ray reaches it.
Scene two_rooms_no_door() {
  Scene s;
  for (int k = 0; k < 2; ++k) {
    Room r;
    r.name = k == 0 ? "a" : "b";
    r.polygon = k == 0 ? Polygon{{0, 0}, {4, 0}, {4, 3}, {0, 3}}
                       : Polygon{{4.2, 0}, {6.2, 0}, {6.2, 3}, {4.2, 3}};
    r.wall_thickness_m = 0.2;
    r.ceiling.height_m = 2.5;
    s.rooms.push_back(r);
  }
  ScannerPose p;
  p.position_m = {2, 1.5, 1.3};
  s.scanners.push_back(p);
  coarse(s, 1.0);
  return s;
}

int count_in(const TruthLayout& L, const Grid<std::uint8_t>& m, double x0, double x1,
             bool want_free_only) {
  int n = 0;
  for (int r = 0; r < L.geometry.height(); ++r)
    for (int c = 0; c < L.geometry.width(); ++c) {
      const double x = L.geometry.center_of({c, r}).x();
      if (x < x0 || x > x1) continue;
      if (want_free_only ? L.cells.at(c, r) == Cell::kFree : m.at(c, r) != 0) ++n;
    }
  return n;
}

}  // namespace

TEST(SimStoreys, SlabBetweenStoreysAndFloorsWhereTheTruthSays) {
  BuildingParams bp;
  bp.random.rooms = 2;
  bp.storeys = 2;
  Building b = random_building(11, bp);
  ASSERT_EQ(b.storeys.size(), 2u);
  // Storey 0 is today's random scene; storey 1 sits one slab above storey 0's highest ceiling.
  const Scene plain = random_scene(11, bp.random);
  EXPECT_EQ(b.storeys[0].scene.furniture.size(), plain.furniture.size());
  EXPECT_EQ(b.storeys[0].scene.rooms[0].polygon, plain.rooms[0].polygon);
  EXPECT_DOUBLE_EQ(b.storeys[0].floor_z_m, 0.0);
  EXPECT_DOUBLE_EQ(b.storeys[1].floor_z_m, b.storeys[0].ceiling_z_m + 0.3);
  EXPECT_GT(b.storeys[1].floor_z_m, 2.8);
  EXPECT_EQ(b.storeys[1].scene.tilt.roll_deg, b.storeys[0].scene.tilt.roll_deg);
  for (auto& st : b.storeys) coarse(st.scene);
  const BuildingSim bs = simulate_building(b);
  ASSERT_EQ(bs.scanner_storey.size(),
            b.storeys[0].scene.scanners.size() + b.storeys[1].scene.scanners.size());
  // Back in the scene frame: both faces of the slab are scanned, nothing lies inside it.
  const Eigen::Matrix3d Rt = tilt_rotation(b.storeys[0].scene.tilt).transpose();
  const double top0 = b.storeys[0].ceiling_z_m, floor1 = b.storeys[1].floor_z_m;
  int on_floor1 = 0, under_slab = 0, inside = 0;
  for (const auto& p : bs.sim.points) {
    const double z = (Rt * p.cast<double>()).z();
    on_floor1 += std::abs(z - floor1) < 0.01;
    under_slab += std::abs(z - top0) < 0.4 && z <= top0 + 0.01;
    inside += z > top0 + 0.02 && z < floor1 - 0.02;
  }
  EXPECT_GT(on_floor1, 500);
  EXPECT_GT(under_slab, 500);
  EXPECT_EQ(inside, 0);
  EXPECT_THROW(random_building(1, {.random = {}, .storeys = 0}), UsageError);
}

TEST(SimSeen, CellsBehindAWallAreNotSeen) {
  const Scene s = normalised(two_rooms_no_door());
  const SimResult sim = simulate(s);
  const TruthLayout L = truth_layout(s, build_geometry(s), 0.05);
  const auto seen = seen_cells(L, sim, s.tilt);
  const int free_a = count_in(L, seen, 0, 4, true), seen_a = count_in(L, seen, 0, 4, false);
  EXPECT_GT(free_a, 4000);  // 80 x 60 cells
  EXPECT_GT(seen_a, 0.97 * free_a);
  EXPECT_EQ(count_in(L, seen, 4.2, 6.2, false), 0);  // room B: free in the truth, never seen
  // Only truth-free cells are ever marked.
  for (std::size_t i = 0; i < seen.data.size(); ++i)
    if (seen.data[i]) {
      ASSERT_EQ(L.cells.data[i], Cell::kFree);
    }
  // With the band cut to 2 cm only floor hits count: fewer cells (the scanner sees no floor
  // within 1.5 m of itself: elevation_min_deg -40 from 1.3 m).
  const auto floor_only =
      seen_cells(L, sim, s.tilt, {}, 0, 0.0, {.min_height_m = -0.05, .max_height_m = 0.02});
  EXPECT_LT(seen_count(floor_only), seen_count(seen));
  EXPECT_GT(seen_count(floor_only), 0);
}

TEST(SimMobile, PathVisitsEveryRoomAndKeepsClearOfWalls) {
  RandomSceneParams rp;
  rp.rooms = 3;
  Scene s = random_scene(5, rp);
  coarse(s);
  const TruthLayout L = truth_layout(s, build_geometry(s), 0.05);
  MobileParams mp;
  const MobilePath path = plan_mobile_path(s, L, mp);
  EXPECT_EQ(path.rooms_visited, 3);
  EXPECT_EQ(path.unreached, 0);
  ASSERT_GT(path.poses.size(), 20u);
  std::vector<int> visits(s.rooms.size(), 0);
  for (std::size_t i = 0; i < path.poses.size(); ++i) {
    const auto& p = path.poses[i].position_m;
    EXPECT_DOUBLE_EQ(p.z(), 1.0);
    const int r = room_at(s, p.head<2>());
    ASSERT_GE(r, 0);
    ++visits[r];
    const CellIndex c = L.geometry.cell_of(p.head<2>());
    EXPECT_EQ(L.cells.at(c.col, c.row), Cell::kFree);
    if (i > 0) {  // a step is at most step_m (a door skips one position)
      const double d = (p - path.poses[i - 1].position_m).norm();
      EXPECT_LE(d, 2 * mp.step_m + 1e-9);
    }
  }
  for (std::size_t r = 0; r < s.rooms.size(); ++r) EXPECT_GT(visits[r], 0) << s.rooms[r].name;
}

TEST(SimMobile, DeterministicAndTheTrajectoryReadsBack) {
  RandomSceneParams rp;
  rp.rooms = 2;
  Scene s = random_scene(8, rp);
  const TruthLayout L = truth_layout(s, build_geometry(s), 0.05);
  MobileParams mp;
  mp.ray_share = 0.005;
  s.scanners = plan_mobile_path(s, L, mp).poses;
  ASSERT_FALSE(s.scanners.empty());
  const SimResult a = simulate_mobile(s, mp), b = simulate_mobile(s, mp);
  ASSERT_EQ(a.points.size(), b.points.size());
  EXPECT_TRUE(a.points == b.points);
  EXPECT_EQ(a.scans.size(), s.scanners.size());
  EXPECT_EQ(a.rays, mobile_ray_count(s, mp));
  const auto traj = trajectory(s.scanners, s.tilt, mp.speed_m_s);
  const fs::path f = test::scratch_dir() / "trajectory.txt";
  formats::write_tum_trajectory(f, traj);
  const auto back = formats::read_trajectory(f);
  EXPECT_EQ(back.format, formats::TrajectoryFormat::kTum);
  ASSERT_EQ(back.positions.size(), traj.size());
  for (std::size_t i = 0; i < back.positions.size(); ++i) {
    EXPECT_NEAR((back.positions[i] - a.scanner_positions_m[i]).norm(), 0, 1e-6);
    EXPECT_NEAR(traj[i].orientation.norm(), 1.0, 1e-6);
    if (i > 0) {
      EXPECT_GT(traj[i].t_s, traj[i - 1].t_s);
    }
  }
  // Each line has 8 columns; bad lines are errors naming the line.
  std::istringstream text(test::read_text(f));
  std::string line;
  std::getline(text, line);
  EXPECT_EQ(line[0], '#');  // the header comment
  std::getline(text, line);
  std::istringstream cols(line);
  int n = 0;
  for (std::string tok; cols >> tok;) ++n;
  EXPECT_EQ(n, 8);
  for (const char* bad :
       {"0 1 2 3 0 0 0 1\n0 1 2 x 0 0 0 1\n", "0 1 2 3 0 0 1\n", "0 1 2 3 0 0 0 2\n"}) {
    test::write_text(f, bad);
    EXPECT_THROW(formats::read_trajectory(f), InputError) << bad;
  }
}

TEST(SimFloorScene, TwoStoreyMobileBuildingWithItsTruth) {
  FloorSceneParams p;
  p.building.random.rooms = 2;
  p.building.storeys = 2;
  p.mobile = true;
  p.mobile_params.ray_share = 0.004;
  const FloorScene f = simulate_floor_scene(3, p);
  ASSERT_EQ(f.truths.size(), 2u);
  ASSERT_EQ(f.paths.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(f.paths[k].rooms_visited, 2);
    EXPECT_EQ(f.building.storeys[k].scene.scanners.size(), f.paths[k].poses.size());
    // Most of the free space of each storey is seen by its own path.
    const auto free = std::count(f.truths[k].layout.cells.data.begin(),
                                 f.truths[k].layout.cells.data.end(), Cell::kFree);
    EXPECT_GT(seen_count(f.truths[k].seen), 0.8 * free) << k;
  }
  EXPECT_EQ(f.sim.sim.scans.size(), f.paths[0].poses.size() + f.paths[1].poses.size());
  // The sensor of storey 1 is 1 m above its floor, in the scene frame.
  const Eigen::Matrix3d Rt = tilt_rotation(f.building.storeys[0].scene.tilt).transpose();
  const Eigen::Vector3d last = Rt * f.sim.sim.scanner_positions_m.back();
  EXPECT_NEAR(last.z(), f.building.storeys[1].floor_z_m + 1.0, 1e-9);
}
