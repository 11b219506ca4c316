#pragma once
// Corridors and crossings (internal to im_areas): each room piece that is long and narrow becomes
// a corridor; its confirmed junctions and corners are cut out as crossings.
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "indoormap/areas/areas.hpp"

namespace indoormap::areas::detail {

struct CorridorSplit {
  Grid<int> labels;                   ///< 1..kinds.size()
  std::vector<AreaKind> kinds;        ///< kinds[label - 1]
  std::vector<CrossingCheck> checks;  ///< at_m in continuous cell coordinates
};

/// pieces: labels 1..n; reach: the cells the footprint reaches (for the fan-of-turns test).
CorridorSplit split_corridors(const Grid<int>& pieces, int n, const Grid<std::uint8_t>& reach,
                              const Grid<std::uint8_t>& free, double cell_m,
                              const AreasParams& params);

/// Zhang-Suen thinning of a 0/1 image (8-connected skeleton), in place.
void thin(cv::Mat& img);
/// Removes end cells `times` times (spurs shorter than that vanish).
void prune(cv::Mat& skel, int times);

inline constexpr int kNb[8][2] = {{1, 0},  {1, 1},   {0, 1},  {-1, 1},
                                  {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};

/// Skeleton cells within path length k of start (steps of 1 and sqrt 2 along the skeleton), and
/// the rim: the first cells at k or beyond on each way out. dist: CV_32F scratch of skel's size,
/// all negative on entry and on return.
struct Reach {
  std::vector<cv::Point> rim;
  std::vector<cv::Point> within;
};
Reach skeleton_reach(const cv::Mat& skel, cv::Point start, double k, cv::Mat& dist);
/// Groups rim cells into arms (8-adjacent cells belong to one arm); returns each arm's mean.
std::vector<cv::Point2d> arms(const std::vector<cv::Point>& rim);

}  // namespace indoormap::areas::detail
