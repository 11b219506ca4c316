// Fewest-moves routes on every shared room-segmentation map (NAME.png, the empty buildings, at
// 0.05 m; skipped when ../shared/data is absent), between the map's far-apart pair
// (planning::far_apart_cells), with the default robot and planner: the min-link search, the
// paper's rules alone, the default planner (the paper's rules, then the min-link search bounded
// by them) and the exact search in the same run, each through plan_routes (safe zone and
// templates built once outside the timing). Counter "moves": the best route's moves. The exact
// search runs once, on the reference map kReferenceMap (about 85 s CPU; hours on the larger
// maps); run with
//   bench_planning_routes --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Results: docs/benchmarks.md ("Fewest-moves routes on building maps").
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "indoormap/formats/ros_map.hpp"
#include "indoormap/planning/planner.hpp"

using namespace indoormap;
using namespace indoormap::planning;

namespace {

/// The map the exact search runs on (its moves on all twelve maps: tests/test_planning_slow.cpp).
constexpr const char* kReferenceMap = "Freiburg52_scan";

struct MapCase {
  std::string name;
  formats::RosMap map;
  Grid<SafeCell> safe;
  Pose2 start, goal;
};

const Templates& templates() {
  static const Templates t = make_templates(RobotParams{}, PlannerParams{}, 0.05);
  return t;
}

std::vector<MapCase>& cases() {
  static std::vector<MapCase> all = [] {
    std::vector<MapCase> out;
    const auto dir = std::filesystem::path(INDOORMAP_SOURCE_DIR) / ".." / "shared" / "data" /
                     "room-segmentation-maps";
    if (!std::filesystem::exists(dir)) return out;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      const auto n = e.path().filename().string();
      if (e.path().extension() != ".png" || n.find("_furnitures") != std::string::npos ||
          n.find("_trashbins") != std::string::npos || n.find("_gt_") != std::string::npos)
        continue;
      files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      MapCase c{f.stem().string(), formats::read_plain_map(f, 0.05), {}, {}, {}};
      c.safe = safe_zone(c.map.cells, templates().disk);
      const auto far = far_apart_cells(c.safe);
      if (!far) continue;
      c.start = {c.map.geometry.center_of(far->first), 0.0};
      c.goal = {c.map.geometry.center_of(far->second), std::nullopt};
      out.push_back(std::move(c));
    }
    return out;
  }();
  return all;
}

/// `search` alone without a work budget (the paper's rules off unless it is kPaper), or the
/// default planner with its default budget when `defaults`. Counter "nodes": the optimal
/// search's expanded nodes (what planner.max_nodes bounds); "complete": it finished.
void run(benchmark::State& st, const MapCase& c, RouteSearch search, bool defaults = false) {
  PlannerParams p;
  if (!defaults) {
    p.search = search;
    p.paper_rules = search == RouteSearch::kPaper;
    p.max_nodes = 1'000'000'000;  // no budget: the exact search must finish
    p.max_seconds = 3600;
  }
  int moves = -1;
  PlanResult res;
  for (auto _ : st) {
    res = plan_routes(c.safe, c.map.geometry, c.start, c.goal, templates(), p);
    moves = res.routes.empty() ? -1 : res.routes.front().moves;
    benchmark::DoNotOptimize(moves);
  }
  st.counters["moves"] = moves;
  st.counters["nodes"] = static_cast<double>(res.exact_nodes);
  st.counters["complete"] = res.exact_complete;
  st.counters["cells"] = static_cast<double>(c.safe.size());
}

const bool registered = [] {
  for (const auto& c : cases()) {
    benchmark::RegisterBenchmark(("MinLink/" + c.name).c_str(), [&c](benchmark::State& st) {
      run(st, c, RouteSearch::kMinLink);
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Paper/" + c.name).c_str(), [&c](benchmark::State& st) {
      run(st, c, RouteSearch::kPaper);
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Default/" + c.name).c_str(), [&c](benchmark::State& st) {
      run(st, c, RouteSearch::kMinLink, true);
    })->Unit(benchmark::kMillisecond);
    if (c.name != kReferenceMap) continue;
    benchmark::RegisterBenchmark(("Exact/" + c.name).c_str(),
                                 [&c](benchmark::State& st) { run(st, c, RouteSearch::kExact); })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1)
        ->Repetitions(1);
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
