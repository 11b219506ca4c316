#pragma once
// The whole pre-processing of paper section 3.2.A as one call: level the cloud, voxelise it,
// analyse the height layers, project the wall and furniture bands, build the room layout M_r.
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "indoormap/cloud/ghosts.hpp"
#include "indoormap/cloud/level.hpp"
#include "indoormap/cloud/voxel.hpp"
#include "indoormap/core/cloud.hpp"
#include "indoormap/layout/layout.hpp"

namespace indoormap::layout {

struct MapParams {
  cloud::LevelParams level;
  cloud::VoxelParams voxel;
  cloud::GhostParams ghosts;  ///< applied with exactly one known scanner
  cloud::LayerParams layers;
  LayoutParams layout;
};

struct StageTime {
  std::string stage;
  double ms = 0.0;
};

struct MapResult {
  cloud::LevelResult level;
  PointCloud cloud_map;                   ///< the input cloud rotated into the levelled map frame
  cloud::Bounds3 bounds;                  ///< robust bounds, map frame
  cloud::VoxelGrid voxels;                ///< ghost voxels cleared (ghosts)
  cloud::GhostResult ghosts;
  cloud::LayerAnalysis layers;
  GridGeometry geometry;                  ///< the 2D grid of M_w, M_f and M_r (map frame)
  Grid<std::uint8_t> walls;               ///< M_w: occupancy of the wall band
  Grid<std::uint8_t> furniture;           ///< M_f: occupancy of the furniture band
  LayoutResult layout;                    ///< M_r and the passage area
  std::vector<StageTime> timings;
  std::vector<std::string> warnings;      ///< from every stage, in order
};

/// Runs the pipeline on a cloud in the input frame (metres, z up). Scanner positions in
/// cloud.scanners are used as flood-fill seeds. Throws InputError / BudgetError on unusable data
/// and UsageError on invalid params (validate).
MapResult make_map(PointCloud cloud, const MapParams& params);

}  // namespace indoormap::layout
