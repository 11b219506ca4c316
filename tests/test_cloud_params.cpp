// cloud's parameter checks: each params struct's validate() names the YAML key, and the library
// entry points call it (layout::make_map too: test_layout.cpp), so a library user gets the
// checks of the apps.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "indoormap/cloud/ghosts.hpp"
#include "indoormap/cloud/level.hpp"
#include "indoormap/cloud/voxel.hpp"
#include "indoormap/core/errors.hpp"

using namespace indoormap;
using namespace indoormap::cloud;

namespace {

// The message of the UsageError that f throws ("" when it throws none).
std::string usage_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

std::vector<Eigen::Vector3f> cube_points() {
  std::vector<Eigen::Vector3f> pts;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      for (int k = 0; k < 10; ++k) pts.emplace_back(0.1f * i, 0.1f * j, 0.1f * k);
  return pts;
}

}  // namespace

TEST(CloudParams, DefaultsAreValid) {
  EXPECT_NO_THROW(validate(VoxelParams{}));
  EXPECT_NO_THROW(validate(LayerParams{}));
  EXPECT_NO_THROW(validate(LevelParams{}));
  EXPECT_NO_THROW(validate(GhostParams{}));
}

TEST(CloudParams, EachStructNamesItsKey) {
  VoxelParams vx;
  vx.cell_m = 0;
  EXPECT_EQ(usage_error([&] { validate(vx); }),
            "invalid parameter voxel.cell_m: must be in [0.001, 10] m");
  LayerParams ly;
  ly.wall_min_extent_m = ly.wall_band_m + 0.1;
  EXPECT_EQ(usage_error([&] { validate(ly); }),
            "invalid parameter layers.wall_min_extent_m: must be in [0, layers.wall_band_m]");
  LayerParams low;
  low.low_wall_band_m = -0.1;
  EXPECT_EQ(usage_error([&] { validate(low); }),
            "invalid parameter layers.low_wall_band_m: must be in [0, 1]");
  LayerParams piece;
  piece.low_wall_min_length_m = -1;
  EXPECT_EQ(usage_error([&] { validate(piece); }),
            "invalid parameter layers.low_wall_min_length_m: must be >= 0");
  LevelParams lv;
  lv.max_tilt_deg = 90;
  EXPECT_EQ(usage_error([&] { validate(lv); }),
            "invalid parameter level.max_tilt_deg: must be in (0, 90)");
  GhostParams gh;
  gh.max_rays = 0;
  EXPECT_EQ(usage_error([&] { validate(gh); }),
            "invalid parameter ghosts.max_rays: must be in [1, 1e9]");
  gh = {};
  gh.far_end_m = -0.5;
  EXPECT_EQ(usage_error([&] { validate(gh); }), "invalid parameter ghosts.far_end_m: must be >= 0");
}

TEST(CloudParams, EntryPointsValidate) {
  const auto pts = cube_points();
  VoxelParams vx;
  vx.bounds_gap_m = -1;
  EXPECT_NE(usage_error([&] { robust_bounds(pts, vx); }).find("voxel.bounds_gap_m"),
            std::string::npos);
  vx = {};
  vx.max_cells = 0;
  EXPECT_NE(usage_error([&] {
              voxelize(pts, {{0, 0, 0}, {1, 1, 1}}, vx);
            }).find("voxel.max_cells"),
            std::string::npos);
  VoxelGrid g = voxelize(pts, {{0, 0, 0}, {1, 1, 1}}, VoxelParams{});
  LayerParams ly;
  ly.ceiling_onset_factor = 1.0;
  EXPECT_NE(usage_error([&] { analyse_layers(g, ly); }).find("layers.ceiling_onset_factor"),
            std::string::npos);
  LevelParams lv;
  lv.enabled = false;  // checked all the same, as the apps do
  lv.sample_points = 2;
  EXPECT_NE(usage_error([&] { estimate_level(pts, lv); }).find("level.sample_points"),
            std::string::npos);
  GhostParams gh;
  gh.min_passes = 0;
  EXPECT_NE(usage_error([&] {
              remove_ghost_voxels(g, pts, {0.5, 0.5, 0.5}, gh);
            }).find("ghosts.min_passes"),
            std::string::npos);
}
