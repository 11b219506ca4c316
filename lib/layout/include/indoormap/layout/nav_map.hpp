#pragma once
// The navigation map (map.pgm / map.yaml): what a robot on the floor collides with, and the free
// space the scans give evidence of. Not in the paper, whose room layout M_r (layout.hpp) marks
// the wall band below the ceiling, so that every door under a lintel is a wall there. M_r keeps
// feeding the room border and the objects; the robot's map is this one. docs/pipeline.md,
// "Navigation map".
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "indoormap/cloud/voxel.hpp"
#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::layout {

struct NavParams {
  /// The body band, above the floor: what lies between these heights is in the robot's way.
  /// Below min_obstacle_height_m the robot drives over it (door sills, cables on the floor, the
  /// floor's own noise at 5 cm voxels); above height_m it passes under (lintels, table tops of
  /// high counters, lamps).
  double min_obstacle_height_m = 0.1;
  double height_m = 1.2;
  /// An occupied cell's body-band column holds at least min_points points, or its occupied
  /// voxels span at least min_column_m: a surface (table top) gives many points in one layer, a
  /// leg or a wall stands over many layers; a stray return or a dangling cord seen from one side
  /// gives a speck of one or two points in one or two voxels.
  /// Or at least min_neighbours of its 8 neighbours hold body-band points too: a sparse surface
  /// far from the scanner (one or two points per cell) is still a surface; a cord, or the veil of
  /// mixed pixels at a door edge (a line of specks), has at most 2.
  int min_points = 4;
  double min_column_m = 0.2;
  int min_neighbours = 3;
  /// The floor counts as observed in a column with a point from floor_z - floor_tolerance_m up to
  /// the body band.
  double floor_tolerance_m = 0.1;
  /// Closings (3x3 square) of the observed floor: far from a scanner the floor's returns thin out
  /// into lines one or two cells apart. 0: off.
  int floor_closing_cells = 1;
  /// The floor's height per tile of floor_tile_m: the most frequent lowest layer of its columns
  /// up to floor_max_offset_m above the floor found (and floor_tolerance_m below), when a quarter
  /// of the tile's columns have one. A levelling residual of 0.3 degrees raises the floor 10 cm
  /// across a 20 m building; the body band follows the floor.
  double floor_max_offset_m = 0.2;
  double floor_tile_m = 1.0;
  /// Floor holes: a component of unknown cells (4-connected, off the map's edge) of at most
  /// floor_hole_max_m2 whose border is at least floor_hole_min_free_share free becomes free: the
  /// gaps a multi-beam scanner leaves between the rings its beams draw on the floor, the blind
  /// disc around a mobile scanner's stop. Not where points lie 0.3 m below the floor (a drop).
  /// A closed room or the inside of a wall or cabinet is bordered by occupied cells and stays
  /// unknown. 0: off. Without any scanner position (no rays) the gaps between floor rings and a
  /// wall are left too, bordered by floor on one side and the wall on the other: there half
  /// the border free suffices (floor_hole_min_free_share_no_rays). With rays, those gaps are
  /// crossed, and an unknown pocket beside the floor is more often hidden behind something.
  double floor_hole_max_m2 = 10.0;
  double floor_hole_min_free_share = 0.75;
  double floor_hole_min_free_share_no_rays = 0.5;
  /// Free space from rays: per scanner position, the map is cast in 2D along azimuth bins, each
  /// to the farthest column in the bin that holds a point below height_m (floor or body band),
  /// stopping at the first occupied cell. false: observed floor alone.
  bool rays = true;
  double max_range_m = 30.0;  ///< columns farther from the position cast no ray
  /// Shadows of free-standing obstacles: where the rays of one position stop on an obstacle whose
  /// occupied cells (8-connected) span at most shadow_max_width_m (a pillar, a bin, a chair) and
  /// the rays on both its sides go on at least shadow_min_depth_m beyond it, the floor behind it
  /// (from one obstacle width behind its front to the line joining the side rays' ends) is free.
  /// A wall seen end-on, or a cabinet touching it, belongs to the whole wall. Inferred cells:
  /// free in the map, not the layout's evidence. docs/pipeline.md, "Shadows". 0 m wide: off.
  double shadow_max_width_m = 0.8;
  double shadow_min_depth_m = 1.0;
  /// Beams over low obstacles: a ray goes on over an occupied cell whose obstacle's top lies at
  /// least a layer below the position (a table, a sofa seen from a standing scanner). Behind it
  /// the beams that saw beyond passed over the line from the position over the highest top so
  /// far; a cell where that line lies at most this high above the floor is free (inferred, as
  /// the shadows above): only a thing lower than that could hide there. docs/pipeline.md, "Beams
  /// over low obstacles". 0: off, every obstacle that is not raised stops a ray.
  double over_low_max_m = 0.3;
  double scanner_clear_m = 0.3;  ///< occupied cells this close to a position (its tripod) pass
  /// A raised obstacle, whose body-band points lie at least this high above the floor and within
  /// 0.15 m of each other, over a floor seen in its own cell (a table top, a chair's seat), does
  /// not stop a ray: the rays that saw the floor beyond it passed beneath it. It stays occupied.
  double ray_under_min_m = 0.3;
};

/// Throws UsageError naming the key (robot.height_m, nav.min_points, ...).
void validate(const NavParams& params);

struct NavResult;
/// The map with the cells free only from the beams over low obstacles unknown: the rooms' input.
/// Beside a table that floor and an unseen patch would make a neck the room split takes for a
/// door (docs/pipeline.md, "Beams over low obstacles").
Grid<Cell> map_without_over_low(const NavResult& nav);

struct NavResult {
  Grid<Cell> map;  ///< kWall (occupied), kFree, kUnknown; the grid of voxels.geometry2d()
  /// 1 where map is free from observation (floor seen, rays), 0 elsewhere and on filled floor
  /// holes: the layout's free-space evidence, which must not rest on inferred cells.
  Grid<std::uint8_t> observed_free;
  double body_lo_m = 0.0, body_hi_m = 0.0;  ///< the body band, map-frame heights
  std::int64_t cells_occupied = 0, cells_free = 0, cells_unknown = 0;
  std::int64_t cells_floor_seen = 0;  ///< free cells whose floor holds points
  std::int64_t cells_ray_free = 0;    ///< free cells known from rays alone
  /// 1 on the free cells known only from the beams over low obstacles (NavParams::over_low_max_m).
  Grid<std::uint8_t> over_low;
  std::int64_t cells_shadow_filled = 0;  ///< free cells behind narrow obstacles (none of those)
  std::int64_t cells_over_low = 0;       ///< free cells behind low obstacles (none of those)
  std::int64_t cells_hole_filled = 0;    ///< free cells of filled floor holes (none of those)
  std::int64_t specks_dropped = 0;       ///< body-band columns with points below the evidence rule
  std::size_t positions = 0;             ///< scanner positions used for rays
  std::size_t rays = 0;
  std::vector<std::string> warnings;
};

/// Builds the navigation map of one storey from its voxel grid (ghosts already cleared) and the
/// floor height floor_z_m. scanners_map: positions in the map frame (any number, also none).
/// veils_cleared: the ghost filter ran with every point's own origin, so no veil of mixed pixels
/// is left in the doorways; otherwise (no position, origins estimated from a trajectory) the seen
/// floor below a column stands in for it (docs/pipeline.md, "Specks"). walls: the layout's wall
/// band cells (M_w), or null: a wall whose foot something hid still bounds the floor holes, a
/// doorway's lintel does not (docs/pipeline.md, "Floor holes").
NavResult build_nav_map(const cloud::VoxelGrid& voxels, double floor_z_m,
                        const std::vector<Eigen::Vector3d>& scanners_map,
                        const NavParams& params = {}, bool veils_cleared = false,
                        const Grid<std::uint8_t>* walls = nullptr);

}  // namespace indoormap::layout
