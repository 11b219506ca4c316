// pcd-to-map stages: loading, levelling, voxelisation + layer split (against pcl::VoxelGrid on the
// same points, in the same run), and the 2D stages, on the Jacobs scan and a 10 M-point cloud.
// Results and how to read them: docs/benchmarks.md.
#include <benchmark/benchmark.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <random>

#include "../tests/ghost_reference.hpp"
#include "indoormap/cloud/ghosts.hpp"
#include "indoormap/cloud/level.hpp"
#include "indoormap/cloud/voxel.hpp"
#include "indoormap/cloud_io/load.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "synthetic.hpp"

using namespace indoormap;

namespace {

std::filesystem::path jacobs_dir() {
  if (const char* env = std::getenv("INDOORMAP_DATA"))
    return std::filesystem::path(env) / "jacobs-thermocolorlab";
  return std::filesystem::path(INDOORMAP_SOURCE_DIR) / ".." / "shared" / "data" /
         "jacobs-thermocolorlab";
}

// The inputs, levelled once (voxelisation benchmarks start from a levelled cloud).
struct Inputs {
  std::vector<Eigen::Vector3f> big;       // 10 M synthetic points, in scan order
  std::vector<Eigen::Vector3f> shuffled;  // the same points, shuffled
  std::vector<Eigen::Vector3f> jacobs;    // empty when the data is absent
  std::vector<Eigen::Vector3f> jacobs_raw;
  std::vector<Eigen::Vector3d> jacobs_scanners;
};

const Inputs& inputs() {
  static const Inputs in = [] {
    Inputs r;
    r.big = bench::synthetic_building(10'000'000);
    PointCloud c{r.big, {}, {}};
    cloud::rotate(c, cloud::estimate_level(c.points, {}).map_from_input);
    r.big = std::move(c.points);
    r.shuffled = r.big;
    std::shuffle(r.shuffled.begin(), r.shuffled.end(), std::mt19937(9));
    if (std::filesystem::exists(jacobs_dir())) {
      auto loaded = cloud_io::load_cloud(jacobs_dir().string());
      r.jacobs_raw = loaded.cloud.points;
      auto lv = cloud::estimate_level(loaded.cloud.points, {});
      cloud::rotate(loaded.cloud, lv.map_from_input);
      r.jacobs = std::move(loaded.cloud.points);
      r.jacobs_scanners = loaded.cloud.scanners;
    }
    return r;
  }();
  return in;
}

const std::vector<Eigen::Vector3f>& pick(int which) {
  return which == 0 ? inputs().big : which == 1 ? inputs().jacobs : inputs().shuffled;
}

bool skip_if_empty(benchmark::State& st, const std::vector<Eigen::Vector3f>& pts) {
  if (!pts.empty()) return false;
  st.SkipWithError("Jacobs data not found (../shared/data or $INDOORMAP_DATA)");
  return true;
}

void BM_LoadJacobs(benchmark::State& st) {
  if (!std::filesystem::exists(jacobs_dir()))
    return (void)st.SkipWithError("Jacobs data not found");
  std::size_t n = 0;
  for (auto _ : st) {
    auto r = cloud_io::load_cloud(jacobs_dir().string());
    n = r.cloud.points.size();
    benchmark::DoNotOptimize(r.cloud.points.data());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * n));
}

void BM_Level(benchmark::State& st) {
  const auto& pts = st.range(0) == 0 ? inputs().big : inputs().jacobs_raw;
  if (skip_if_empty(st, pts)) return;
  for (auto _ : st) benchmark::DoNotOptimize(cloud::estimate_level(pts, {}));
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * pts.size()));
}

// Ours: robust bounds + voxel counts + layer analysis + both band projections.
void BM_VoxelizeAndLayers(benchmark::State& st) {
  const auto& pts = pick(static_cast<int>(st.range(0)));
  if (skip_if_empty(st, pts)) return;
  cloud::VoxelParams vp;
  for (auto _ : st) {
    auto g = cloud::voxelize(pts, cloud::robust_bounds(pts, vp), vp);
    auto a = cloud::analyse_layers(g, {});
    auto mw = cloud::project_band(g, a.wall_band, 1);
    auto mf = cloud::project_band(g, a.furniture_band, 1);
    benchmark::DoNotOptimize(mw.data.data());
    benchmark::DoNotOptimize(mf.data.data());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * pts.size()));
}

// The ghost filter on the Jacobs grid: /0 with the default ray budget (every 2nd point), /1 with
// every point. Each iteration copies the grid first (BM_GhostsJacobsCopyOnly measures that).
void BM_GhostsJacobs(benchmark::State& st) {
  const auto& pts = inputs().jacobs;
  if (skip_if_empty(st, pts) || inputs().jacobs_scanners.size() != 1) {
    if (!pts.empty()) st.SkipWithError("Jacobs scan without exactly one scanner position");
    return;
  }
  cloud::VoxelParams vp;
  const auto g = cloud::voxelize(pts, cloud::robust_bounds(pts, vp), vp);
  cloud::GhostParams gp;
  if (st.range(0) == 1) gp.max_rays = pts.size();
  std::size_t rays = 0;
  for (auto _ : st) {
    auto copy = g;
    rays = cloud::remove_ghost_voxels(copy, pts, inputs().jacobs_scanners[0], gp).rays;
    benchmark::DoNotOptimize(copy.counts.data());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * rays));
}
// The reference: the first ghost filter, walking every ray voxel by voxel
// (tests/ghost_reference.hpp), same grid, same rays (/0 the default budget, /1 every point).
void BM_GhostsJacobsReference(benchmark::State& st) {
  const auto& pts = inputs().jacobs;
  if (skip_if_empty(st, pts) || inputs().jacobs_scanners.size() != 1) return;
  cloud::VoxelParams vp;
  const auto g = cloud::voxelize(pts, cloud::robust_bounds(pts, vp), vp);
  cloud::GhostParams gp;
  if (st.range(0) == 1) gp.max_rays = pts.size();
  const std::vector<cloud::RaySource> src{{pts, inputs().jacobs_scanners[0]}};
  std::size_t rays = 0;
  for (auto _ : st) {
    auto copy = g;
    rays = cloud::reference_remove_ghost_voxels(copy, src, gp).rays;
    benchmark::DoNotOptimize(copy.counts.data());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * rays));
}
// The 80 x 60 m hall (bench::synthetic_hall, 10 M points, one scanner): voxelisation (the
// reference of the same run), the ghost filter (/0 ours, /1 the ray-walking reference) and the
// whole in-process pipeline (layout::make_map: levelling, voxels, ghosts, layout, objects' grids).
const bench::Hall& hall() {
  static const bench::Hall h = bench::synthetic_hall(10'000'000);
  return h;
}
void BM_HallVoxelize(benchmark::State& st) {
  cloud::VoxelParams vp;
  for (auto _ : st) {
    auto g = cloud::voxelize(hall().points, cloud::robust_bounds(hall().points, vp), vp);
    benchmark::DoNotOptimize(g.counts.data());
  }
}
void BM_HallGhosts(benchmark::State& st) {
  cloud::VoxelParams vp;
  const auto g = cloud::voxelize(hall().points, cloud::robust_bounds(hall().points, vp), vp);
  const std::vector<cloud::RaySource> src{{hall().points, hall().scanner}};
  const cloud::GhostParams gp;
  std::int64_t removed = 0;
  for (auto _ : st) {
    auto copy = g;
    removed = st.range(0) == 0 ? cloud::remove_ghost_voxels_by_origin(copy, src, gp).voxels_removed
                               : cloud::reference_remove_ghost_voxels(copy, src, gp).voxels_removed;
    benchmark::DoNotOptimize(copy.counts.data());
  }
  st.counters["voxels_removed"] = static_cast<double>(removed);
}
void BM_HallMakeMap(benchmark::State& st) {
  for (auto _ : st) {
    PointCloud c{hall().points, {hall().scanner}, {}};
    auto r = layout::make_map(std::move(c), layout::MapParams{});
    benchmark::DoNotOptimize(r.ghosts.voxels_removed);
    for (const auto& t : r.timings) st.counters[t.stage + "_ms"] = t.ms;
    st.counters["voxels_removed"] = static_cast<double>(r.ghosts.voxels_removed);
  }
}
void BM_GhostsJacobsCopyOnly(benchmark::State& st) {
  const auto& pts = inputs().jacobs;
  if (skip_if_empty(st, pts)) return;
  cloud::VoxelParams vp;
  const auto g = cloud::voxelize(pts, cloud::robust_bounds(pts, vp), vp);
  for (auto _ : st) {
    auto copy = g;
    benchmark::DoNotOptimize(copy.counts.data());
  }
}
// Reference: pcl::VoxelGrid with the same leaf size on the same points (conversion excluded).
void BM_PclVoxelGrid(benchmark::State& st) {
  const auto& pts = pick(static_cast<int>(st.range(0)));
  if (skip_if_empty(st, pts)) return;
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(pts.size());
  for (const auto& p : pts) cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  pcl::VoxelGrid<pcl::PointXYZ> vg;
  vg.setLeafSize(0.05f, 0.05f, 0.05f);
  vg.setInputCloud(cloud);
  for (auto _ : st) {
    pcl::PointCloud<pcl::PointXYZ> out;
    vg.filter(out);
    benchmark::DoNotOptimize(out.data());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * pts.size()));
}

// The 2D stages (passage area, seeds, flood fill, furniture, closing) on the real room grid.
void BM_Layout2D(benchmark::State& st) {
  const auto& pts = pick(static_cast<int>(st.range(0)));
  if (skip_if_empty(st, pts)) return;
  cloud::VoxelParams vp;
  auto g = cloud::voxelize(pts, cloud::robust_bounds(pts, vp), vp);
  auto a = cloud::analyse_layers(g, {});
  auto mw = cloud::project_band(g, a.wall_band, 1);
  auto mf = cloud::project_band(g, a.furniture_band, 1);
  std::vector<Eigen::Vector2d> seeds;
  if (st.range(0) == 1)
    for (const auto& s : inputs().jacobs_scanners) seeds.emplace_back(s.x(), s.y());
  for (auto _ : st) benchmark::DoNotOptimize(layout::build_layout(mw, mf, g.geometry2d(), seeds));
  st.counters["cells"] = static_cast<double>(mw.size());
}

}  // namespace

// Arg 0: the 10 M-point synthetic building in scan order; 1: the Jacobs scan (516 k points);
// 2: the 10 M points shuffled. Times are CPU time; read the ratios, the machine is shared.
BENCHMARK(BM_LoadJacobs)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Level)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VoxelizeAndLayers)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GhostsJacobs)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GhostsJacobsReference)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HallVoxelize)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HallGhosts)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HallMakeMap)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GhostsJacobsCopyOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PclVoxelGrid)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Layout2D)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
