// lib/laser: one 360-beam scan integrated into a 0.05 m grid (HIMM and log-odds; the issue's
// target: under 0.2 ms), the consistency check of one scan, and Bresenham lines.
// The scan: a 10 m x 8 m room seen from inside, ranges cast exactly, 360 beams over 360 degrees
// (mean range about 4 m, so about 80 cells per beam).
#include <benchmark/benchmark.h>

#include <numbers>
#include <random>

#include "indoormap/laser/bresenham.hpp"
#include "indoormap/laser/mappers.hpp"
#include "indoormap/laser/raycast.hpp"

using namespace indoormap;
using namespace indoormap::laser;

namespace {

struct Room {
  GridGeometry g{{0.0, 0.0}, 0.05, 200, 160};
  Grid<Cell> cells{200, 160, Cell::kFree};
  std::vector<LaserScan> scans;
  Room() {
    for (int c = 0; c < 200; ++c) cells.at(c, 0) = cells.at(c, 159) = Cell::kWall;
    for (int r = 0; r < 160; ++r) cells.at(0, r) = cells.at(199, r) = Cell::kWall;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> x(2.0, 8.0), y(2.0, 6.0), th(-3.0, 3.0);
    for (int k = 0; k < 64; ++k) {
      LaserScan s;
      s.max_range_m = 30.0;
      s.angle_min_rad = -std::numbers::pi;
      s.angle_increment_rad = 2 * std::numbers::pi / 360;
      s.robot_pose_map = {x(rng), y(rng), th(rng)};
      for (int i = 0; i < 360; ++i)
        s.ranges_m.push_back(
            static_cast<float>(cast_ray(cells, g, s.robot_pose_map.position_m(),
                                        s.robot_pose_map.theta_rad + s.beam_angle_rad(i), 30.0) +
                               0.02));
      scans.push_back(std::move(s));
    }
  }
};

const Room& room() {
  static const Room r;
  return r;
}

void BM_Update360(benchmark::State& st) {
  const Room& r = room();
  OccupancyGridParams p;
  p.fixed_geometry = r.g;
  auto m = make_mapper(st.range(0) ? MapperKind::kLogOdds : MapperKind::kHimm, p);
  std::size_t k = 0;
  for (auto _ : st) m->integrate(r.scans[k++ % r.scans.size()]);
  st.SetLabel(std::string(to_string(st.range(0) ? MapperKind::kLogOdds : MapperKind::kHimm)) +
              ", fixed 200 x 160 grid");
}
BENCHMARK(BM_Update360)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// The same into a growing grid (the laser-to-map default): the bound check per scan.
void BM_Update360Growing(benchmark::State& st) {
  const Room& r = room();
  auto m = make_mapper(MapperKind::kHimm, OccupancyGridParams{});
  std::size_t k = 0;
  for (auto _ : st) m->integrate(r.scans[k++ % r.scans.size()]);
}
BENCHMARK(BM_Update360Growing)->Unit(benchmark::kMicrosecond);

void BM_ConsistencyScan(benchmark::State& st) {
  const Room& r = room();
  ConsistencyCheck check(r.cells, r.g);
  std::size_t k = 0;
  for (auto _ : st) check.add(r.scans[k++ % r.scans.size()]);
}
BENCHMARK(BM_ConsistencyScan)->Unit(benchmark::kMicrosecond);

void BM_Bresenham100(benchmark::State& st) {
  std::size_t n = 0;
  for (auto _ : st) {
    bresenham({0, 0}, {100, 37}, [&](CellIndex c) {
      n += static_cast<std::size_t>(c.col);
      return true;
    });
    benchmark::DoNotOptimize(n);
  }
}
BENCHMARK(BM_Bresenham100);

}  // namespace

BENCHMARK_MAIN();
