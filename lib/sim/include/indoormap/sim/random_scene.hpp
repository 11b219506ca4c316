#pragma once
// Plausible random scenes: K furnished rooms along a corridor, some L-shaped, some with a sloped
// ceiling, the whole building rotated by a random yaw, the scan slightly tilted. Deterministic:
// the same seed and parameters give the same scene.
#include <cstdint>
#include <optional>

#include "indoormap/sim/scene.hpp"

namespace indoormap::sim {

struct RandomSceneParams {
  int rooms = 1;              ///< furnished rooms (1..200); a corridor is always added
  double max_yaw_deg = 40.0;  ///< the building is rotated by a yaw in [-max, max]
  double max_tilt_deg = 1.5;  ///< tilt magnitude drawn from [0.3, max]
  double l_shape_probability = 0.3;
  double sloped_ceiling_probability = 0.2;
  bool scanner_in_corridor = true;  ///< also scan from the corridor when rooms >= 2
  /// When set, the building's yaw (degrees) instead of the drawn one; the draw still happens,
  /// so the rest of the scene is the same (random_building: every storey shares one yaw).
  std::optional<double> yaw_deg = std::nullopt;
};

/// Throws UsageError for rooms outside [1, 200]. Called by random_scene.
void validate(const RandomSceneParams& params);

/// Builds a random scene; scene.seed is set to seed (it also drives the noise).
/// Throws UsageError for invalid params (validate).
Scene random_scene(std::uint64_t seed, const RandomSceneParams& params = {});

/// The yaw (degrees) by which random_scene rotated its building: the direction of the corridor's
/// first edge (the corridor runs along +x before the rotation). nullopt without a corridor.
std::optional<double> random_scene_yaw_deg(const Scene& scene);

}  // namespace indoormap::sim
