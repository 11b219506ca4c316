#pragma once
// The terrestrial-scanner simulation: for every scanner position, a full turn of vertical fans
// cast into the scene, with range noise, range limits, occlusion and mixed pixels.
//
// Output frame: the tilted frame, i.e. the scene frame rotated by tilt_rotation(scene.tilt) about
// the origin, which is what a real (not quite level) scanner delivers. The scanner's angular
// pattern is regular in that frame. Deterministic: the same scene (including its seed) gives the
// same points, bit for bit, with the same build.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "indoormap/core/progress.hpp"
#include "indoormap/sim/scene.hpp"

namespace indoormap::sim {

struct SimOptions {
  /// Split every scanner position into scans of this many degrees of azimuth (the Jacobs data
  /// comes as 40-degree sectors); 0 or >= 360: one scan per position.
  double sector_deg = 0.0;
  /// Refuse scenes that would cast more rays than this (BudgetError), before allocating.
  std::uint64_t max_rays = 400'000'000;
  /// Rays cast of ray_count(scene), about every 100,000 rays (empty: none).
  ProgressFn progress;
};

/// One scan: points [begin, end) of SimResult::points, from one scanner position and sector.
struct ScanBlock {
  int scanner = 0;
  int sector = 0;
  double azimuth_begin_deg = 0.0;  ///< in the scanner's (tilted) frame, heading included
  double azimuth_end_deg = 360.0;
  std::size_t begin = 0, end = 0;
};

struct SimResult {
  std::vector<Eigen::Vector3f> points;  ///< tilted frame, metres, ordered scan by scan
  std::vector<ScanBlock> scans;
  std::vector<Eigen::Vector3d> scanner_positions_m;  ///< tilted frame, one per scene scanner
  std::uint64_t rays = 0;
  std::uint64_t returns = 0;       ///< == points.size()
  std::uint64_t mixed_pixels = 0;  ///< returns that are mixed pixels
};

/// Number of rays simulate() casts for the scene (all positions).
std::uint64_t ray_count(const Scene& scene);

/// Simulates every scanner position of the scene. Throws UsageError on an invalid scene
/// (check_scene) and BudgetError when ray_count exceeds options.max_rays.
SimResult simulate(const Scene& scene, const SimOptions& options = {});

/// Small deterministic generator (xoshiro256**, seeded through splitmix64); its sequences do not
/// depend on the standard library's distributions, so outputs are reproducible across builds.
class Rng {
 public:
  explicit Rng(std::uint64_t seed);
  std::uint64_t next();
  double uniform();  ///< [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  int uniform_int(int lo, int hi);  ///< [lo, hi] inclusive
  double normal();                  ///< standard normal (Marsaglia polar method)

 private:
  std::uint64_t s_[4];
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace indoormap::sim
