// Simulation speed (docs/benchmarks.md). Acceptance: >= 5 M simulated points per second on one
// core. The reference measured in the same run is the same ray caster with a single grid cell
// (every primitive tested for every ray), so the ratio shows what the uniform grid buys.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "indoormap/sim/random_scene.hpp"
#include "indoormap/sim/simulate.hpp"
#include "indoormap/sim/world.hpp"

using namespace indoormap::sim;

namespace {

/// A random scene of `rooms` furnished rooms, scanned every `step_deg` in azimuth and elevation.
Scene furnished_rooms(std::uint64_t seed, int rooms, double step_deg) {
  RandomSceneParams p;
  p.rooms = rooms;
  Scene s = random_scene(seed, p);
  s.scanner.azimuth_step_deg = s.scanner.elevation_step_deg = step_deg;
  return s;
}

Scene office_like() {
  return furnished_rooms(1, 1, 0.25);
}

/// 12 furnished rooms along a corridor, 13 scanner positions, about 20 M points.
Scene building() {
  return furnished_rooms(3, 12, 0.155);
}

void report(benchmark::State& state, std::uint64_t points, std::uint64_t rays) {
  state.counters["points"] = static_cast<double>(points);
  state.counters["points_per_s"] = benchmark::Counter(
      static_cast<double>(points) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["rays_per_s"] = benchmark::Counter(static_cast<double>(rays) * state.iterations(),
                                                    benchmark::Counter::kIsRate);
}

/// The whole simulation of one scene, per iteration.
void simulate_scene(benchmark::State& state, const Scene& s) {
  std::uint64_t points = 0, rays = 0;
  for (auto _ : state) {
    const SimResult r = simulate(s);
    points = r.points.size();
    rays = r.rays;
    benchmark::DoNotOptimize(r.points.data());
  }
  report(state, points, rays);
}

void BM_SimulateOffice(benchmark::State& state) {
  simulate_scene(state, office_like());
}
BENCHMARK(BM_SimulateOffice)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_SimulateBuilding20M(benchmark::State& state) {
  simulate_scene(state, building());
}
BENCHMARK(BM_SimulateBuilding20M)->Unit(benchmark::kSecond)->Iterations(1);

/// Ray casting alone on the building, through the grid (cell 0.5 m) or a single cell.
void cast_rays(benchmark::State& state, double cell_m) {
  Scene s = building();
  const SceneGeometry g = build_geometry(normalised(s));
  RayCaster rc(g, cell_m);
  const Eigen::Vector3d o = s.scanners[0].position_m;
  std::uint64_t hits = 0, rays = 0;
  for (auto _ : state) {
    for (int i = 0; i < 720; ++i) {
      const double az = i * 0.5 * std::numbers::pi / 180;
      for (int j = 0; j < 100; ++j) {
        const double el = (-40 + j) * std::numbers::pi / 180;
        const Eigen::Vector3d d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az),
                                std::sin(el));
        hits += rc.cast(o, d, 100.0).has_value();
        ++rays;
      }
    }
  }
  state.counters["rays_per_s"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
  state.counters["primitives"] = static_cast<double>(g.solids.size() + g.caps.size());
  benchmark::DoNotOptimize(hits);
}
void BM_CastRaysGrid(benchmark::State& state) {
  cast_rays(state, 0.5);
}
void BM_CastRaysSingleCellReference(benchmark::State& state) {
  cast_rays(state, 1e6);
}
BENCHMARK(BM_CastRaysGrid)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CastRaysSingleCellReference)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
