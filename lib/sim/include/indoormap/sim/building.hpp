#pragma once
// Buildings: storeys stacked on slabs, each storey an ordinary Scene in its own storey frame
// (floor at z = 0), placed at floor_z_m in the building's scene frame. A slab lies between the
// highest ceiling of a storey and the floor of the next one, so no ray passes from one storey to
// another: every storey is simulated on its own and the clouds are merged (rays leaving through a
// window do not see the outer walls of other storeys; docs/scene-sim.md says so).
//
// Frames: storey frame (x, y) = scene frame (x, y); z_scene = z_storey + floor_z_m. The cloud is
// in the tilted frame, p_cloud = tilt_rotation(tilt) * p_scene, as for a single scene.
#include <cstdint>
#include <string>
#include <vector>

#include "indoormap/sim/random_scene.hpp"
#include "indoormap/sim/scene.hpp"
#include "indoormap/sim/simulate.hpp"

namespace indoormap::sim {

struct Storey {
  Scene scene;               ///< storey frame; its tilt is the building's
  double floor_z_m = 0.0;    ///< scene frame
  double ceiling_z_m = 0.0;  ///< scene frame: the highest ceiling point of the storey
};

struct Building {
  std::vector<Storey> storeys;  ///< bottom to top
};

struct BuildingParams {
  RandomSceneParams random;       ///< the rooms of every storey
  int storeys = 1;                ///< 1..20
  double slab_thickness_m = 0.3;  ///< from the highest ceiling of a storey to the next floor
  /// Every storey has the same rooms and furniture (storey 0's); else each storey draws its own
  /// layout (seed derived from the building's seed), with the building's yaw and tilt.
  bool same_footprint = false;
};

/// Throws UsageError for storeys outside [1, 20] or a slab outside [0.15, 2] m (the walls rise
/// 0.1 m above the ceiling into the slab), and for invalid random params.
void validate(const BuildingParams& params);

/// Highest ceiling point of a scene, storey frame.
double storey_top_z(const Scene& scene);

/// Stacks storey scenes (storey frames) bottom to top on slabs; every storey gets the tilt of
/// the first one. Throws UsageError when a storey is invalid (check_scene) or empty.
Building stack_storeys(std::vector<Scene> storeys, double slab_thickness_m = 0.3);

/// A random building: storey 0 is random_scene(seed, params.random) exactly (so a one-storey
/// building is the random scene of today); storey k > 0 is drawn with a seed derived from seed
/// and k (or copied, same_footprint), and shares storey 0's yaw and tilt.
Building random_building(std::uint64_t seed, const BuildingParams& params = {});

/// Which storey of the building a scan block belongs to (SimResult::scans[i].scanner indexes the
/// building's scanners storey by storey).
struct BuildingSim {
  SimResult sim;                    ///< merged, tilted frame; scanners storey by storey
  std::vector<int> scanner_storey;  ///< per merged scanner
};

/// Simulates every storey with simulate() and merges them (merge_storeys).
/// For one storey at floor 0 the result is simulate(storey.scene) bit for bit.
BuildingSim simulate_building(const Building& building, const SimOptions& options = {});

/// Merges the per-storey results of a building (each in its storey's tilted frame) into one, in
/// the building's tilted frame: points and scanner positions move by R * (0, 0, floor_z_m).
BuildingSim merge_storeys(const Building& building, std::vector<SimResult> storeys);

}  // namespace indoormap::sim
