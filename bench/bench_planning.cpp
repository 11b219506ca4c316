// Stages of the paper's Table 1 (section 3.2.D) on the Jacobs room (when ../shared/data is
// present; otherwise a synthetic 207 x 190 room) and on a synthetic 2000 x 2000 map.
// Table 1 (ms): safe-zone template 28.8, layout 3, wave 2, region 1, neighbourhood template
// 404.3, scenario 1.8.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <random>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "indoormap/planning/planner.hpp"

using namespace indoormap;
using namespace indoormap::planning;

namespace {

struct Scene {
  Grid<Cell> layout;
  GridGeometry geo;
  Pose2 start, goal;
};

Scene synthetic(int n) {
  Scene s{Grid<Cell>(n, n, Cell::kFree), GridGeometry({0, 0}, 0.05, n, n), {}, {}};
  std::mt19937 rng(3);
  for (int c = 0; c < n; ++c) s.layout.at(c, 0) = s.layout.at(c, n - 1) = Cell::kWall;
  for (int r = 0; r < n; ++r) s.layout.at(0, r) = s.layout.at(n - 1, r) = Cell::kWall;
  for (int b = 0; b < n * n / 4000; ++b) {
    const int c0 = 20 + static_cast<int>(rng() % (n - 60)),
              r0 = 20 + static_cast<int>(rng() % (n - 60));
    for (int r = r0; r < r0 + 12; ++r)
      for (int c = c0; c < c0 + 12; ++c) s.layout.at(c, r) = Cell::kFurniture;
  }
  s.start = {{0.6, 0.6}, 0.0};
  s.goal = {{n * 0.05 * 0.35, n * 0.05 * 0.3}, std::nullopt};
  return s;
}

const Scene& jacobs() {
  static const Scene s = [] {
    const auto dir = std::filesystem::path(INDOORMAP_SOURCE_DIR) / ".." / "shared" / "data" /
                     "jacobs-thermocolorlab";
    if (!std::filesystem::exists(dir)) return synthetic(200);
    auto loaded = cloud_io::load_clouds({dir.string()}, {});
    const auto m = layout::make_map(std::move(loaded.cloud), {});
    return Scene{m.layout.layout, m.geometry, {{-1.2, 0.1}, 0.0}, {{2.6, -1.6}, std::nullopt}};
  }();
  return s;
}

const Scene& big() {
  static const Scene s = synthetic(2000);
  return s;
}

const Scene& scene(int which) {
  return which == 0 ? jacobs() : big();
}

const PlannerParams kParams;
const RobotParams kRobot;

void BM_SafeZoneTemplate(benchmark::State& st) {
  for (auto _ : st) benchmark::DoNotOptimize(make_disk_template(d_save_m(kRobot), 0.05));
}
void BM_NeighbourhoodTemplate(benchmark::State& st) {
  for (auto _ : st) benchmark::DoNotOptimize(make_neighbourhood_template(kParams.d_max_m, 0.05));
}
void BM_SafeZoneLayout(benchmark::State& st) {
  const auto& s = scene(static_cast<int>(st.range(0)));
  const auto disk = make_disk_template(d_save_m(kRobot), 0.05);
  for (auto _ : st) benchmark::DoNotOptimize(safe_zone(s.layout, disk));
}
void BM_Wave(benchmark::State& st) {
  const auto& s = scene(static_cast<int>(st.range(0)));
  const auto safe = safe_zone(s.layout, make_disk_template(d_save_m(kRobot), 0.05));
  const auto a = s.geo.cell_of(s.start.position_map), b = s.geo.cell_of(s.goal.position_map);
  for (auto _ : st) benchmark::DoNotOptimize(lee_wave(safe, a, b));
}
void BM_Region(benchmark::State& st) {
  const auto& s = scene(static_cast<int>(st.range(0)));
  const auto safe = safe_zone(s.layout, make_disk_template(d_save_m(kRobot), 0.05));
  const auto a = s.geo.cell_of(s.start.position_map), b = s.geo.cell_of(s.goal.position_map);
  const auto wave = lee_wave(safe, a, b);
  for (auto _ : st) benchmark::DoNotOptimize(trajectory_region(wave, a, b));
}
/// Scenario generation = plan_routes (wave + region + moves + ranking), paper rules only (range 1
/// = 0) or combined with the exact search (1) or the min-link search (2, the default).
void BM_Scenario(benchmark::State& st) {
  const auto& s = scene(static_cast<int>(st.range(0)));
  PlannerParams p = kParams;
  p.search = st.range(1) == 0   ? RouteSearch::kPaper
             : st.range(1) == 1 ? RouteSearch::kExact
                                : RouteSearch::kMinLink;
  const auto tmpl = make_templates(kRobot, p, 0.05);
  const auto safe = safe_zone(s.layout, tmpl.disk);
  for (auto _ : st) benchmark::DoNotOptimize(plan_routes(safe, s.geo, s.start, s.goal, tmpl, p));
}
/// Everything per request once the templates exist: safe zone + planning.
void BM_WholePlanning(benchmark::State& st) {
  const auto& s = scene(static_cast<int>(st.range(0)));
  const auto tmpl = make_templates(kRobot, kParams, 0.05);
  for (auto _ : st) {
    const auto safe = safe_zone(s.layout, tmpl.disk);
    benchmark::DoNotOptimize(plan_routes(safe, s.geo, s.start, s.goal, tmpl, kParams));
  }
}

}  // namespace

// Arg 0 = Jacobs room, 1 = 2000 x 2000 map.
BENCHMARK(BM_SafeZoneTemplate)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NeighbourhoodTemplate)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SafeZoneLayout)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Wave)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Region)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Scenario)
    ->Args({0, 0})
    ->Args({0, 1})
    ->Args({0, 2})
    ->Args({1, 0})
    ->Args({1, 1})
    ->Args({1, 2})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WholePlanning)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
