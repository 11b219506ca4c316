// The whole pre-processing pipeline (paper 3.2.A) on the real Jacobs scan, position 0, all nine
// sectors read straight from the 3DTK files. Skips when ../shared/data is absent.
#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "ghost_reference.hpp"
#include "indoormap/cloud/level.hpp"
#include "indoormap/cloud_io/load.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "indoormap/objects/objects.hpp"
#include "test_support.hpp"

using namespace indoormap;

namespace {

struct Jacobs {
  cloud_io::LoadResult loaded;
  layout::MapResult map;
};

// Loaded and mapped once for the whole suite.
const Jacobs* jacobs() {
  static const Jacobs* j = []() -> const Jacobs* {
    auto root = test::shared_data_dir();
    if (!root || !std::filesystem::exists(*root / "jacobs-thermocolorlab")) return nullptr;
    auto* r = new Jacobs;
    r->loaded = cloud_io::load_cloud((*root / "jacobs-thermocolorlab").string());
    r->map = layout::make_map(r->loaded.cloud, {});
    return r;
  }();
  return j;
}

#define REQUIRE_JACOBS()                                                             \
  const Jacobs* J = jacobs();                                                        \
  if (!J)                                                                            \
  GTEST_SKIP() << "real data 'jacobs-thermocolorlab' not found: set INDOORMAP_DATA " \
                  "or provide ../shared/data next to the source tree"

// Number of layers within +-5 of `layer` holding at least half of that layer's occupied cells.
int smear(const std::vector<std::int64_t>& h, std::int64_t layer) {
  int n = 0;
  for (std::int64_t z = std::max<std::int64_t>(0, layer - 5);
       z <= std::min<std::int64_t>(static_cast<std::int64_t>(h.size()) - 1, layer + 5); ++z)
    n += 2 * h[z] >= h[layer];
  return n;
}

}  // namespace

TEST(JacobsPipeline, AllNineSectorsLoadWithTheScannerPose) {
  REQUIRE_JACOBS();
  EXPECT_EQ(J->loaded.cloud.points.size(), 516110u);
  ASSERT_FALSE(J->loaded.cloud.scanners.empty());
}

// The ghost filter (candidate voxels, rays indexed by direction) against the ray-walking reference
// on the real scan, levelled as the pipeline does: the same voxels removed.
TEST(JacobsPipeline, GhostFilterRemovesWhatTheRayWalkingReferenceRemoves) {
  REQUIRE_JACOBS();
  PointCloud c = J->loaded.cloud;
  ASSERT_EQ(c.scanners.size(), 1u);
  cloud::rotate(c, cloud::estimate_level(c.points, {}).map_from_input);
  const cloud::VoxelParams vp;
  const cloud::VoxelGrid g0 = cloud::voxelize(c.points, cloud::robust_bounds(c.points, vp), vp);
  const std::vector<cloud::RaySource> src{{c.points, c.scanners[0]}};
  cloud::VoxelGrid fast = g0, ref = g0;
  const auto a = cloud::remove_ghost_voxels_by_origin(fast, src, {});
  const auto b = cloud::reference_remove_ghost_voxels(ref, src, {});
  std::size_t differ = 0;
  for (std::size_t i = 0; i < fast.counts.size(); ++i) differ += fast.counts[i] != ref.counts[i];
  std::printf("[ figures  ] Jacobs: %lld / %lld voxels removed, %zu differ\n",
              static_cast<long long>(a.voxels_removed), static_cast<long long>(b.voxels_removed),
              differ);
  EXPECT_GT(b.voxels_removed, 100);
  EXPECT_EQ(a.rays, b.rays);
  EXPECT_LE(differ, static_cast<std::size_t>(b.voxels_removed) / 1000);
}

// A storey's slice of a building holds points seen from another storey's positions, which it does
// not list: their origin is unknown. The filter runs with the rays it knows (those points cast
// none) and counts as exact while they are at most a tenth of the cloud; beyond, it still runs
// and says what share it could not trace. Before, any unknown origin skipped it.
TEST(JacobsPipeline, GhostFilterRunsWithTheRaysWhoseOriginIsKnown) {
  REQUIRE_JACOBS();
  PointCloud c = J->loaded.cloud;
  ASSERT_EQ(c.origins.size(), 9u);  // the nine sector files, one position
  c.scanners.push_back(c.scanners[0] + Eigen::Vector3d(5.0, 0.0, 0.0));  // two positions listed
  const std::size_t unknown = std::numeric_limits<std::size_t>::max();
  const auto run = [&](double unknown_share) {
    PointCloud x = c;
    // The last sector's span, or its tail, from a position the cloud does not list.
    auto& last = x.origins.back();
    const auto n = static_cast<std::size_t>(unknown_share * static_cast<double>(x.points.size()));
    ASSERT_LE(n, last.count);
    last.count -= n;
    x.origins.push_back({last.first + last.count, n, unknown});
    const layout::MapResult m = layout::make_map(std::move(x), {});
    EXPECT_TRUE(m.ghosts.applied);
    EXPECT_GT(m.ghosts.voxels_removed, 100);
    EXPECT_EQ(m.ghost_origins_exact, unknown_share <= 0.1);
    bool warned = false;
    for (const auto& w : m.warnings) warned = warned || w.find("their rays not traced") != w.npos;
    EXPECT_EQ(warned, unknown_share > 0.1) << unknown_share;
  };
  run(0.05);
  run(0.11);
}

TEST(JacobsPipeline, LevellingPutsFloorAndCeilingIntoOneOrTwoLayers) {
  REQUIRE_JACOBS();
  const auto& m = J->map;
  ASSERT_TRUE(m.level.levelled) << m.level.note;
  // Floor and ceiling planes agree on a tilt of 2.1 degrees (1.6 about one horizontal axis and
  // 1.4 about the other); the floor smears over five layers without levelling.
  EXPECT_GT(m.level.tilt_deg, 1.0);
  EXPECT_LT(m.level.tilt_deg, 3.0);
  ASSERT_TRUE(m.level.floor.found);
  ASSERT_TRUE(m.level.ceiling.found);
  ASSERT_TRUE(m.layers.ceiling_found);
  EXPECT_LE(smear(m.layers.occupied_per_layer, m.layers.floor_layer), 2);
  EXPECT_LE(smear(m.layers.occupied_per_layer, m.layers.ceiling_layer), 2);
  const double height = m.layers.ceiling_z_m - m.layers.floor_z_m;
  EXPECT_GT(height, 2.5);  // an office: about 2.8 - 3.0 m
  EXPECT_LT(height, 3.3);
}

TEST(JacobsPipeline, WithoutLevellingTheFloorSmears) {
  REQUIRE_JACOBS();
  layout::MapParams p;
  p.level.enabled = false;
  auto m = layout::make_map(J->loaded.cloud, p);
  EXPECT_GE(smear(m.layers.occupied_per_layer, m.layers.floor_layer), 3);
}

TEST(JacobsPipeline, FreeSpaceIsOneRegionAroundTheScannerEnclosedByWall) {
  REQUIRE_JACOBS();
  const auto& m = J->map;
  const auto& L = m.layout.layout;
  ASSERT_FALSE(m.layout.seeds_estimated);
  ASSERT_EQ(m.layout.seeds.size(), 1u);
  // The seed is the scanner's own cell (it stands in free space).
  const auto& s = m.cloud_map.scanners.front();
  EXPECT_EQ(m.layout.seeds[0], m.geometry.cell_of({s.x(), s.y()}));

  cv::Mat free_mask(L.height, L.width, CV_8U, cv::Scalar(0));
  for (int r = 0; r < L.height; ++r)
    for (int c = 0; c < L.width; ++c) free_mask.at<std::uint8_t>(r, c) = L.at(c, r) == Cell::kFree;
  cv::Mat labels;
  EXPECT_EQ(cv::connectedComponents(free_mask, labels, 4, CV_32S), 2);  // background + one region
  const double cell_area = m.geometry.cell_m() * m.geometry.cell_m();
  EXPECT_GT(m.layout.cells_free * cell_area, 12.0);  // room of about 8.5 m x 6 m, crowded
  EXPECT_LT(m.layout.cells_free * cell_area, 51.0);

  // Enclosed: no free cell touches unknown space or the grid edge.
  for (int r = 0; r < L.height; ++r)
    for (int c = 0; c < L.width; ++c) {
      if (L.at(c, r) != Cell::kFree) continue;
      for (auto [dc, dr] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        ASSERT_TRUE(L.contains(c + dc, r + dr));
        ASSERT_NE(L.at(c + dc, r + dr), Cell::kUnknown) << "free cell " << c << "," << r;
      }
    }
}

TEST(JacobsPipeline, FurnitureStandsAlongTheWalls) {
  REQUIRE_JACOBS();
  const auto& m = J->map;
  const auto& L = m.layout.layout;
  const double cell_area = m.geometry.cell_m() * m.geometry.cell_m();
  EXPECT_GT(m.layout.cells_furniture * cell_area, 3.0);  // desks and cabinets
  // Most furniture lies within 1 m of a wall cell.
  cv::Mat not_wall(L.height, L.width, CV_8U, cv::Scalar(1));
  for (int r = 0; r < L.height; ++r)
    for (int c = 0; c < L.width; ++c)
      if (L.at(c, r) == Cell::kWall) not_wall.at<std::uint8_t>(r, c) = 0;
  cv::Mat dist;
  cv::distanceTransform(not_wall, dist, cv::DIST_L2, cv::DIST_MASK_5);
  std::int64_t near = 0, all = 0;
  for (int r = 0; r < L.height; ++r)
    for (int c = 0; c < L.width; ++c)
      if (L.at(c, r) == Cell::kFurniture) {
        ++all;
        near += dist.at<float>(r, c) * m.geometry.cell_m() <= 1.0;
      }
  ASSERT_GT(all, 0);
  EXPECT_GT(static_cast<double>(near) / all, 0.7);
}

TEST(JacobsPipeline, DesksAndCabinetsAlongTheWallsHavePlausibleSizesAndHeights) {
  REQUIRE_JACOBS();
  const auto& m = J->map;
  const auto objs = objects::extract_objects(m.layout.layout, m.geometry, m.voxels, m.layers, {},
                                             m.cloud_map.scanners);
  ASSERT_FALSE(objs.objects.empty());
  int along_walls = 0;
  for (const auto& o : objs.objects) {
    ASSERT_TRUE(o.has_height) << "object " << o.id;
    EXPECT_GE(o.z_min_m, m.layers.floor_z_m - 1e-9) << "object " << o.id;
    EXPECT_LE(o.z_max_m, m.layers.ceiling_z_m) << "object " << o.id;
    if (o.area_m2 < 0.3 || !o.touches_wall) continue;
    // Desks and cabinets: 0.5 to 2.3 m high, at most 2 m deep, standing on the floor. Since the
    // fragments are joined (issue 17) a row of low boxes along the south-west wall (0.25 m) is
    // one object of 0.3 m2 too: low objects are not desks and are not counted.
    const double height = o.z_max_m - m.layers.floor_z_m;
    if (height <= 0.5) continue;
    ++along_walls;
    EXPECT_LT(height, 2.3) << "object " << o.id;
    EXPECT_LT(o.box.width_m, 2.0) << "object " << o.id;
    EXPECT_TRUE(o.on_floor) << "object " << o.id;
  }
  EXPECT_GE(along_walls, 3);
}

// The two lamps of the scan hang over the desks; one reaches 2.15 m, into the low wall band
// (layers.low_wall_band_m). It stands on nothing, so it is no wall but a lamp, as the other.
TEST(JacobsPipeline, BothLampsAreLampsNotWall) {
  REQUIRE_JACOBS();
  const auto& m = J->map;
  const auto objs = objects::extract_objects(m.layout.layout, m.geometry, m.voxels, m.layers, {},
                                             m.cloud_map.scanners);
  int lamps = 0;
  for (const auto& o : objs.objects) lamps += o.kind == ObjectKind::kLamp;
  EXPECT_EQ(lamps, 2);
}
