#pragma once
// Shared by the point-cloud targets: the loader's options under fuzzing and the invariants of a
// successful load (a violation is a finding, reported as std::logic_error).
#include <stdexcept>
#include <string>

#include "fuzz_target.hpp"
#include "indoormap/cloud_io/load.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::fuzz {

inline cloud_io::LoadOptions cloud_options() {
  cloud_io::LoadOptions o;
  o.max_points = kMaxPoints;
  return o;
}

/// Loads path and checks: at least one point, all finite, counts consistent, within budget.
inline void load_and_check(const std::string& path) {
  const cloud_io::LoadResult r = cloud_io::load_cloud(path, cloud_options());
  if (r.cloud.points.empty() || r.inputs.size() != 1)
    throw std::logic_error("load succeeded without points");
  for (const auto& p : r.cloud.points)
    if (!p.allFinite()) throw std::logic_error("non-finite point kept");
  const auto& in = r.inputs.front();
  if (in.points_read > kMaxPoints || in.points_dropped > in.points_read ||
      in.points_read - in.points_dropped != r.cloud.points.size())
    throw std::logic_error("inconsistent point counts");
  for (const auto& s : r.cloud.scanners)
    if (!s.allFinite()) throw std::logic_error("non-finite scanner position");
}

}  // namespace indoormap::fuzz
