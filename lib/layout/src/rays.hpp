#pragma once
// 2D rays of the navigation map (nav_map.cpp): per scanner position, the cells a ray crossed below
// the body band, and the floor behind free-standing obstacles (shadows). docs/pipeline.md,
// "Free space from evidence" and "Shadows".
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "indoormap/core/grid.hpp"

namespace indoormap::layout::detail {

/// fill_shadows' limits, in cells.
struct ShadowLimits {
  double max_width_cells = 0.0;  ///< 0: no shadow filled
  double min_depth_cells = 0.0;
  /// 1 on the occupied cells of free-standing obstacles: 8-connected pieces at most
  /// max_width_cells across (bounding box). A wall seen end-on is narrow but belongs to the
  /// whole wall; so does a cabinet standing against it.
  std::vector<std::uint8_t> compact;
};

/// ShadowLimits::compact of an occupancy grid (all 0 when max_cells <= 0).
std::vector<std::uint8_t> compact_obstacles(const Grid<std::uint8_t>& occupied, double max_cells);

/// 2D rays from one position (s_cells, in cells of the grid): per azimuth bin, to the farthest
/// low-seen column of the bin, stopping at the first occupied cell beyond clear_cells that is not
/// `raised` (1: a raised obstacle the rays pass beneath; empty: none); the cells crossed (not
/// occupied) are set in `crossed`, the shadows of free-standing obstacles (cast from the first
/// occupied cell, raised or not) in `shadow`. Returns the rays cast.
std::size_t cast_from(const Eigen::Vector2d& s_cells, const std::vector<std::uint8_t>& low_seen,
                      const Grid<std::uint8_t>& occupied, const std::vector<std::uint8_t>& raised,
                      double max_range_cells, double clear_cells,
                      const std::vector<std::uint8_t>& floor_seen, const ShadowLimits& shadows,
                      std::vector<std::uint8_t>& crossed, std::vector<std::uint8_t>& shadow);

}  // namespace indoormap::layout::detail
