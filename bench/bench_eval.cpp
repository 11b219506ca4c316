// map-eval: sim::evaluate_objects on N truth furniture items spread over a building (a grid of
// rotated boxes 1.5 m apart), the result the same items shifted by 4 cm with every tenth missing
// and every twentieth spurious. Side by side in the same run: the all-pairs loop it replaced
// with the cell-by-cell raster IoU (reference, kept here), which tests every truth item against
// every result object (quadratic; 30,000 items took over a minute in map-eval). Results:
// docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>

#include "indoormap/core/polygon.hpp"
#include "indoormap/sim/eval.hpp"

using namespace indoormap;

namespace {

struct Items {
  std::vector<sim::EvalObject> truth, result;
};

const Items& items(int n) {
  static std::map<int, Items> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  Items s;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> size(0.4, 1.2), yaw(0.0, 3.14159);
  const int cols = static_cast<int>(std::ceil(std::sqrt(n)));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d c(1.5 * (i % cols), 1.5 * (i / cols));
    const Eigen::Vector2d wh(size(rng), size(rng));
    const double a = yaw(rng);
    sim::EvalObject t{"t" + std::to_string(i), "table", rectangle(c, wh, a), 0.0, 0.75, true};
    s.truth.push_back(t);
    if (i % 10 != 0) {
      sim::EvalObject r = t;
      r.id = "r" + std::to_string(i);
      r.footprint = rectangle(c + Eigen::Vector2d(0.04, 0.0), wh, a);
      s.result.push_back(r);
    }
    if (i % 20 == 0)
      s.result.push_back({"s" + std::to_string(i), "",
                          rectangle(c + Eigen::Vector2d(0.7, 0.7), {0.2, 0.2}, 0.0), 0.0, 0.5,
                          true});
  }
  return cache.emplace(n, std::move(s)).first->second;
}

// The replaced raster IoU: every cell centre tested with contains() (now a row scan).
double iou_cell_by_cell(const Polygon& a, const Polygon& b, double cell_m) {
  const auto [alo, ahi] = bounds(a);
  const auto [blo, bhi] = bounds(b);
  const Eigen::Vector2d lo = alo.cwiseMin(blo), hi = ahi.cwiseMax(bhi);
  if (alo.x() > bhi.x() || blo.x() > ahi.x() || alo.y() > bhi.y() || blo.y() > ahi.y()) return 0.0;
  const double cell = std::max(cell_m, std::sqrt((hi - lo).prod() / 4e6));
  const int w = static_cast<int>(std::ceil((hi.x() - lo.x()) / cell));
  const int h = static_cast<int>(std::ceil((hi.y() - lo.y()) / cell));
  std::int64_t inter = 0, uni = 0;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const Eigen::Vector2d p(lo.x() + (c + 0.5) * cell, lo.y() + (r + 0.5) * cell);
      const bool ia = contains(a, p), ib = contains(b, p);
      inter += ia && ib;
      uni += ia || ib;
    }
  return uni > 0 ? static_cast<double>(inter) / static_cast<double>(uni) : 0.0;
}

// The replaced loop: every pair, each rasterised cell by cell (disjoint boxes return early).
int all_pairs_matches(const std::vector<sim::EvalObject>& truth,
                      const std::vector<sim::EvalObject>& result, double min_iou) {
  int pairs = 0;
  for (const auto& t : truth)
    for (const auto& r : result) {
      if (t.footprint.size() < 3 || r.footprint.size() < 3) continue;
      pairs += iou_cell_by_cell(t.footprint, r.footprint, 0.01) >= min_iou;
    }
  return pairs;
}

void BM_EvaluateObjects(benchmark::State& state) {
  const Items& s = items(static_cast<int>(state.range(0)));
  int matched = 0;
  for (auto _ : state) {
    const auto scores = sim::evaluate_objects(s.truth, s.result, 0.5);
    matched = scores.matched;
    benchmark::DoNotOptimize(matched);
  }
  state.counters["matched"] = matched;
}
BENCHMARK(BM_EvaluateObjects)->Arg(3000)->Arg(30000)->Unit(benchmark::kMillisecond);

void BM_EvaluateObjectsAllPairsReference(benchmark::State& state) {
  const Items& s = items(static_cast<int>(state.range(0)));
  int pairs = 0;
  for (auto _ : state) {
    pairs = all_pairs_matches(s.truth, s.result, 0.5);
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["pairs"] = pairs;
}
BENCHMARK(BM_EvaluateObjectsAllPairsReference)->Arg(3000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
