// core's VoxelGeometry: the one owner of world <-> voxel conversion in 3D, and the float binning
// of the voxelisation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "indoormap/core/voxel_geometry.hpp"

using indoormap::VoxelBinner;
using indoormap::VoxelGeometry;
using indoormap::VoxelIndex;

namespace {

VoxelGeometry small_grid() {
  VoxelGeometry g;
  g.origin_m = {-1.0, 2.0, -0.5};
  g.cell_m = 0.25;
  g.nx = 8;
  g.ny = 6;
  g.nz = 4;
  return g;
}

}  // namespace

TEST(VoxelGeometry, IndexIsLayerByLayerRowsOfX) {
  const VoxelGeometry g = small_grid();
  EXPECT_EQ(g.layer_size(), 48);
  EXPECT_EQ(g.voxel_count(), 192);
  EXPECT_EQ(g.index(0, 0, 0), 0);
  EXPECT_EQ(g.index(1, 0, 0), 1);
  EXPECT_EQ(g.index(0, 1, 0), 8);
  EXPECT_EQ(g.index(0, 0, 1), 48);
  EXPECT_EQ(g.index(7, 5, 3), 191);
  EXPECT_EQ(g.index(VoxelIndex{3, 2, 1}), (1 * 6 + 2) * 8 + 3);
}

TEST(VoxelGeometry, VoxelOfFloorsAndContainsChecksEveryAxis) {
  const VoxelGeometry g = small_grid();
  EXPECT_EQ(g.voxel_of({-1.0, 2.0, -0.5}), (VoxelIndex{0, 0, 0}));
  EXPECT_EQ(g.voxel_of({-0.76, 2.26, 0.0}), (VoxelIndex{0, 1, 2}));
  EXPECT_EQ(g.voxel_of({-1.01, 1.99, -0.51}), (VoxelIndex{-1, -1, -1}));  // floor, not truncation
  EXPECT_TRUE(g.contains(g.voxel_of({0.99, 3.49, 0.49})));
  EXPECT_FALSE(g.contains(g.voxel_of({1.0, 3.0, 0.0})));  // x = nx
  EXPECT_FALSE(g.contains(g.voxel_of({0.0, 3.5, 0.0})));  // y = ny
  EXPECT_FALSE(g.contains(g.voxel_of({0.0, 3.0, 0.5})));  // z = nz
  EXPECT_FALSE(g.contains(VoxelIndex{0, 0, -1}));
  EXPECT_EQ(g.layer_of(-0.5), 0);
  EXPECT_EQ(g.layer_of(0.24), 2);
  EXPECT_EQ(g.layer_of(-0.6), -1);
}

TEST(VoxelGeometry, FarAndNonFiniteCoordinatesSaturateOutsideTheGrid) {
  const VoxelGeometry g = small_grid();
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(1e300, 2.5, 0.0), Eigen::Vector3d(0.0, -inf, 0.0),
        Eigen::Vector3d(0.0, 2.5, nan), Eigen::Vector3d(-1e30, 1e30, inf)})
    EXPECT_FALSE(g.contains(g.voxel_of(p)));
  EXPECT_GT(g.voxel_of({1e300, 2.5, 0.0}).ix, g.nx);
  EXPECT_LT(g.voxel_of({0.0, -inf, 0.0}).iy, 0);
  EXPECT_FALSE(g.layer_of(nan) >= 0 && g.layer_of(nan) < g.nz);
  EXPECT_GT(g.layer_of(inf), g.nz);
}

TEST(VoxelGeometry, ContinuousCoordinatesLayersAndTheLayerGrid) {
  const VoxelGeometry g = small_grid();
  const Eigen::Vector3d v = g.to_voxel_coords({-0.875, 2.375, -0.125});
  EXPECT_DOUBLE_EQ(v.x(), 0.5);
  EXPECT_DOUBLE_EQ(v.y(), 1.5);
  EXPECT_DOUBLE_EQ(v.z(), 1.5);
  EXPECT_DOUBLE_EQ(g.to_layer_coord(-0.125), 1.5);
  EXPECT_DOUBLE_EQ(g.to_cells(1.0), 4.0);
  EXPECT_DOUBLE_EQ(g.layer_bottom_m(2), 0.0);
  EXPECT_DOUBLE_EQ(g.layer_center_m(2), 0.125);
  const indoormap::GridGeometry g2 = g.geometry2d();
  EXPECT_EQ(g2.width(), 8);
  EXPECT_EQ(g2.height(), 6);
  EXPECT_DOUBLE_EQ(g2.cell_m(), 0.25);
  EXPECT_EQ(g2.origin_m(), Eigen::Vector2d(-1.0, 2.0));
}

// The float binning agrees with voxel_of away from voxel boundaries and rejects what lies outside
// (NaN included).
TEST(VoxelBinner, AgreesWithVoxelOfInsideAndRejectsOutside) {
  const VoxelGeometry g = small_grid();
  const VoxelBinner binner(g);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  int inside = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d f(u(rng), u(rng), u(rng));  // fraction of the grid's extent
    const Eigen::Vector3d p =
        g.origin_m + Eigen::Vector3d(f.x() * g.nx, f.y() * g.ny, f.z() * g.nz) * g.cell_m;
    const Eigen::Vector3d c = g.to_voxel_coords(p);
    const Eigen::Vector3d frac = c - c.array().floor().matrix();
    if ((frac.array() < 1e-3).any() || (frac.array() > 1 - 1e-3).any()) continue;
    const VoxelIndex v = g.voxel_of(p);
    const std::int64_t idx = binner.index_of(p.cast<float>());
    if (g.contains(v)) {
      ++inside;
      EXPECT_EQ(idx, g.index(v)) << p.transpose();
    } else {
      EXPECT_EQ(idx, -1) << p.transpose();
    }
  }
  EXPECT_GT(inside, 500);
  EXPECT_EQ(binner.index_of(Eigen::Vector3f(std::nanf(""), 2.5f, 0.f)), -1);
}
