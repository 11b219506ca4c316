// cloud::robust_bounds: the grid holds the main body of the data, its sparse far ends included,
// and nothing beyond an empty gap.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <random>
#include <vector>

#include "indoormap/cloud/voxel.hpp"

using namespace indoormap;
using namespace indoormap::cloud;

namespace {

// n points uniformly in the box [0,w] x [0,d] x [0,h]. Fixed seed.
std::vector<Eigen::Vector3f> box_points(double w, double d, double h, int n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Vector3f> pts;
  for (int i = 0; i < n; ++i)
    pts.emplace_back(static_cast<float>(w * u(rng)), static_cast<float>(d * u(rng)),
                     static_cast<float>(h * u(rng)));
  // The box's corners, so that its bounds are exact.
  pts.emplace_back(0.f, 0.f, 0.f);
  pts.emplace_back(static_cast<float>(w), static_cast<float>(d), static_cast<float>(h));
  return pts;
}

}  // namespace

TEST(RobustBounds, FarOutlierDoesNotStretchTheGrid) {
  auto pts = box_points(8.0, 6.0, 2.9, 20000);
  for (int i = 0; i < 300; ++i) pts.emplace_back(80.f + i * 0.01f, 3.f, 1.f);  // through a window
  pts.emplace_back(-500.f, 2.f, 1.f);
  VoxelParams p;
  Bounds3 b = robust_bounds(pts, p);
  EXPECT_NEAR(b.lo_m.x(), 0.0, 1e-6);
  EXPECT_NEAR(b.hi_m.x(), 8.0, 1e-5);
  EXPECT_NEAR(b.hi_m.y(), 6.0, 1e-5);
  EXPECT_NEAR(b.hi_m.z(), 2.9, 1e-5);
  VoxelGrid g = voxelize(pts, b, p);
  EXPECT_EQ(g.points_outside, 301u);
}

// A long corridor's far part seen from a scanner 20 m away holds a point every few decimetres:
// a sample of the cloud (1 point in 8 here) leaves gaps of a metre and more in it, and bounds
// taken from the sample would cut the corridor's end off the grid.
TEST(RobustBounds, SparseFarEndOfTheMainBodyStaysInTheGrid) {
  auto pts = box_points(8.0, 2.0, 2.5, 500000);
  for (int k = 0; k <= 40; ++k) pts.emplace_back(8.f + 0.3f * k, 0.f, 1.f);  // a side wall
  for (int k = 0; k < 10; ++k) pts.emplace_back(20.f, 0.2f * k, 1.f);        // the end wall
  VoxelParams p;
  ASSERT_LT(p.bounds_sample, pts.size() / 4);  // the test is about a sampled cloud
  const Bounds3 b = robust_bounds(pts, p);
  EXPECT_NEAR(b.hi_m.x(), 20.0, 1e-5);
  EXPECT_EQ(voxelize(pts, b, p).points_outside, 0u);
  // One gap of 1.5 m in it, and the grid stops before the gap.
  pts.emplace_back(21.5f, 1.f, 1.f);
  EXPECT_NEAR(robust_bounds(pts, p).hi_m.x(), 20.0, 1e-5);
}
