// lib/exploration: WFD on a 1000 x 1000 map (the target: under 20 ms), one goal choice
// per rule, and a whole exploration of a shared furnished map (target: at least 100 times faster
// than real time at 0.4 m/s; the counter realtime_x is simulated time / wall time).
// The shared map is read from ../shared/data (or $INDOORMAP_DATA); without it that benchmark is
// skipped.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <random>

#include "indoormap/exploration/coverage.hpp"
#include "indoormap/exploration/explore.hpp"

using namespace indoormap;
using namespace indoormap::exploration;

namespace {

// 1000 x 1000 cells: the west 60 % explored (free, with 200 boxes of furniture and a wall grid
// of rooms with doors), the rest unknown: one long frontier and many small ones.
const Grid<Cell>& explored_map() {
  static const Grid<Cell> m = [] {
    Grid<Cell> g(1000, 1000, Cell::kUnknown);
    for (int r = 0; r < 1000; ++r)
      for (int c = 0; c < 600; ++c) g.at(c, r) = Cell::kFree;
    for (int k = 100; k < 600; k += 100)
      for (int r = 0; r < 1000; ++r)
        if (r % 100 > 20) g.at(k, r) = Cell::kWall;  // walls with 20-cell doors
    std::mt19937 rng(9);
    for (int b = 0; b < 200; ++b) {
      const int c0 = static_cast<int>(rng() % 580), r0 = static_cast<int>(rng() % 980);
      for (int r = r0; r < r0 + 8; ++r)
        for (int c = c0; c < c0 + 8; ++c) g.at(c, r) = Cell::kFurniture;
      for (int k = 0; k < 6; ++k) g.at(c0 + k, r0 + 12) = Cell::kUnknown;  // unseen specks
    }
    return g;
  }();
  return m;
}

void BM_Wfd1000(benchmark::State& st) {
  const Grid<Cell>& m = explored_map();
  const GridGeometry g({0, 0}, 0.05, 1000, 1000);
  std::size_t frontiers = 0;
  for (auto _ : st) {
    const WfdResult r = detect_frontiers(m, g, {50, 50});
    frontiers = r.frontiers.size();
    benchmark::DoNotOptimize(r.frontiers.data());
  }
  st.counters["frontiers"] = static_cast<double>(frontiers);
}
BENCHMARK(BM_Wfd1000)->Unit(benchmark::kMillisecond);

void BM_ChooseGoal1000(benchmark::State& st) {
  const Grid<Cell>& m = explored_map();
  const GridGeometry g({0, 0}, 0.05, 1000, 1000);
  GoalParams gp;
  gp.rule = st.range(0) ? GoalRule::kGainPerCost : GoalRule::kNearestFrontier;
  for (auto _ : st) {
    Blacklist bl;
    const GoalChoice c = choose_goal(m, g, {50, 50}, bl, gp, {});
    benchmark::DoNotOptimize(c.goal);
  }
  st.SetLabel(std::string(to_string(gp.rule)));
}
BENCHMARK(BM_ChooseGoal1000)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

std::filesystem::path data_dir() {
  if (const char* env = std::getenv("INDOORMAP_DATA"); env && *env) return env;
  return std::filesystem::path(INDOORMAP_SOURCE_DIR) / ".." / "shared" / "data";
}

void BM_ExploreSharedMap(benchmark::State& st) {
  const auto path = data_dir() / "room-segmentation-maps" / "lab_c_scan_furnitures.png";
  const cv::Mat img = cv::imread(path.string(), cv::IMREAD_GRAYSCALE);
  if (img.empty()) return (void)st.SkipWithError("room-segmentation maps not found");
  Grid<Cell> truth(img.cols, img.rows);
  for (int r = 0; r < img.rows; ++r)
    for (int c = 0; c < img.cols; ++c)
      truth.at(c, img.rows - 1 - r) = img.at<unsigned char>(r, c) < 250 ? Cell::kWall : Cell::kFree;
  const GridGeometry g({0, 0}, 0.05, img.cols, img.rows);
  ExploreParams p;
  p.goal.rule = st.range(0) ? GoalRule::kGainPerCost : GoalRule::kNearestFrontier;
  const auto starts = start_points(truth, g, 0.3, {0.5});
  double sim_s = 0.0, wall_s = 0.0, dist = 0.0, share = 0.0;
  for (auto _ : st) {
    const auto t0 = std::chrono::steady_clock::now();
    const ExploreResult r = explore(truth, g, {starts[0].x(), starts[0].y(), 0.0}, p);
    wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    sim_s += r.time_s;
    dist = r.distance_m;
    share = r.explored_share;
  }
  st.counters["realtime_x"] = sim_s / wall_s;
  st.counters["distance_m"] = dist;
  st.counters["explored"] = share;
  st.SetLabel("lab_c_scan_furnitures, " + std::string(to_string(p.goal.rule)));
}
BENCHMARK(BM_ExploreSharedMap)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
