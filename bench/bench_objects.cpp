// furniture-extract: labelling of the furniture class with the paper's two-pass union-find
// (section 3.2.B, 4-connected; the paper: 1.3 ms mean on its 193 x 175 grid) side by side with
// cv::connectedComponentsWithStats (4-connected, CV_32S) on the same mask in the same run, on the
// Jacobs room grid and on a 2000 x 2000 synthetic furniture mask; and the whole extract_objects on
// the Jacobs map. The Jacobs data is read from ../shared/data (or $INDOORMAP_DATA); without it the
// Jacobs benchmarks report an error and are skipped. Results: docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <random>

#include "indoormap/layout/pipeline.hpp"
#include "indoormap/objects/label.hpp"
#include "indoormap/objects/objects.hpp"
#include "jacobs_fixtures.hpp"

using namespace indoormap;

namespace {

using bench::jacobs;

// Furniture mask of the Jacobs room layout M_r (1 = furniture).
const Grid<std::uint8_t>* jacobs_mask() {
  static std::optional<Grid<std::uint8_t>> g = []() -> std::optional<Grid<std::uint8_t>> {
    const auto* m = jacobs();
    if (!m) return std::nullopt;
    const auto& lay = m->layout.layout;
    Grid<std::uint8_t> mask(lay.width, lay.height, 0);
    for (std::size_t i = 0; i < lay.data.size(); ++i)
      mask.data[i] = lay.data[i] == Cell::kFurniture ? 1 : 0;
    return mask;
  }();
  return g ? &*g : nullptr;
}

// A furniture-like 2000 x 2000 mask: axis-aligned rectangles of 3..40 x 3..40 cells at random
// places (they may overlap and touch) until about 30 % of the cells are set. Fixed seed.
const Grid<std::uint8_t>& synthetic_mask() {
  static const Grid<std::uint8_t> g = [] {
    const int n = 2000;
    Grid<std::uint8_t> mask(n, n, 0);
    std::mt19937 rng(4);
    std::uniform_int_distribution<int> side(3, 40), pos(0, n - 1);
    const std::int64_t target = static_cast<std::int64_t>(0.30 * n * n);
    std::int64_t set = 0;
    while (set < target) {
      const int c0 = pos(rng), r0 = pos(rng);
      const int c1 = std::min(n, c0 + side(rng)), r1 = std::min(n, r0 + side(rng));
      for (int r = r0; r < r1; ++r)
        for (int c = c0; c < c1; ++c)
          if (!mask.at(c, r)) {
            mask.at(c, r) = 1;
            ++set;
          }
    }
    return mask;
  }();
  return g;
}

const Grid<std::uint8_t>* pick(benchmark::State& st) {
  if (st.range(0) == 1) return &synthetic_mask();
  const auto* m = jacobs_mask();
  if (!m) st.SkipWithError("Jacobs data not found (../shared/data or $INDOORMAP_DATA)");
  return m;
}

cv::Mat as_mat(const Grid<std::uint8_t>& g) {
  return cv::Mat(g.height, g.width, CV_8U, const_cast<std::uint8_t*>(g.data.data()));
}

void report(benchmark::State& st, const Grid<std::uint8_t>& mask, int components) {
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * mask.size()));
  st.counters["cells"] = static_cast<double>(mask.size());
  st.counters["components"] = components;
}

// Ours: two-pass raster labelling with a union-find table, 4-connected.
void BM_LabelOurs(benchmark::State& st) {
  const auto* mask = pick(st);
  if (!mask) return;
  int count = 0;
  for (auto _ : st) {
    auto l = objects::label_components(*mask, objects::Connectivity::k4);
    count = l.count;
    benchmark::DoNotOptimize(l.labels.data.data());
  }
  report(st, *mask, count);
}

// Reference: OpenCV on the same mask (wrapped, not copied); outputs allocated per call as ours.
void BM_LabelOpenCV(benchmark::State& st) {
  const auto* mask = pick(st);
  if (!mask) return;
  const cv::Mat in = as_mat(*mask);
  // The two must agree on the number of components, or the comparison means nothing.
  const int ours = objects::label_components(*mask, objects::Connectivity::k4).count;
  {
    cv::Mat labels, stats, centroids;
    if (cv::connectedComponentsWithStats(in, labels, stats, centroids, 4, CV_32S) - 1 != ours)
      return (void)st.SkipWithError("OpenCV and label_components disagree on the count");
  }
  int count = 0;
  for (auto _ : st) {
    cv::Mat labels, stats, centroids;
    count = cv::connectedComponentsWithStats(in, labels, stats, centroids, 4, CV_32S) - 1;
    benchmark::DoNotOptimize(labels.data);
  }
  report(st, *mask, count);
}

// The whole furniture extraction (labelling, height split, heights, boxes, outlines) on Jacobs.
void BM_ExtractObjectsJacobs(benchmark::State& st) {
  const auto* m = jacobs();
  if (!m)
    return (void)st.SkipWithError("Jacobs data not found (../shared/data or $INDOORMAP_DATA)");
  std::size_t n = 0;
  for (auto _ : st) {
    auto r = objects::extract_objects(m->layout.layout, m->geometry, m->voxels, m->layers);
    n = r.objects.size();
    benchmark::DoNotOptimize(r.objects.data());
  }
  st.counters["cells"] = static_cast<double>(m->layout.layout.size());
  st.counters["objects"] = static_cast<double>(n);
}

}  // namespace

// Arg 0: the Jacobs room grid; 1: the 2000 x 2000 synthetic mask. CPU time; read the ratios.
// Process CPU time, not the default thread CPU time: OpenCV labels large images with a parallel
// algorithm, and its worker threads' time must count too.
BENCHMARK(BM_LabelOurs)->Arg(0)->Arg(1)->MeasureProcessCPUTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LabelOpenCV)->Arg(0)->Arg(1)->MeasureProcessCPUTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ExtractObjectsJacobs)->MeasureProcessCPUTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
