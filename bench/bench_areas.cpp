// lib/areas: the whole area split (rooms, corridors, crossings, polygons, graph) of each furnished
// room-segmentation map (the target: under 1 s per map on one core), against a reference
// measured in the same run: one cv::distanceTransform of the same map's free space.
// The maps are read from ../shared/data (or $INDOORMAP_DATA); without them the benchmarks are
// reported as errors and skipped. Run on one core: taskset -c 0, OPENCV_FOR_THREADS_NUM=1.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <opencv2/imgproc.hpp>
#include <string>

#include "indoormap/areas/areas.hpp"
#include "indoormap/formats/ros_map.hpp"

using namespace indoormap;

namespace {

const char* const kMaps[] = {"Freiburg52_scan", "Freiburg79_scan", "lab_a_scan", "lab_b_scan",
                             "lab_c_scan",      "lab_intel",       "office_a",   "office_b",
                             "office_c",        "office_d"};

std::filesystem::path data_dir() {
  if (const char* env = std::getenv("INDOORMAP_DATA"); env && *env) return env;
  return std::filesystem::path(INDOORMAP_SOURCE_DIR) / ".." / "shared" / "data";
}

/// The furnished map i, read once; nullptr when the data is absent.
const formats::RosMap* shared_map(int i) {
  static std::map<int, formats::RosMap> cache;
  auto it = cache.find(i);
  if (it != cache.end()) return &it->second;
  const auto path =
      data_dir() / "room-segmentation-maps" / (std::string(kMaps[i]) + "_furnitures.png");
  if (!std::filesystem::exists(path)) return nullptr;
  return &cache.emplace(i, formats::read_plain_map(path, 0.05, 250)).first->second;
}

void BM_SplitAreas(benchmark::State& st) {
  const formats::RosMap* m = shared_map(static_cast<int>(st.range(0)));
  if (!m) {
    st.SkipWithError("room-segmentation-maps not found (../shared/data or $INDOORMAP_DATA)");
    return;
  }
  st.SetLabel(kMaps[st.range(0)]);
  std::size_t n = 0;
  for (auto _ : st) {
    const areas::AreasResult r = areas::split_areas(m->cells, m->geometry, {});
    n = r.areas.size();
    benchmark::DoNotOptimize(n);
  }
  st.counters["areas"] = static_cast<double>(n);
  st.counters["cells"] = static_cast<double>(m->cells.size());
}

void BM_DistanceTransformReference(benchmark::State& st) {
  const formats::RosMap* m = shared_map(static_cast<int>(st.range(0)));
  if (!m) {
    st.SkipWithError("room-segmentation-maps not found (../shared/data or $INDOORMAP_DATA)");
    return;
  }
  st.SetLabel(kMaps[st.range(0)]);
  cv::Mat free(m->cells.height, m->cells.width, CV_8U);
  for (int r = 0; r < m->cells.height; ++r)
    for (int c = 0; c < m->cells.width; ++c)
      free.at<std::uint8_t>(r, c) = m->cells.at(c, r) == Cell::kFree ? 255 : 0;
  cv::Mat d;
  for (auto _ : st) {
    cv::distanceTransform(free, d, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
    benchmark::DoNotOptimize(d.data);
  }
}

}  // namespace

BENCHMARK(BM_SplitAreas)->DenseRange(0, 9)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DistanceTransformReference)->DenseRange(0, 9)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
