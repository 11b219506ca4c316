#pragma once
// 2D rays of the navigation map (nav_map.cpp): per scanner position, the cells a ray crossed below
// the body band, and the floor behind free-standing obstacles (shadows). docs/pipeline.md,
// "Free space from evidence" and "Shadows".
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "indoormap/cloud/voxel.hpp"
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

/// The heights of cast_from's beams over low obstacles (voxel z: layers, the grid's cells).
struct BeamHeights {
  /// Per cell: the top of an occupied cell's obstacle (the top face of its highest layer), or
  /// negative where it is unknown (the ray stops there). Empty: every obstacle stops a ray.
  std::vector<float> tops;
  /// Per cell that is not occupied: the lowest point above the body band (its top in `tops`), or
  /// negative. Behind a low obstacle such a cell below the position raises the line over the
  /// tops (a cabinet's top plate above the band), or stops the ray when its top is not below it.
  std::vector<float> lows;
  /// A cell behind a low obstacle is free where the line over the tops lies this high at most.
  double max_hidden = 0.0;
};

/// BeamHeights of the cells (voxel z), without max_hidden: an occupied cell that is no raised
/// obstacle, the top of the run of occupied voxels from its highest body-band layer (hi, relative
/// to the column's floor offset off) up, gaps of one layer bridged: a table's top, a wall's top at
/// the ceiling, not a lamp above a gap; a cell that is not occupied, with a point above the body
/// band (body_hi) and below the highest position, the lowest such point and the top of its run:
/// the top of a cabinet taller than the band, over the hidden inside behind its face.
BeamHeights beam_heights(const cloud::VoxelGrid& g, const std::vector<std::int32_t>& hi,
                         const std::vector<std::int8_t>& off, std::int64_t body_hi,
                         const std::vector<Eigen::Vector3d>& scanners,
                         const Grid<std::uint8_t>& occupied,
                         const std::vector<std::uint8_t>& raised);

/// What the rays of every position marked, one entry per cell.
struct RayMarks {
  std::vector<std::uint8_t> crossed, shadow, over;
  std::size_t positions = 0, rays = 0;
  explicit RayMarks(std::size_t cells = 0) : crossed(cells, 0), shadow(cells, 0), over(cells, 0) {}
};

struct RayReach {
  double max_range_cells = 0.0;  ///< columns farther from a position cast no ray
  double clear_cells = 0.0;      ///< occupied cells this close to a position do not stop it
};

/// cast_from for every position (map frame; non-finite ones skipped), split between the cores;
/// the marks are OR-ed in part order (the same map whatever the timing).
RayMarks cast_all(const cloud::VoxelGrid& g, const std::vector<Eigen::Vector3d>& scanners,
                  const std::vector<std::uint8_t>& low_seen, const Grid<std::uint8_t>& occupied,
                  const std::vector<std::uint8_t>& raised, const RayReach& reach,
                  const std::vector<std::uint8_t>& floor_seen, const ShadowLimits& shadows,
                  const BeamHeights& beams);

/// ShadowLimits::compact of an occupancy grid (all 0 when max_cells <= 0).
std::vector<std::uint8_t> compact_obstacles(const Grid<std::uint8_t>& occupied, double max_cells);

/// 2D rays from one position (s_cells: x, y in cells of the grid, z in layers): per azimuth bin,
/// to the farthest low-seen column of the bin, stopping at the first occupied cell beyond
/// clear_cells that is not `raised` (1: a raised obstacle the rays pass beneath; empty: none) nor
/// a low obstacle the beams passed over (`beams`: its top at least a layer below the position;
/// the cells behind it where the line over the tops so far lies below `beams.max_hidden` go to
/// `over`, inferred); the cells crossed (not occupied) are set in `crossed`, the shadows
/// of free-standing obstacles (cast from the first occupied cell) in `shadow`. Returns the rays
/// cast.
std::size_t cast_from(const Eigen::Vector3d& s_cells, const std::vector<std::uint8_t>& low_seen,
                      const Grid<std::uint8_t>& occupied, const std::vector<std::uint8_t>& raised,
                      double max_range_cells, double clear_cells,
                      const std::vector<std::uint8_t>& floor_seen, const ShadowLimits& shadows,
                      const BeamHeights& beams, std::vector<std::uint8_t>& crossed,
                      std::vector<std::uint8_t>& shadow, std::vector<std::uint8_t>& over);

}  // namespace indoormap::layout::detail
