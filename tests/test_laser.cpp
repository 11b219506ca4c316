// lib/laser (scans, Bresenham, HIMM and log-odds mapping, ray casting, self-consistency) on
// hand-checked inputs. The CARMEN reader and the shared logs: test_carmen.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "indoormap/core/errors.hpp"
#include "indoormap/laser/bresenham.hpp"
#include "indoormap/laser/mappers.hpp"
#include "indoormap/laser/pose_refine.hpp"
#include "indoormap/laser/raycast.hpp"
#include "test_support.hpp"

namespace {

using namespace indoormap;
using namespace indoormap::laser;
constexpr double kPi = std::numbers::pi;

// One beam (or a few) from a pose: the scan type's smallest use.
LaserScan beam_scan(double x, double y, double theta, std::vector<float> ranges,
                    double angle_min = 0.0, double increment = 0.0) {
  LaserScan s;
  s.ranges_m = std::move(ranges);
  s.angle_min_rad = angle_min;
  s.angle_increment_rad = increment;
  s.max_range_m = 80.0;
  s.robot_pose_map = {x, y, theta};
  return s;
}

OccupancyGridParams fixed_grid(int w, int h, double cell_m = 1.0) {
  OccupancyGridParams p;
  p.cell_m = cell_m;
  p.fixed_geometry = GridGeometry({0.0, 0.0}, cell_m, w, h);
  return p;
}

// ------------------------------------------------------------------------------- Bresenham
TEST(Bresenham, HandExample) {
  const auto cells = bresenham_line({0, 0}, {5, 2});
  const std::vector<CellIndex> want = {{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 2}, {5, 2}};
  EXPECT_EQ(cells, want);
  EXPECT_EQ(bresenham_line({3, 3}, {3, 3}), (std::vector<CellIndex>{{3, 3}}));
}

// Reference: the exact rasterisation rule, in integers. Along the major axis every cell is
// visited once; along the minor axis the cell is within half a cell of the true line between the
// centres (|2 (m - m0) D - 2 (M - M0) d| <= D), which also puts every cell in the segment's
// supercover. Both ends are included and the line is 8-connected.
TEST(Bresenham, MatchesExactReferenceOnRandomSegments) {
  std::mt19937 rng(20240601);
  std::uniform_int_distribution<int> coord(-60, 60);
  for (int k = 0; k < 20000; ++k) {
    const CellIndex a{coord(rng), coord(rng)}, b{coord(rng), coord(rng)};
    const auto cells = bresenham_line(a, b);
    const long dx = b.col - a.col, dy = b.row - a.row;
    const bool x_major = std::labs(dx) >= std::labs(dy);
    const long major = x_major ? std::labs(dx) : std::labs(dy);
    ASSERT_EQ(static_cast<long>(cells.size()), major + 1);
    ASSERT_EQ(cells.front(), a);
    ASSERT_EQ(cells.back(), b);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const long u = cells[i].col - a.col, v = cells[i].row - a.row;
      // |v * dx - u * dy| <= max(|dx|, |dy|) / 2, the minor-axis distance to the line, doubled.
      ASSERT_LE(std::labs(2 * (v * dx - u * dy)), major) << "segment " << k;
      if (i > 0) {
        const long sc = cells[i].col - cells[i - 1].col, sr = cells[i].row - cells[i - 1].row;
        ASSERT_LE(std::labs(sc), 1);
        ASSERT_LE(std::labs(sr), 1);
        ASSERT_EQ(x_major ? std::labs(sc) : std::labs(sr), 1);  // one step along the major axis
      }
    }
  }
}

// ------------------------------------------------------------------------------- HIMM
// Grid of 1 m cells, laser at (0.5, 1.5) looking along +x, one beam of 4 m: it ends in cell
// (4, 1). The four cells before get 7 - 1 = 6 (free), the end 7 + 3 = 10 (occupied).
TEST(Himm, OneBeamHandChecked) {
  HimmMapper m(fixed_grid(10, 3), {});
  m.integrate(beam_scan(0.5, 1.5, 0.0, {4.0f}));
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(m.value({c, 1}), 6) << c;
    EXPECT_EQ(m.cell_at({c, 1}), Cell::kFree);
  }
  EXPECT_EQ(m.value({4, 1}), 10);
  EXPECT_EQ(m.cell_at({4, 1}), Cell::kWall);
  EXPECT_EQ(m.value({5, 1}), 7);
  EXPECT_EQ(m.cell_at({5, 1}), Cell::kUnknown);
  EXPECT_EQ(m.cell_at({4, 0}), Cell::kUnknown);
  // Three more: the hit saturates at 15 (10, 13, 15, 15), the free cells go down to 3.
  for (int k = 0; k < 3; ++k) m.integrate(beam_scan(0.5, 1.5, 0.0, {4.0f}));
  EXPECT_EQ(m.value({4, 1}), 15);
  EXPECT_EQ(m.value({2, 1}), 3);
  // A longer beam passes the 15 cell: it is never decreased; the next cell is hit.
  m.integrate(beam_scan(0.5, 1.5, 0.0, {6.0f}));
  EXPECT_EQ(m.value({4, 1}), 15);
  EXPECT_EQ(m.value({5, 1}), 6);
  EXPECT_EQ(m.value({6, 1}), 10);
  const OccupancyMap snap = m.snapshot();
  EXPECT_EQ(snap.raw.at(4, 1), 15.0f);
  EXPECT_EQ(snap.cells.at(6, 1), Cell::kWall);
}

TEST(Himm, WithoutFreezeA15CellIsDecreased) {
  HimmParams p;
  p.freeze_at_max = false;
  HimmMapper m(fixed_grid(10, 3), p);
  for (int k = 0; k < 4; ++k) m.integrate(beam_scan(0.5, 1.5, 0.0, {4.0f}));
  m.integrate(beam_scan(0.5, 1.5, 0.0, {6.0f}));
  EXPECT_EQ(m.value({4, 1}), 14);
}

// Beyond the maximum range (44 m) a return is no obstacle, but the beam clears up to 44 m, and a
// beam ending outside the grid still clears the cells inside it.
TEST(Himm, MaxRangeAndBeamsLeavingTheGrid) {
  OccupancyGridParams grid = fixed_grid(10, 3);
  grid.clear_no_return = true;  // off by default (real logs); here: clear up to 44 m
  HimmMapper m(grid, {});
  m.integrate(beam_scan(0.5, 1.5, 0.0, {50.0f}));
  for (int c = 0; c < 10; ++c) EXPECT_EQ(m.value({c, 1}), 6) << c;
  m.integrate(beam_scan(0.5, 1.5, 0.0, {20.0f}));  // a hit 20 m away: outside the grid
  for (int c = 0; c < 10; ++c) EXPECT_EQ(m.value({c, 1}), 5) << c;
  // From outside the grid the beam is clipped to it: the inside part is cleared.
  m.integrate(beam_scan(-5.5, 1.5, 0.0, {8.0f}));  // ends at x = 2.5: cells 0, 1 free, 2 hit
  EXPECT_EQ(m.value({0, 1}), 4);
  EXPECT_EQ(m.value({1, 1}), 4);
  EXPECT_EQ(m.value({2, 1}), 8);
}

// The mask: the cell (5, 3), never observed, has its four neighbours hit from four sides.
TEST(Himm, MaskFillsACellSurroundedByObstacles) {
  for (bool mask : {true, false}) {
    HimmParams p;
    p.mask = mask;
    HimmMapper m(fixed_grid(11, 7), p);
    m.integrate(beam_scan(0.5, 3.5, 0.0, {4.2f}));       // hit (4, 3)
    m.integrate(beam_scan(9.5, 3.5, kPi, {2.8f}));       // hit (6, 3)
    m.integrate(beam_scan(5.5, 0.5, kPi / 2, {1.8f}));   // hit (5, 2)
    m.integrate(beam_scan(5.5, 6.5, -kPi / 2, {2.2f}));  // hit (5, 4)
    for (CellIndex c : {CellIndex{4, 3}, {6, 3}, {5, 2}, {5, 4}}) EXPECT_EQ(m.value(c), 10);
    EXPECT_EQ(m.value({5, 3}), mask ? 15 : 7);
    EXPECT_EQ(m.cell_at({5, 3}), mask ? Cell::kWall : Cell::kUnknown);
  }
}

TEST(Himm, ParamsAreValidated) {
  HimmParams p;
  p.max_value = 16;
  EXPECT_THROW(HimmMapper(fixed_grid(3, 3), p), UsageError);
  OccupancyGridParams g;
  g.cell_m = 0.0;
  EXPECT_THROW(HimmMapper(g, {}), UsageError);
  HimmMapper m(fixed_grid(3, 3), {});
  EXPECT_THROW(m.integrate(LaserScan{}), UsageError);
}

// ------------------------------------------------------------------------------- log-odds
TEST(LogOdds, HandExample) {
  LogOddsMapper m(fixed_grid(10, 3), {});
  m.integrate(beam_scan(0.5, 1.5, 0.0, {4.0f}));
  const float miss = std::log(0.4f / 0.6f), hit = std::log(0.7f / 0.3f);
  EXPECT_NEAR(m.log_odds({0, 1}), miss, 1e-6);
  EXPECT_NEAR(m.log_odds({3, 1}), miss, 1e-6);
  EXPECT_NEAR(m.log_odds({4, 1}), hit, 1e-6);
  EXPECT_TRUE(std::isnan(m.log_odds({5, 1})));
  EXPECT_EQ(m.cell_at({0, 1}), Cell::kFree);  // p = 0.4 < 0.45
  EXPECT_EQ(m.cell_at({4, 1}), Cell::kWall);  // p = 0.7 > 0.6
  EXPECT_EQ(m.cell_at({5, 1}), Cell::kUnknown);
  m.integrate(beam_scan(0.5, 1.5, 0.0, {4.0f}));
  EXPECT_NEAR(m.log_odds({4, 1}), 2 * hit, 1e-5);
  for (int k = 0; k < 5; ++k) m.integrate(beam_scan(0.5, 1.5, 0.0, {4.0f}));
  EXPECT_NEAR(m.log_odds({4, 1}), std::log(0.97 / 0.03), 1e-5);  // clamped at p_max
  EXPECT_NEAR(m.log_odds({0, 1}), std::log(0.12 / 0.88), 1e-5);  // clamped at p_min
  // Unlike HIMM a saturated cell can change its mind: enough misses make it free.
  for (int k = 0; k < 12; ++k) m.integrate(beam_scan(0.5, 1.5, 0.0, {6.0f}));
  EXPECT_EQ(m.cell_at({4, 1}), Cell::kFree);
}

// Unclamped (clamp: false, laser-to-map's default) a cell's class is its evidence over all its
// observations: hit 8 times, then passed 10 times (a thing that stood there and went away), it sums
// 8 logit(0.7) + 10 logit(0.4) = 6.78 - 4.05 = 2.72 > logit(0.6): still a wall, as 8 of the 18
// beams that reached it say. Clamped, the hits stop counting at logit(0.97) = 3.48 and the cell
// ends free at 3.48 - 4.05 = -0.58: it follows its last observations.
TEST(LogOdds, UnclampedCellWeighsEveryObservationAlike) {
  LogOddsParams unclamped;
  unclamped.clamp = false;
  LogOddsMapper all(fixed_grid(10, 3), unclamped), recent(fixed_grid(10, 3), {});
  for (int k = 0; k < 8; ++k)
    for (auto* m : {&all, &recent}) m->integrate(beam_scan(0.5, 1.5, 0.0, {4.0f}));
  for (int k = 0; k < 10; ++k)
    for (auto* m : {&all, &recent}) m->integrate(beam_scan(0.5, 1.5, 0.0, {6.0f}));
  const float miss = std::log(0.4f / 0.6f), hit = std::log(0.7f / 0.3f);
  EXPECT_NEAR(all.log_odds({4, 1}), 8 * hit + 10 * miss, 1e-4);
  EXPECT_EQ(all.cell_at({4, 1}), Cell::kWall);
  EXPECT_NEAR(all.log_odds({0, 1}), 18 * miss, 1e-4);  // no floor either
  EXPECT_NEAR(recent.log_odds({4, 1}), std::log(0.97 / 0.03) + 10 * miss, 1e-4);
  EXPECT_EQ(recent.cell_at({4, 1}), Cell::kFree);
  // Twelve more passes outweigh the eight hits: 2.72 + 12 logit(0.4) = -2.14, free.
  for (int k = 0; k < 12; ++k) all.integrate(beam_scan(0.5, 1.5, 0.0, {6.0f}));
  EXPECT_EQ(all.cell_at({4, 1}), Cell::kFree);
}

// ------------------------------------------------------------------------------- growing
TEST(Occupancy, GridGrowsToFitScansAndKeepsValues) {
  OccupancyGridParams p;
  p.cell_m = 0.5;
  p.grow_margin_m = 1.0;
  auto m = make_mapper(MapperKind::kHimm, p);
  m->integrate(beam_scan(0.25, 0.25, 0.0, {2.0f}));
  const GridGeometry g0 = m->geometry();
  const CellIndex hit0 = g0.cell_of({2.25, 0.25});
  EXPECT_EQ(m->cell_at(hit0), Cell::kWall);
  m->integrate(beam_scan(-30.0, 12.0, kPi / 2, {10.0f}));
  const GridGeometry& g1 = m->geometry();
  EXPECT_GT(g1.width(), g0.width());
  EXPECT_TRUE(g1.contains(g1.cell_of({-30.0, 22.0})));
  EXPECT_EQ(m->cell_at(g1.cell_of({2.25, 0.25})), Cell::kWall);  // kept through the regrid
  EXPECT_EQ(m->cell_at(g1.cell_of({-30.0, 22.1})), Cell::kWall);
  // Cells stay aligned to multiples of cell_m.
  EXPECT_NEAR(std::remainder(g1.origin_m().x(), 0.5), 0.0, 1e-9);
}

TEST(Occupancy, BudgetIsCheckedBeforeAllocating) {
  OccupancyGridParams p;
  p.cell_m = 0.01;
  p.max_cells = 1000;
  auto m = make_mapper(MapperKind::kLogOdds, p);
  EXPECT_THROW(m->integrate(beam_scan(0, 0, 0, {30.0f})), BudgetError);
  EXPECT_THROW(bound_for_positions({{0, 0}, {1e6, 0}}, 40.0, 0.05, 1'000'000), BudgetError);
  const GridGeometry g = bound_for_positions({{0, 0}, {10, 5}}, 4.0, 0.5, 1'000'000);
  EXPECT_LE(g.origin_m().x(), -4.0);
  EXPECT_GE(g.corner_of({g.width(), g.height()}).y(), 9.0);
}

// ------------------------------------------------------------------------------- ray casting
TEST(RayCast, HitsTheFirstWallCell) {
  Grid<Cell> cells(10, 10, Cell::kFree);
  for (int r = 0; r < 10; ++r) cells.at(6, r) = Cell::kWall;
  const GridGeometry g({0.0, 0.0}, 0.5, 10, 10);  // wall column covers x in [3, 3.5)
  EXPECT_NEAR(cast_ray(cells, g, {0.25, 0.25}, 0.0, 20.0), 2.75, 1e-12);
  EXPECT_NEAR(cast_ray(cells, g, {0.25, 0.25}, kPi / 4, 20.0), 2.75 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(cast_ray(cells, g, {0.25, 0.25}, kPi, 20.0), 20.0, 1e-12);  // leaves the grid
  EXPECT_NEAR(cast_ray(cells, g, {0.25, 0.25}, 0.0, 1.0), 1.0, 1e-12);    // beyond max range
  EXPECT_NEAR(cast_ray(cells, g, {3.2, 1.0}, 0.0, 5.0), 0.0, 1e-12);      // starts in a wall
}

// A map built from scans simulated in it agrees with them.
TEST(Consistency, ScansCastInAKnownRoomAgreeWithTheirMap) {
  const GridGeometry g({0.0, 0.0}, 0.05, 200, 120);
  Grid<Cell> room(200, 120, Cell::kFree);
  for (int c = 0; c < 200; ++c) room.at(c, 0) = room.at(c, 119) = Cell::kWall;
  for (int r = 0; r < 120; ++r) room.at(0, r) = room.at(199, r) = Cell::kWall;
  for (int r = 30; r < 60; ++r)
    for (int c = 90; c < 110; ++c) room.at(c, r) = Cell::kWall;  // a pillar
  std::vector<LaserScan> scans;
  for (double x : {1.5, 3.0, 7.0, 8.5})
    for (double y : {1.0, 4.5}) {
      LaserScan s = beam_scan(x, y, 0.3, {}, -kPi, 2 * kPi / 360);
      s.max_range_m = 30.0;
      for (int i = 0; i < 360; ++i) {  // to the middle of the wall cell, as a laser would
        const RayHit h =
            cast_ray_cell(g, s.laser_pose_map().position_m(), 0.3 + s.beam_angle_rad(i), 30.0,
                          [&](CellIndex c) { return is_obstacle(room.at(c)); });
        s.ranges_m.push_back(static_cast<float>(0.5 * (h.entry_m + h.exit_m)));
      }
      scans.push_back(std::move(s));
    }
  for (MapperKind kind : {MapperKind::kHimm, MapperKind::kLogOdds}) {
    OccupancyGridParams p;
    p.cell_m = 0.05;
    auto m = make_mapper(kind, p);
    for (const auto& s : scans) m->integrate(s);
    OccupancyMap map = m->snapshot();
    ConsistencyCheck check(map.cells, map.geometry);
    for (const auto& s : scans) check.add(s);
    const ConsistencyResult r = check.result();
    EXPECT_EQ(r.beams_checked, scans.size() * 360);
    EXPECT_GE(r.within_share, 0.97) << to_string(kind);
    EXPECT_LE(r.median_abs_error_m, 0.01) << to_string(kind);
  }
}

// ------------------------------------------------------------------------- pose refinement
// An L-shaped room with a pillar (no symmetry to slide along), 0.05 m cells.
Grid<Cell> refine_room() {
  Grid<Cell> room(200, 120, Cell::kFree);
  for (int c = 0; c < 200; ++c) room.at(c, 0) = room.at(c, 119) = Cell::kWall;
  for (int r = 0; r < 120; ++r) room.at(0, r) = room.at(199, r) = Cell::kWall;
  for (int r = 60; r < 120; ++r) room.at(140, r) = Cell::kWall;  // the L's inner wall
  for (int c = 140; c < 200; ++c) room.at(c, 60) = Cell::kWall;
  for (int r = 30; r < 40; ++r)
    for (int c = 60; c < 70; ++c) room.at(c, r) = Cell::kWall;  // a pillar
  return room;
}

// A 360-beam scan from the true pose, ranges to the middle of the wall cells.
LaserScan scan_in(const Grid<Cell>& room, const GridGeometry& g, const Pose2d& truth) {
  LaserScan s = beam_scan(truth.x_m, truth.y_m, truth.theta_rad, {}, -kPi, 2 * kPi / 360);
  s.max_range_m = 30.0;
  for (int i = 0; i < 360; ++i) {
    const RayHit h = cast_ray_cell(g, truth.position_m(), truth.theta_rad + s.beam_angle_rad(i),
                                   30.0, [&](CellIndex c) { return is_obstacle(room.at(c)); });
    s.ranges_m.push_back(static_cast<float>(0.5 * (h.entry_m + h.exit_m)));
  }
  return s;
}

TEST(PoseRefine, FieldIsOneOnAThinWallAndFallsOffBesideIt) {
  const GridGeometry g({0.0, 0.0}, 0.05, 40, 40);
  Grid<Cell> cells(40, 40, Cell::kFree);
  for (int r = 0; r < 40; ++r) cells.at(20, r) = Cell::kWall;
  const MatchField f(cells, g, 0.05);
  Eigen::Vector2d grad;
  EXPECT_NEAR(f.sample(g.center_of({20, 20})), 1.0, 1e-3);
  f.sample(g.center_of({20, 20}) - Eigen::Vector2d(0.02, 0.0), &grad);
  EXPECT_GT(grad.x(), 0.0);  // uphill towards the wall from the left
  const double beside = f.sample(g.center_of({21, 20}), &grad);
  EXPECT_NEAR(beside, std::exp(-0.5), 0.05);  // one sigma away
  EXPECT_LT(grad.x(), 0.0);                   // uphill towards the wall
  EXPECT_EQ(f.sample({-1.0, 0.5}), 0.0);      // outside the grid
}

TEST(PoseRefine, RecoversAKnownPoseError) {
  const GridGeometry g({0.0, 0.0}, 0.05, 200, 120);
  const Grid<Cell> room = refine_room();
  const MatchField field(room, g, 0.05);
  const PoseRefineParams p;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> shift(-0.08, 0.08), turn(-1.5, 1.5);
  const double xy[10][2] = {{1.5, 1.0}, {2.0, 4.5}, {4.5, 1.0}, {5.0, 3.5}, {6.0, 5.0},
                            {8.0, 1.5}, {9.0, 2.2}, {2.5, 2.5}, {4.0, 2.8}, {1.0, 5.0}};
  for (int k = 0; k < 10; ++k) {
    const Pose2d truth{xy[k][0], xy[k][1], 0.6 * k - 2.5};
    LaserScan s = scan_in(room, g, truth);
    s.robot_pose_map = {truth.x_m + shift(rng), truth.y_m + shift(rng),
                        truth.theta_rad + turn(rng) * kPi / 180.0};
    const PoseCorrection c = refine_pose(s, field, 30.0, p);
    ASSERT_TRUE(c.applied) << k;
    EXPECT_NEAR(c.robot_pose_map.x_m, truth.x_m, 0.01) << k;
    EXPECT_NEAR(c.robot_pose_map.y_m, truth.y_m, 0.01) << k;
    EXPECT_NEAR(wrap_angle(c.robot_pose_map.theta_rad - truth.theta_rad), 0.0, 0.3 * kPi / 180)
        << k;
  }
}

TEST(PoseRefine, KeepsThePoseWhenTheScanCannotSupportACorrection) {
  const GridGeometry g({0.0, 0.0}, 0.05, 200, 120);
  const Grid<Cell> room = refine_room();
  const MatchField field(room, g, 0.05);
  PoseRefineParams p;
  // A scan whose beams all fall outside the grid: nothing to match.
  LaserScan far = beam_scan(50.0, 50.0, 0.0, std::vector<float>(360, 2.0f), -kPi, 2 * kPi / 360);
  EXPECT_FALSE(refine_pose(far, field, 30.0, p).applied);
  // Too few hits.
  LaserScan s = scan_in(room, g, {3.0, 2.0, 0.0});
  s.ranges_m.resize(20);
  EXPECT_FALSE(refine_pose(s, field, 30.0, p).applied);
  // A correction larger than the bound is refused: the scan keeps its pose.
  LaserScan off = scan_in(room, g, {3.0, 2.0, 0.0});
  off.robot_pose_map.x_m += 0.12;
  p.max_shift_m = 0.05;
  const PoseCorrection c = refine_pose(off, field, 30.0, p);
  EXPECT_FALSE(c.applied);
  EXPECT_EQ(c.robot_pose_map, off.robot_pose_map);
  p = {};
  p.passes = -1;
  EXPECT_THROW(p.validate(), UsageError);
  p = {};
  p.field_sigma_m = 0.0;
  EXPECT_THROW(p.validate(), UsageError);
}

}  // namespace
