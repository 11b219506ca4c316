// Wall alignment (issue 19, --align-walls): the dominant wall direction of synthetic rotated
// rooms, the composed levelling rotation and its inverse.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "indoormap/cloud/align.hpp"
#include "indoormap/cloud/level.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/layout/pipeline.hpp"

using namespace indoormap;
using namespace indoormap::cloud;

namespace {

// A 7 x 5 x 2.6 m room with floor, ceiling, four walls and a table, random points (no lattice:
// a lattice has sharp projections of its own at 0 and 45 degrees), 5 mm noise, turned by
// yaw_deg about z round (1, 2) and moved by (3, -2). Fixed seed.
std::vector<Eigen::Vector3f> turned_room(double yaw_deg, std::uint32_t seed = 3) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(0.0, 7.0), uy(0.0, 5.0), uz(0.0, 2.6);
  std::normal_distribution<double> n(0.0, 0.005);
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 20000; ++i) {
    pts.emplace_back(ux(rng), uy(rng), n(rng));        // floor
    pts.emplace_back(ux(rng), uy(rng), 2.6 + n(rng));  // ceiling
  }
  for (int i = 0; i < 8000; ++i) {
    pts.emplace_back(ux(rng), n(rng), uz(rng));
    pts.emplace_back(ux(rng), 5.0 + n(rng), uz(rng));
    pts.emplace_back(n(rng), uy(rng), uz(rng));
    pts.emplace_back(7.0 + n(rng), uy(rng), uz(rng));
  }
  std::uniform_real_distribution<double> tx(2.0, 3.6), ty(1.5, 2.3);
  for (int i = 0; i < 3000; ++i) pts.emplace_back(tx(rng), ty(rng), 0.75 + n(rng));  // table top
  const Eigen::Matrix3d r = yaw_rotation(yaw_deg);
  const Eigen::Vector3d pivot(1.0, 2.0, 0.0), shift(3.0, -2.0, 0.0);
  std::vector<Eigen::Vector3f> out;
  for (const auto& p : pts) out.push_back((r * (p - pivot) + pivot + shift).cast<float>());
  return out;
}

// |a - b| modulo 90 degrees.
double quarter_diff(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 90.0);
  return std::min(d, 90.0 - d);
}

WallAlignParams on() {
  WallAlignParams p;
  p.enabled = true;
  return p;
}

}  // namespace

TEST(WallAlign, RecoversTheAngleOfATurnedRoom) {
  double worst = 0.0;
  for (double deg : {0.0, 0.05, -0.1, 3.0, 17.3, 30.0, 44.9, 45.1, -20.0, 60.0, 89.95}) {
    const WallAlignResult r = estimate_wall_alignment(turned_room(deg), on());
    ASSERT_TRUE(r.applied) << deg << ": " << r.note;
    EXPECT_LT(quarter_diff(r.direction_deg, deg), 0.2) << deg << " -> " << r.direction_deg;
    worst = std::max(worst, quarter_diff(r.direction_deg, deg));
    EXPECT_GT(r.direction_deg, -45.0);
    EXPECT_LE(r.direction_deg, 45.0);
    EXPECT_DOUBLE_EQ(r.yaw_deg, -r.direction_deg);
    EXPECT_GT(r.confidence, 0.5) << deg;
    EXPECT_GT(r.wall_points, 10000u) << deg;  // the walls, not the floor or the table
  }
  RecordProperty("worst_error_deg", std::to_string(worst));
}

TEST(WallAlign, NearFortyFiveDegreesTurnsTheShortWay) {
  // 44.9 and 45.1 are 0.2 degrees apart but are undone by turns of -44.9 and +44.9.
  const WallAlignResult a = estimate_wall_alignment(turned_room(44.9), on());
  const WallAlignResult b = estimate_wall_alignment(turned_room(45.1), on());
  EXPECT_NEAR(a.yaw_deg, -44.9, 0.2);
  EXPECT_NEAR(b.yaw_deg, 44.9, 0.2);
}

TEST(WallAlign, AlignedWallsRunAlongTheAxes) {
  const auto pts = turned_room(33.0);
  const WallAlignResult r = estimate_wall_alignment(pts, on());
  ASSERT_TRUE(r.applied) << r.note;
  // After the turn the wall x = 7 of the room is one line x = const: its points' x spread only
  // by the noise.
  std::vector<double> xs;
  for (const auto& p : pts) {
    const Eigen::Vector3d q = r.rotation * p.cast<double>();
    if (q.z() > 0.3 && q.z() < 2.3) xs.push_back(q.x());
  }
  const double xmax = *std::max_element(xs.begin(), xs.end());
  std::size_t near_wall = 0;
  for (double x : xs) near_wall += x > xmax - 0.05;
  // 8000 points on that wall, 2.0 of its 2.6 m in the band: 6150, nearly all within 5 cm.
  EXPECT_GT(near_wall, 5900u);
}

TEST(WallAlign, TheLevelledFrameIsWhatIsMeasured) {
  // A 2 degree tilt: the estimate runs on the points after levelled_from_input.
  const Eigen::Matrix3d t =
      Eigen::AngleAxisd(2.0 * M_PI / 180.0, Eigen::Vector3d(1, 1, 0).normalized())
          .toRotationMatrix();
  auto pts = turned_room(12.0);
  for (auto& p : pts) p = (t * p.cast<double>()).cast<float>();
  const WallAlignResult r = estimate_wall_alignment(pts, on(), t.transpose());
  ASSERT_TRUE(r.applied) << r.note;
  EXPECT_LT(quarter_diff(r.direction_deg, 12.0), 0.2);
}

TEST(WallAlign, NoWallsNoAlignment) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 6.0);
  std::vector<Eigen::Vector3f> floor;
  for (int i = 0; i < 20000; ++i) floor.emplace_back(u(rng), u(rng), 0.0f);
  const WallAlignResult r = estimate_wall_alignment(floor, on());
  EXPECT_FALSE(r.applied);
  EXPECT_TRUE(r.rotation.isIdentity());
  EXPECT_NE(r.note.find("too few wall points"), std::string::npos) << r.note;
  EXPECT_FALSE(estimate_wall_alignment({}, on()).applied);
  EXPECT_FALSE(estimate_wall_alignment(turned_room(20.0), {}).applied);  // disabled by default
}

TEST(WallAlign, ARoundRoomHasNoDominantDirection) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> a(0.0, 2.0 * M_PI), z(0.0, 2.5);
  std::normal_distribution<double> n(0.0, 0.005);
  std::vector<Eigen::Vector3f> pts;
  for (int i = 0; i < 40000; ++i) {
    const double t = a(rng), r = 4.0 + n(rng);
    pts.emplace_back(r * std::cos(t), r * std::sin(t), z(rng));
  }
  const WallAlignResult r = estimate_wall_alignment(pts, on());
  EXPECT_FALSE(r.applied) << r.note;
  EXPECT_LT(r.confidence, 0.1);
}

TEST(WallAlign, ParametersAreValidated) {
  WallAlignParams p = on();
  p.cell_m = 0.0;
  EXPECT_THROW(validate(p), UsageError);
  p = on();
  p.min_confidence = 1.0;
  EXPECT_THROW(validate(p), UsageError);
  p = on();
  p.min_wall_height_m = -1.0;
  try {
    validate(p);
    FAIL() << "no throw";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("align_walls.min_wall_height_m"), std::string::npos);
  }
  EXPECT_NO_THROW(validate(WallAlignParams{}));
}

TEST(WallAlign, LevelCloudComposesTiltAndYawAndMapsBack) {
  // Tilt 1.5 degrees and walls at 38 degrees: level_cloud turns the cloud once by
  // map_from_input = yaw * tilt; its transpose maps every point back to the input frame.
  const Eigen::Matrix3d t =
      Eigen::AngleAxisd(1.5 * M_PI / 180.0, Eigen::Vector3d(0.3, 1, 0).normalized())
          .toRotationMatrix();
  auto pts = turned_room(38.0);
  for (auto& p : pts) p = (t * p.cast<double>()).cast<float>();
  PointCloud cloud{pts, {Eigen::Vector3d(4.0, 1.0, 1.2)}, {}};
  layout::MapParams params;
  params.align_walls.enabled = true;
  std::vector<std::string> warnings;
  const LevelResult lv = layout::level_cloud(cloud, params, warnings);
  ASSERT_TRUE(lv.levelled) << lv.note;
  ASSERT_TRUE(lv.align.applied) << lv.align.note;
  EXPECT_NEAR(lv.align.yaw_deg, -38.0, 0.2);
  EXPECT_NEAR(yaw_of(lv.map_from_input * t.transpose()), -38.0, 0.2);
  EXPECT_LT(
      (lv.map_from_input * lv.map_from_input.transpose() - Eigen::Matrix3d::Identity()).norm(),
      1e-12);
  double worst = 0.0;
  for (std::size_t i = 0; i < pts.size(); i += 97) {
    const Eigen::Vector3d back = lv.map_from_input.transpose() * cloud.points[i].cast<double>();
    worst = std::max(worst, (back - pts[i].cast<double>()).norm());
  }
  EXPECT_LT(worst, 1e-5);  // float storage of the turned points
  const Eigen::Vector3d s_back = lv.map_from_input.transpose() * cloud.scanners[0];
  EXPECT_LT((s_back - Eigen::Vector3d(4.0, 1.0, 1.2)).norm(), 1e-9);
  // The turned cloud's walls run along the axes: a second estimate finds (almost) nothing to do.
  const WallAlignResult again = estimate_wall_alignment(cloud.points, params.align_walls);
  EXPECT_LT(quarter_diff(again.direction_deg, 0.0), 0.2) << again.direction_deg;
}
