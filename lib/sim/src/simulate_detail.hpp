#pragma once
// Internal: the ray loop shared by the terrestrial scanner (simulate) and the mobile scanner
// (simulate_mobile). A pattern gives, per scanner position, the elevations of one column and the
// number and step of the azimuth columns (from the position's heading).
#include <functional>
#include <vector>

#include "indoormap/sim/simulate.hpp"

namespace indoormap::sim::detail {

struct RayPattern {
  std::vector<double> elevation_deg;  ///< one column, bottom to top
  int azimuths = 0;
  double azimuth_step_deg = 0.25;
  double azimuth_offset_deg = 0.0;  ///< added to the heading (0 for the terrestrial scanner)
};

using PatternFn = std::function<RayPattern(std::size_t scanner)>;

/// Casts pattern(s) from every scanner s of a normalised, valid scene (rays: the total, for
/// the budget check). Points, scans and noise as documented for simulate().
SimResult simulate_pattern(const Scene& scene, const SimOptions& options, std::uint64_t rays,
                           const PatternFn& pattern);

}  // namespace indoormap::sim::detail
