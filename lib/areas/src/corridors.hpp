#pragma once
// Corridors and crossings (internal to im_areas): each room piece that is long and narrow becomes
// a corridor; its confirmed junctions and corners are cut out as crossings.
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "indoormap/areas/areas.hpp"

namespace indoormap::areas::detail {

struct CorridorSplit {
  Grid<int> labels;              ///< 1..kinds.size()
  std::vector<AreaKind> kinds;   ///< kinds[label - 1]
  std::vector<CrossingCheck> checks;  ///< at_m in continuous cell coordinates
};

/// pieces: labels 1..n; reach: the cells the footprint reaches (for the fan-of-turns test).
CorridorSplit split_corridors(const Grid<int>& pieces, int n, const Grid<std::uint8_t>& reach,
                              const Grid<std::uint8_t>& free, double cell_m,
                              const AreasParams& params);

/// Zhang-Suen thinning of a 0/1 image (8-connected skeleton), in place.
void thin(cv::Mat& img);

}  // namespace indoormap::areas::detail
