#pragma once
// Origins of a merged cloud: which position saw which point, estimated where the input does not
// say (one merged PCD with --scanner per position, a mobile scanner's cloud and trajectory).
// docs/pipeline.md, "Ghost filter per origin".
#include <cstddef>

#include "indoormap/core/cloud.hpp"

namespace indoormap::layout {

struct NearestOriginResult {
  bool applied = false;   ///< origins set (at least 2 positions, points, and few enough)
  std::size_t spans = 0;  ///< origin spans written (positions that got points)
  double lookup_cell_m = 0.0;
};

/// Takes every point as seen from the position nearest to it in the plane (per cell of a lookup
/// grid of about 0.25 m, coarser for very many positions), reorders cloud.points by that position
/// (an in-place counting sort: no copy of the points) and sets cloud.origins to one span per
/// position. The ghost filter's evidence is the rays that pass through a voxel: a room's own
/// scanner, its nearest, passes through the veil of mixed pixels another position left there
/// through the door. A point its nearest position could not see gives a ray through a wall; the
/// filter counts a ray only for voxels 4 layers above or below its end (GhostParams), and a wall
/// voxel holds more points than a ghost may. Does nothing with fewer than 2 positions, no points,
/// or more than 65535 positions.
NearestOriginResult assign_nearest_origins(PointCloud& cloud);

}  // namespace indoormap::layout
