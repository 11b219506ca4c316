// lib/scan_features: all features of one 360-beam scan (the target: under 0.5 ms) and one
// alignment of two consecutive scans (target: under 2 ms), both ICP variants from one start.
// Reference, measured in the same run: the conversion of the scan to laser-frame points.
// Scans: simulated rooms of lib/sim (random_scan_scene, doors onto closets, a pillar), 360 beams
// over 180 degrees (as freiburg-079), 1 cm range noise; the pair moved 10 cm and 2 degrees.
#include <benchmark/benchmark.h>

#include <numbers>
#include <random>
#include <vector>

#include "indoormap/scan_features/features.hpp"
#include "indoormap/scan_features/icp.hpp"
#include "indoormap/sim/scan_scenes.hpp"

using namespace indoormap;
using namespace indoormap::scan_features;

namespace {

struct Scans {
  std::vector<laser::LaserScan> a, b;  ///< pairs: b is a moved by (0.1 m, 0, 2 deg)
  Scans() {
    sim::LaserModel m;
    m.beams = 360;
    m.fov_rad = std::numbers::pi;
    for (std::uint64_t k = 0; k < 32; ++k) {
      const sim::ScanScene scene = sim::random_scan_scene(100 + k);
      std::mt19937_64 rng(k);
      const laser::Pose2d p = sim::random_pose(scene, 1.0, rng);
      a.push_back(sim::cast_scan(scene, p, m, rng));
      b.push_back(
          sim::cast_scan(scene, p.compose({0.1, 0.0, 2.0 * std::numbers::pi / 180}), m, rng));
    }
  }
};

const Scans& scans() {
  static const Scans s;
  return s;
}

void BM_ScanToPoints_Reference(benchmark::State& st) {
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(scan_points_laser(scans().a[i++ % scans().a.size()]));
  }
}
BENCHMARK(BM_ScanToPoints_Reference)->Unit(benchmark::kMicrosecond);

void BM_AllFeatures360Beams(benchmark::State& st) {
  const FeatureParams p;
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(extract_features(scans().a[i++ % scans().a.size()], p));
  }
}
BENCHMARK(BM_AllFeatures360Beams)->Unit(benchmark::kMicrosecond);

void BM_Align(benchmark::State& st) {
  IcpParams p;
  p.kind = st.range(0) == 0 ? IcpKind::kPointToPoint : IcpKind::kPointToLine;
  AlignSearch one_start;
  one_start.rotation_offsets_rad = {0.0};
  std::size_t i = 0;
  for (auto _ : st) {
    const std::size_t k = i++ % scans().a.size();
    benchmark::DoNotOptimize(align_scans(scans().a[k], scans().b[k], p, one_start));
  }
  st.SetLabel(icp_kind_name(p.kind));
}
BENCHMARK(BM_Align)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
