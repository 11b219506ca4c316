#pragma once
// A whole simulated floor (or building) in one call, for scene-sim and for tests: the random
// building of N rooms and S storeys for a seed, its mobile paths (mobile mode), the merged
// simulation, and per storey the truth layout and the seen mask. scene-sim --random --seed N
// --rooms K --storeys S [--mobile] computes exactly this before writing its files.
#include <cstdint>
#include <string>
#include <vector>

#include "indoormap/sim/building.hpp"
#include "indoormap/sim/ground_truth.hpp"
#include "indoormap/sim/mobile.hpp"
#include "indoormap/sim/seen.hpp"

namespace indoormap::sim {

/// Per storey: the truth layout and the seen mask on its grid.
struct StoreyTruth {
  TruthLayout layout;
  Grid<std::uint8_t> seen;
};

/// The truth of every storey of a simulated building (sim: its merged simulation).
std::vector<StoreyTruth> storey_truths(const Building& building, const BuildingSim& sim,
                                       double truth_cell_m = 0.05, const SeenParams& seen = {});

/// Mobile mode: every storey's scanners become its planned path's poses (plan_mobile_path on
/// the storey's truth layout at truth_cell_m). Returns the paths; throws InputError when a
/// storey gets no path at all.
std::vector<MobilePath> plan_mobile_paths(Building& building, const MobileParams& params,
                                          double truth_cell_m = 0.05);

/// Simulates every storey (simulate, or simulate_mobile with mobile) and merges them.
BuildingSim simulate_storeys(const Building& building, const SimOptions& options = {},
                             const MobileParams* mobile = nullptr);

struct FloorSceneParams {
  BuildingParams building;  ///< rooms (building.random.rooms), storeys, slab
  ScannerParams scanner;    ///< of every storey
  bool mobile = false;
  MobileParams mobile_params;
  SeenParams seen;
  SimOptions sim;
  double truth_cell_m = 0.05;
};

struct FloorScene {
  Building building;
  std::vector<MobilePath> paths;  ///< mobile mode: per storey
  BuildingSim sim;
  std::vector<StoreyTruth> truths;
};

/// The building scene scene-sim --random simulates for seed and params, with its truth.
FloorScene simulate_floor_scene(std::uint64_t seed, const FloorSceneParams& params = {});

}  // namespace indoormap::sim
