// Room border closure: stages 3 and 4 of the paper's Table 1 on the Jacobs room (border
// components: 0.3 ms mean; shortest path: 0.2 ms mean, Intel i5-4440), and the whole closure on
// a 2000 x 2000 map. The Jacobs data is read from ../shared/data (or $INDOORMAP_DATA); without it
// the Jacobs benchmarks report an error and are skipped.
#include <benchmark/benchmark.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "indoormap/border/border.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "jacobs_fixtures.hpp"

using namespace indoormap;

namespace {

using bench::jacobs;

// The Jacobs room's ring component (the room border), found once.
struct JacobsStages {
  Grid<std::uint8_t> heavy;
  border::LeeMarking marking;
  std::size_t ring = 0;
};
const JacobsStages* jacobs_stages() {
  static std::optional<JacobsStages> s = []() -> std::optional<JacobsStages> {
    const auto* m = jacobs();
    if (!m) return std::nullopt;
    JacobsStages st;
    st.heavy = border::heavy_border(m->layout.layout);
    st.marking = border::mark_border_components(m->layout.layout, st.heavy);
    std::int64_t best = -1;
    for (std::size_t i = 0; i < st.marking.components.size(); ++i)
      if (st.marking.components[i].kind == border::ComponentKind::kRing &&
          st.marking.components[i].cells > best) {
        best = st.marking.components[i].cells;
        st.ring = i;
      }
    return st;
  }();
  return s ? &*s : nullptr;
}

void BM_JacobsStage1_HeavyBorder(benchmark::State& state) {
  const auto* m = jacobs();
  if (!m) return state.SkipWithError("Jacobs data not found");
  for (auto _ : state) benchmark::DoNotOptimize(border::heavy_border(m->layout.layout));
}

void BM_JacobsStage3_BorderComponents(benchmark::State& state) {
  const auto* m = jacobs();
  const auto* st = jacobs_stages();
  if (!m || !st) return state.SkipWithError("Jacobs data not found");
  for (auto _ : state)
    benchmark::DoNotOptimize(border::mark_border_components(m->layout.layout, st->heavy));
}

// Stage 4 needs a fresh M_Lee per run (the wave writes into it): the copy is timed too, and
// BM_JacobsStage4_CopyOnly measures it alone so it can be subtracted.
void BM_JacobsStage4_ShortestPath(benchmark::State& state) {
  const auto* st = jacobs_stages();
  if (!st) return state.SkipWithError("Jacobs data not found");
  for (auto _ : state) {
    Grid<std::int32_t> lee = st->marking.lee;
    benchmark::DoNotOptimize(border::trace_ring(lee, st->marking.components[st->ring]));
  }
}

void BM_JacobsStage4_CopyOnly(benchmark::State& state) {
  const auto* st = jacobs_stages();
  if (!st) return state.SkipWithError("Jacobs data not found");
  for (auto _ : state) {
    Grid<std::int32_t> lee = st->marking.lee;
    benchmark::DoNotOptimize(lee.data.data());
  }
}

void BM_JacobsWholeClosure(benchmark::State& state) {
  const auto* m = jacobs();
  if (!m) return state.SkipWithError("Jacobs data not found");
  for (auto _ : state) benchmark::DoNotOptimize(border::close_border(*m));
}

// A 2000 x 2000 map (100 m x 100 m at 5 cm): one large room rotated by 30 degrees with walls,
// furniture blocks along them and a door.
void BM_WholeClosure2000(benchmark::State& state) {
  const int n = 2000;
  cv::Mat img(n, n, CV_8U, cv::Scalar(0));
  const cv::RotatedRect outer({1000.f, 1000.f}, {1500.f, 1100.f}, 30.f),
      inner({1000.f, 1000.f}, {1494.f, 1094.f}, 30.f);
  cv::Point2f po[4], pi[4];
  outer.points(po);
  inner.points(pi);
  auto poly = [](const cv::Point2f* p) {
    std::vector<cv::Point> v;
    for (int i = 0; i < 4; ++i) v.emplace_back(cvRound(p[i].x), cvRound(p[i].y));
    return v;
  };
  cv::fillConvexPoly(img, poly(po), cv::Scalar(1));
  cv::fillConvexPoly(img, poly(pi), cv::Scalar(3));
  for (int k = 0; k < 12; ++k) {
    const cv::RotatedRect f({500.f + 90.f * k, 700.f + 40.f * k}, {40.f, 80.f}, 30.f);
    cv::Point2f pf[4];
    f.points(pf);
    cv::fillConvexPoly(img, poly(pf), cv::Scalar(2));
  }
  const GridGeometry geo({0, 0}, 0.05, n, n);
  Grid<Cell> lay(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) lay.at(c, r) = static_cast<Cell>(img.at<std::uint8_t>(r, c));
  const std::vector<Eigen::Vector2d> scanner{geo.center_of({1000, 1000})};
  for (auto _ : state) benchmark::DoNotOptimize(border::close_border(lay, geo, scanner));
}

}  // namespace

BENCHMARK(BM_JacobsStage1_HeavyBorder)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_JacobsStage3_BorderComponents)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_JacobsStage4_ShortestPath)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_JacobsStage4_CopyOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_JacobsWholeClosure)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WholeClosure2000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
