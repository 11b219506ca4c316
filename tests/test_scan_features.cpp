// scan_features: each detector on hand-made scans (rupture and breakpoint detection, the
// iterative end-point fit, the TLS refit, walls, doors, corners and their typing, corridors),
// the accuracy targets on simulated scans with known geometry (fixed seeds), and ICP.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "indoormap/scan_features/features.hpp"
#include "indoormap/scan_features/icp.hpp"
#include "indoormap/sim/scan_eval.hpp"
#include "indoormap/sim/scan_scenes.hpp"

namespace {

using namespace indoormap;
using namespace indoormap::scan_features;
using V = Eigen::Vector2d;
constexpr double kDeg = std::numbers::pi / 180.0;

/// A scan of the given walls (no noise), 360 beams over 180 degrees or a full circle of 720.
laser::LaserScan scan_of(const std::vector<sim::ScanSegment>& walls, bool full = false,
                         double max_range_m = 30.0, laser::Pose2d pose = {}) {
  sim::ScanScene scene;
  scene.walls = walls;
  sim::LaserModel m;
  m.beams = full ? 720 : 361;
  m.fov_rad = full ? 2.0 * std::numbers::pi : std::numbers::pi;
  m.sigma_r_m = 0.0;
  m.max_range_m = max_range_m;
  std::mt19937_64 rng(1);
  return sim::cast_scan(scene, pose, m, rng);
}

laser::LaserScan ranges_scan(std::vector<float> r, double inc_rad) {
  laser::LaserScan s;
  s.ranges_m = std::move(r);
  s.angle_increment_rad = inc_rad;
  s.max_range_m = 10.0;
  return s;
}

TEST(ScanFeaturesSegments, BorgesAldonThreshold) {
  SegmentParams p;
  const double expect = 2.0 * std::sin(0.5 * kDeg) / std::sin(9.5 * kDeg) + 0.03;
  EXPECT_NEAR(breakpoint_threshold_m(2.0, 0.5 * kDeg, p), expect, 1e-12);
  EXPECT_EQ(breakpoint_threshold_m(2.0, 11.0 * kDeg, p), 0.0);  // wider than lambda: always
}

TEST(ScanFeaturesSegments, RupturesAndBreakpointsCutRuns) {
  // 1 m, 1 m, 1 m, no return, 1 m x3, then a jump to 3 m (D_max at 1 m is ~0.13 m).
  const auto s = ranges_scan({1, 1, 1, 0, 1, 1, 1, 3, 3, 3}, 1.0 * kDeg);
  const Segmentation seg = segment_scan(s, {});
  EXPECT_EQ(seg.ruptures, 1);
  EXPECT_EQ(seg.breakpoints, 1);
  ASSERT_EQ(seg.runs.size(), 3u);
  EXPECT_EQ(seg.runs[0].first, 0);
  EXPECT_EQ(seg.runs[0].last, 2);
  EXPECT_EQ(seg.runs[0].start, Boundary::kScanEnd);
  EXPECT_EQ(seg.runs[0].end, Boundary::kRupture);
  EXPECT_EQ(seg.runs[1].start, Boundary::kRupture);
  EXPECT_EQ(seg.runs[1].end, Boundary::kBreakpoint);
  EXPECT_EQ(seg.runs[2].start, Boundary::kBreakpoint);
  EXPECT_EQ(seg.runs[2].size(), 3);
  EXPECT_EQ(seg.points[7].beam, 8);  // the no-return beam left no point
}

TEST(ScanFeaturesSegments, BeyondMaximumRangeIsARupture) {
  auto s = ranges_scan({1, 1, 12, 1, 1, std::nanf("")}, 1.0 * kDeg);
  SegmentParams p;
  p.max_range_m = 5.0;
  s.ranges_m[3] = 6.0f;  // within the scan's 10 m but beyond the 5 m asked for
  const Segmentation seg = segment_scan(s, p);
  EXPECT_EQ(seg.ruptures, 3);
  EXPECT_EQ(seg.runs.size(), 2u);
}

TEST(ScanFeaturesSegments, FullCircleRunIsNotCutAtTheSeam) {
  // A closed square room seen from its centre, a pillar-free full circle: with a far jump
  // (a door to a closet) away from the seam, the run across the seam stays one.
  const auto s = scan_of({{{-2, -2}, {2, -2}},
                          {{2, -2}, {2, 2}},
                          {{2, 2}, {-2, 2}},
                          {{-2, 2}, {-2, 0.5}},
                          {{-2, -0.5}, {-2, -2}},
                          {{-4, 0.5}, {-4, -0.5}}},
                         true);
  const Segmentation seg = segment_scan(s, {});
  EXPECT_TRUE(seg.full_circle);
  ASSERT_GE(seg.runs.size(), 2u);
  for (const auto& r : seg.runs) EXPECT_NE(r.start, Boundary::kScanEnd);
}

TEST(ScanFeaturesLines, TlsFitAndIterativeEndPointFit) {
  std::vector<ScanPoint> pts;
  for (int i = 0; i <= 10; ++i) pts.push_back({V(0.1 * i, 1.0 + 0.05 * i), 0.0, i});
  LineFit f = fit_tls(pts);
  EXPECT_NEAR(std::abs(f.direction.normalized().dot(V(1, 0.5).normalized())), 1.0, 1e-12);
  EXPECT_NEAR(f.rms_m, 0.0, 1e-12);
  EXPECT_GT(f.direction.x(), 0.0);  // first to last
  // An L: 11 points along x, then 10 up: one split, at the corner point (index 10).
  for (int i = 1; i <= 10; ++i) pts.push_back({V(1.0, 1.5 + 0.1 * i), 0.0, 10 + i});
  const auto pieces = split_iepf(pts, 0, 20, 0.05);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0], std::make_pair(0, 10));
  EXPECT_EQ(pieces[1], std::make_pair(10, 20));
}

TEST(ScanFeaturesLines, NoisyStraightWallIsOneLine) {
  // A wall 2 m ahead, 1 cm noise: the split threshold may cut it; the merge joins it again.
  sim::ScanScene scene;
  scene.walls = {{{2, -3}, {2, 3}}};
  sim::LaserModel m;
  m.beams = 181;
  m.fov_rad = std::numbers::pi / 2;
  std::mt19937_64 rng(7);
  LineParams lp;
  lp.split_distance_m = 0.02;  // below the noise's 3 sigma: splits happen
  const Segmentation seg = segment_scan(sim::cast_scan(scene, {}, m, rng), {});
  const auto lines = extract_lines(seg, lp);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NEAR(std::abs(lines[0].fit.direction.y()), 1.0, 1e-3);
  EXPECT_NEAR(lines[0].fit.rms_m, 0.01, 0.003);
  EXPECT_NEAR(lines[0].start_laser.x(), 2.0, 0.01);
}

TEST(ScanFeaturesCorners, ThreeDistanceRule) {
  const V s(0, 0);
  // Room corner ahead: the corner lies beyond the missing leg.
  EXPECT_EQ(corner_type_three_distances(s, {2, -1}, {2, 2}, {-1, 2}), CornerType::kInner);
  // Box corner pointing at the sensor: between sensor and leg.
  double rc, rl, cl;
  EXPECT_EQ(corner_type_three_distances(s, {1, 2}, {1, 1}, {2, 1}, &rc, &rl, &cl),
            CornerType::kOuter);
  EXPECT_NEAR(rc, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(rl, 3.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(cl, 1.0 / std::sqrt(2.0), 1e-12);
  // Sensor near a room corner with long legs: inside the triangle, still an inner corner.
  EXPECT_EQ(corner_type_three_distances({1, 1}, {2, -5}, {2, 2}, {-5, 2}), CornerType::kInner);
}

TEST(ScanFeaturesCorners, RoomCornerAndBoxCorner) {
  // Sensor at the origin facing +x: a room corner at (3, 2) and a box with a corner at (1.5, -1).
  const auto s = scan_of({{{3, -4}, {3, 2}},
                          {{3, 2}, {-1, 2}},  // room walls, free side left
                          {{1.5, -1}, {2.2, -1}},
                          {{2.2, -1}, {2.2, -1.7}},
                          {{1.5, -1.7}, {1.5, -1}}});
  const ScanFeatures f = extract_features(s, {});
  int inner = 0, outer = 0;
  for (const Corner& c : f.corners) {
    if ((c.p_laser - V(3, 2)).norm() < 0.02) {
      ++inner;
      EXPECT_EQ(c.type, CornerType::kInner);
    }
    if ((c.p_laser - V(1.5, -1)).norm() < 0.02) {
      ++outer;
      EXPECT_EQ(c.type, CornerType::kOuter);
    }
  }
  EXPECT_EQ(inner, 1);
  EXPECT_EQ(outer, 1);
  for (const Wall& w : f.walls) {  // free side (the sensor) on the left of every wall
    const V d = w.end_laser - w.start_laser;
    EXPECT_GT(d.x() * (-w.start_laser.y()) - d.y() * (-w.start_laser.x()), 0.0);
  }
}

TEST(ScanFeaturesCorners, CornerBeyondMaximumRangeIsPotential) {
  const auto s = scan_of({{{3, -3}, {3, 3}}, {{3, 3}, {-3, 3}}}, false, 4.0);
  const ScanFeatures f = extract_features(s, {});
  ASSERT_EQ(f.corners.size(), 1u);
  EXPECT_EQ(f.corners[0].type, CornerType::kPotential);
  EXPECT_NEAR((f.corners[0].p_laser - V(3, 3)).norm(), 0.0, 0.02);
}

TEST(ScanFeaturesDoors, GapBetweenCollinearWallsIsADoor) {
  // Wall at x = 3 with a 0.9 m opening onto a closet 2 m deep.
  const std::vector<sim::ScanSegment> room{
      {{3, -3}, {3, 0.2}}, {{3, 1.1}, {3, 3}}, {{5, 0}, {5, 1.3}}};
  const ScanFeatures f = extract_features(scan_of(room), {});
  ASSERT_EQ(f.doors.size(), 1u);
  EXPECT_EQ(f.doors[0].kind, DoorKind::kCollinear);
  // The jambs are the last hits on the walls: wider by up to a beam spacing (2.7 cm) each side.
  EXPECT_GE(f.doors[0].width_m(), 0.89);
  EXPECT_LE(f.doors[0].width_m(), 0.9 + 2 * 0.027);
  EXPECT_NEAR(f.doors[0].a_laser.y(), 0.2, 0.02);
  // Too wide (1.5 m) is no door; an object in front of the gap closes it.
  const ScanFeatures wide =
      extract_features(scan_of({{{3, -3}, {3, 0.2}}, {{3, 1.7}, {3, 3}}, {{5, 0}, {5, 2}}}), {});
  EXPECT_TRUE(wide.doors.empty());
  auto blocked = room;
  blocked.push_back({{2.5, 0.5}, {2.5, 0.8}});
  EXPECT_TRUE(extract_features(scan_of(blocked), {}).doors.empty());
}

TEST(ScanFeaturesCorridors, TwoLongFacingWalls) {
  // A corridor along x, 2 m wide, the sensor in its middle, facing along it.
  const auto s = scan_of({{{-1, -1}, {8, -1}}, {{8, 1}, {-1, 1}}});
  const ScanFeatures f = extract_features(s, {});
  ASSERT_EQ(f.corridors.size(), 1u);
  EXPECT_NEAR(f.corridors[0].width_m, 2.0, 0.02);
  EXPECT_FALSE(f.corridors[0].side_a.empty());
  EXPECT_FALSE(f.corridors[0].side_b.empty());
  EXPECT_TRUE(extract_features(scan_of({{{-1, -1}, {8, -1}}}), {}).corridors.empty());
}

TEST(ScanFeaturesFrames, RobotAndMapFramesFollowThePoses) {
  auto s = scan_of({{{3, -3}, {3, 3}}});
  s.laser_offset = {0.2, 0.0, 0.0};
  s.robot_pose_map = {10.0, 5.0, std::numbers::pi / 2};
  const ScanFeatures f = extract_features(s, {});
  ASSERT_EQ(f.walls.size(), 1u);
  EXPECT_NEAR(f.walls[0].start_robot.x(), 3.2, 0.01);
  EXPECT_NEAR(f.walls[0].start_map.y(), 5.0 + 3.2, 0.01);  // x forward turned to map +y
}

struct SimFigures {
  double median_endpoint_m, endpoint_found, door_recall, door_precision, corner_type_accuracy;
};

SimFigures run_sim(int scenes, bool full_circle, std::uint64_t seed) {
  sim::ScanScore total;
  sim::LaserModel m;
  if (!full_circle) m.beams = 361, m.fov_rad = std::numbers::pi;
  for (int k = 0; k < scenes; ++k) {
    const sim::ScanScene scene = sim::random_scan_scene(seed + static_cast<std::uint64_t>(k));
    std::mt19937_64 rng(seed * 1000 + static_cast<std::uint64_t>(k));
    for (int pose = 0; pose < 2; ++pose) {
      const auto scan = sim::cast_scan(scene, sim::random_pose(scene, 0.5, rng), m, rng);
      total.add(sim::score_scan(scene, scan, extract_features(scan, {})));
    }
  }
  auto e = total.endpoint_errors_m;
  std::nth_element(e.begin(), e.begin() + static_cast<std::ptrdiff_t>(e.size() / 2), e.end());
  const SimFigures f{e.empty() ? 1.0 : e[e.size() / 2],
                     double(e.size()) / std::max(1, total.endpoints_visible),
                     double(total.doors_found) / std::max(1, total.doors_visible),
                     double(total.doors_right) / std::max(1, total.doors_detected),
                     double(total.corners_type_right) / std::max(1, total.corners_typed)};
  std::printf(
      "sim %s: %d scans; wall end points %zu of %d visible matched, median error %.4f m; doors "
      "%d visible, recall %.3f, precision %.3f (%d detected); corners %d typed, type accuracy "
      "%.3f, %d of %d visible found\n",
      full_circle ? "360 deg/720 beams" : "180 deg/361 beams", 2 * scenes, e.size(),
      total.endpoints_visible, f.median_endpoint_m, total.doors_visible, f.door_recall,
      f.door_precision, total.doors_detected, total.corners_typed, f.corner_type_accuracy,
      total.corners_found, total.corners_visible);
  return f;
}

TEST(ScanFeaturesSim, AcceptanceTargetsOnSimulatedScans) {
  for (bool full : {true, false}) {
    const SimFigures f = run_sim(100, full, full ? 1 : 5001);
    EXPECT_LE(f.median_endpoint_m, 0.05);
    EXPECT_GE(f.endpoint_found, 0.5);
    EXPECT_GE(f.door_recall, 0.9);
    EXPECT_GE(f.door_precision, 0.9);
    EXPECT_GE(f.corner_type_accuracy, 0.95);
  }
}

}  // namespace

// --- alignment ---------------------------------------------------------------------------------

TEST(ScanFeaturesIcp, ProcrustesRecoversAKnownTransform) {
  const laser::Pose2d t{0.3, -0.2, 0.25};
  std::vector<V> src{{1, 0}, {2, 1}, {0, 3}, {-1, 1}}, dst;
  for (const V& p : src) dst.push_back(t.transform(p));
  const laser::Pose2d got = procrustes(src, dst);
  EXPECT_NEAR(got.x_m, 0.3, 1e-12);
  EXPECT_NEAR(got.y_m, -0.2, 1e-12);
  EXPECT_NEAR(got.theta_rad, 0.25, 1e-12);
  const laser::Pose2d rel = relative_pose({1, 2, 0.5}, laser::Pose2d{1, 2, 0.5}.compose(t));
  EXPECT_NEAR(rel.x_m, 0.3, 1e-12);
  EXPECT_NEAR(rel.theta_rad, 0.25, 1e-12);
}

TEST(ScanFeaturesIcp, BothVariantsRecoverTheMotionBetweenSimulatedScans) {
  const sim::ScanScene scene = sim::random_scan_scene(42);
  std::mt19937_64 rng(42);
  const laser::Pose2d a = sim::random_pose(scene, 1.0, rng);
  const laser::Pose2d motion{0.25, 0.1, 6.0 * kDeg};  // b in a's frame
  const laser::Pose2d b = a.compose(motion);
  sim::LaserModel m;
  m.beams = 360;
  const auto sa = sim::cast_scan(scene, a, m, rng), sb = sim::cast_scan(scene, b, m, rng);
  for (IcpKind kind : {IcpKind::kPointToPoint, IcpKind::kPointToLine}) {
    IcpParams p;
    p.kind = kind;
    const IcpResult r = align_scans(sa, sb, p);
    EXPECT_TRUE(r.converged) << icp_kind_name(kind);
    EXPECT_NEAR(r.transform.x_m, motion.x_m, 0.01) << icp_kind_name(kind);
    EXPECT_NEAR(r.transform.y_m, motion.y_m, 0.01) << icp_kind_name(kind);
    EXPECT_NEAR(r.transform.theta_rad, motion.theta_rad, 0.3 * kDeg) << icp_kind_name(kind);
    EXPECT_GT(r.inlier_share, 0.8);
    EXPECT_LT(r.rms_m, 0.03);
  }
}

TEST(ScanFeaturesIcp, TooFewPointsIsAFailedAlignmentNotAnError) {
  const auto s = ranges_scan({1, 1, 1}, 1.0 * kDeg);
  const IcpResult r = align_scans(s, s, {});
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.pairs, 0);
}
