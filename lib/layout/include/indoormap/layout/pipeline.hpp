#pragma once
// The whole pre-processing of paper section 3.2.A as one call: level the cloud, voxelise it,
// analyse the height layers, project the wall and furniture bands, build the room layout M_r.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "indoormap/cloud/ghosts.hpp"
#include "indoormap/cloud/level.hpp"
#include "indoormap/cloud/voxel.hpp"
#include "indoormap/core/cloud.hpp"
#include "indoormap/layout/layout.hpp"
#include "indoormap/layout/nav_map.hpp"
#include "indoormap/layout/nearest_origin.hpp"

namespace indoormap::layout {

struct MapParams {
  cloud::LevelParams level;
  cloud::WallAlignParams align_walls;  ///< turn the levelled cloud so the walls run along x / y
  cloud::VoxelParams voxel;
  cloud::GhostParams ghosts;  ///< applied per origin (one scanner, or the cloud's origin spans)
  cloud::LayerParams layers;
  LayoutParams layout;
  NavParams nav;  ///< the navigation map (robot.min_obstacle_height_m, robot.height_m, nav.*)
  ViewpointCheckParams viewpoint_check;  ///< one position that cannot be the cloud's origin
};

struct StageTime {
  std::string stage;
  double ms = 0.0;
};

struct MapResult {
  cloud::LevelResult level;
  PointCloud cloud_map;     ///< the input cloud rotated into the levelled map frame
  cloud::Bounds3 bounds;    ///< robust bounds, map frame
  cloud::VoxelGrid voxels;  ///< ghost voxels cleared (ghosts)
  cloud::GhostResult ghosts;
  cloud::LayerAnalysis layers;
  GridGeometry geometry;         ///< the 2D grid of M_w, M_f and M_r (map frame)
  Grid<std::uint8_t> walls;      ///< M_w: occupancy of the wall band
  Grid<std::uint8_t> furniture;  ///< M_f: occupancy of the furniture band
  LayoutResult layout;           ///< M_r and the passage area
  NavResult nav;                 ///< the robot's map (map.pgm): body band, evidence
  /// The ghost filter ran with every point's own scanner (one position, or origins the input
  /// records): the doorway veils are gone. Not with origins estimated from a trajectory.
  bool ghost_origins_exact = false;
  /// check_viewpoint of a file's single position: the share of points hidden from it (none: not
  /// run), and whether the position was dropped for it.
  std::optional<double> viewpoint_occluded_share;
  bool viewpoint_dropped = false;
  double floor_fill = 1.0;  ///< floor points / cells of their 0.2 m blocks (sparse scans: low)
  /// floor_fill at least LayoutParams::sparse_floor_fill: the objects step's stray test reads it.
  bool dense_scan = true;
  /// M_r's flood ran over the cells the scan shows free only (a sparse scan, a moving scanner's
  /// path; LayoutParams::free_needs_evidence).
  bool free_from_evidence = false;
  /// Furniture-band cells taken out of M_f as veils (without_veils; origins not exact and the
  /// flood on evidence only).
  std::int64_t veil_cells_dropped = 0;
  std::vector<StageTime> timings;
  std::vector<std::string> warnings;  ///< from every stage, in order
};

/// Runs the pipeline on a cloud in the input frame (metres, z up). Scanner positions in
/// cloud.scanners are used as flood-fill seeds of M_r and as ray origins of the navigation map.
/// Throws InputError / BudgetError on unusable data, UsageError (naming the key) for invalid level
/// / voxel / ghosts / layers parameters.
MapResult make_map(PointCloud cloud, const MapParams& params);

// The stages of make_map, for make_storey_maps (storeys.hpp), which levels and voxelises the
// whole cloud once before it knows the storeys.
/// Every parameter check of make_map (UsageError naming the key).
void validate(const MapParams& params);
/// Levels the cloud in place (estimate_level, then estimate_wall_alignment when
/// params.align_walls.enabled; one rotate by the composed map_from_input); "not levelled" and
/// "not aligned" go to warnings.
cloud::LevelResult level_cloud(PointCloud& cloud, const MapParams& params,
                               std::vector<std::string>& warnings);
/// Everything after voxelising: r.level, r.bounds and r.voxels set, `cloud` levelled (map frame).
void map_voxelized(PointCloud cloud, const MapParams& params, MapResult& r);

}  // namespace indoormap::layout
