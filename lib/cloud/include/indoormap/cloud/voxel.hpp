#pragma once
// Voxel occupancy grid with a count per voxel (pipeline step 3) and the height-layer analysis
// (step 4) that finds the floor, the ceiling, the wall band and the furniture band.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "indoormap/core/grid.hpp"
#include "indoormap/core/voxel_geometry.hpp"

namespace indoormap::cloud {

struct Bounds3 {
  Eigen::Vector3d lo_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d hi_m = Eigen::Vector3d::Zero();
};

struct VoxelParams {
  double cell_m = 0.05;                  ///< voxel edge
  std::int64_t max_cells = 400'000'000;  ///< refuse larger grids before allocating (2 B/cell)
  double bounds_gap_m = 1.0;             ///< robust bounds stop at an empty gap this wide
  std::size_t bounds_sample = 65536;     ///< points sampled for the gap search
};

/// Throws UsageError naming the key (voxel.cell_m, ...) for a parameter out of its range.
void validate(const VoxelParams& params);

/// Dense voxel grid with a count per voxel; its geometry (origin, cell, size, index) is the
/// VoxelGeometry base. Counts saturate.
struct VoxelGrid : VoxelGeometry {
  std::vector<std::uint16_t> counts;  ///< at index(ix, iy, iz)
  std::uint64_t points_inside = 0;
  std::uint64_t points_outside = 0;  ///< beyond the robust bounds (or non-finite)

  std::uint16_t count(std::int64_t ix, std::int64_t iy, std::int64_t iz) const {
    return counts[static_cast<std::size_t>(index(ix, iy, iz))];
  }
};

/// Bounds of the main body of the data: per axis, the run of all points around a sample's median
/// with no empty gap of bounds_gap_m or more (a histogram of bounds_gap_m / 2 bins), then the
/// exact extent of the points inside it. Points seen through a window far outside the room do not
/// stretch the grid; a far wall with few points (a long corridor's end) stays in it. Throws
/// InputError for a cloud without a finite point.
Bounds3 robust_bounds(const std::vector<Eigen::Vector3f>& points, const VoxelParams& params);

/// Counts points per voxel inside bounds. Throws BudgetError (before allocating) when the grid
/// would exceed params.max_cells.
VoxelGrid voxelize(const std::vector<Eigen::Vector3f>& points, const Bounds3& bounds,
                   const VoxelParams& params);

struct LayerParams {
  int min_points_per_voxel = 1;        ///< a voxel with fewer points counts as empty
  int isolated_min_points = 3;         ///< points an isolated 2D cell needs (see project_band)
  double floor_min_fraction = 0.3;     ///< floor: first layer from below with this share of the max
  double ceiling_min_fraction = 0.25;  ///< ceiling: first layer from above with this share of max
  double min_room_height_m = 1.8;      ///< the ceiling lies at least this far above the floor
  /// When the floor test on occupied cells leaves no room for a ceiling above the floor, the
  /// floor and ceiling tests count a layer's occupied blocks of this size instead: a sparse scan
  /// (1-2 degree steps) hits one far floor cell in several, while a block of 0.2 m still holds a
  /// point, so the floor stays as strong as the nearer ceiling. 0 (or one cell): cells only.
  double surface_block_m = 0.2;
  /// No strong ceiling layer (a sloped ceiling spreads over many layers): the ceiling starts at the
  /// first layer above min_room_height whose count exceeds this factor times the walls' baseline.
  double ceiling_onset_factor = 1.5;
  double floor_clearance_m = 0.10;    ///< the furniture band starts this far above the floor
  double ceiling_clearance_m = 0.15;  ///< the wall band ends this far below the ceiling
  double wall_band_m = 0.50;          ///< thickness of the wall band
  /// A wall cell's band column spans at least this height (lowest to highest occupied voxel): a
  /// wall stands through the band, while a lamp or the top of a tall cabinet reaching into it is a
  /// thin horizontal slab. 0: any point in the band makes a wall (the paper).
  double wall_min_extent_m = 0.2;
  double furniture_max_height_m = 2.0;  ///< the furniture band ends here (above the floor) at most
  /// Walls of rooms lower than the storey's ceiling: the wall band lies under the ceiling that
  /// analyse_layers finds (the highest strong one), above the ceiling of a lower room of the same
  /// storey, so that room's walls, which end at its own ceiling, miss the band. A wall still stands
  /// through every height of its room; furniture ends below furniture_max_height_m. So a column
  /// occupied through the whole of this height just above the furniture band is wall as well
  /// (LayerAnalysis::low_wall_band). 0: off (the paper's single band).
  double low_wall_band_m = 0.2;
  /// A piece of the low wall band (8-connected) whose bounding box is shorter than this on both
  /// sides and that stands on nothing (under fewer than half of its cells, points in half the
  /// furniture band's layers) is no wall: a lamp hanging over a desk into the band. A wall, even a
  /// short stub between two windows, goes on down to the floor. 0: off.
  double low_wall_min_length_m = 1.0;
  // Overrides (map-frame heights, metres); unset means "detect".
  std::optional<double> floor_z_m;
  std::optional<double> ceiling_z_m;
  std::optional<double> wall_band_lo_m, wall_band_hi_m;
  std::optional<double> furniture_band_lo_m, furniture_band_hi_m;
};

/// Throws UsageError naming the key (layers.wall_band_m, ...) for a parameter out of its range.
void validate(const LayerParams& params);

/// A height interval, both as metres and as the inclusive range of layers it covers.
struct HeightBand {
  double lo_m = 0.0, hi_m = 0.0;
  std::int64_t lo_layer = 0, hi_layer = -1;  ///< inclusive; empty when hi_layer < lo_layer
};

struct LayerAnalysis {
  std::vector<std::int64_t> occupied_per_layer;  ///< bottom up
  std::int64_t floor_layer = 0;
  double floor_z_m = 0.0;
  bool ceiling_found = false;  ///< false: ceiling_z_m is the documented fallback (top of data)
  bool ceiling_sloped =
      false;  ///< found as an onset, not a single layer: ceiling_z_m is its lowest part
  std::int64_t ceiling_layer = 0;
  double ceiling_z_m = 0.0;
  HeightBand wall_band;
  /// From one cell above the furniture band, low_wall_band_m high (LayerParams::low_wall_band_m);
  /// empty when it does not end below the wall band.
  HeightBand low_wall_band;
  HeightBand furniture_band;
  std::vector<std::string> warnings;
};

/// The share of the cells of the floor's 0.2 m blocks (4 x 4 cells of 5 cm) that hold floor
/// points (floor_layer and its neighbours): how densely the scan sampled the floor, 0.74-0.85 at
/// the simulated scanner's default 0.25 degree step, 0.4-0.5 at 1 degree, about 0.2 at 2 degrees.
/// 1 when no cell holds floor points.
double floor_fill(const VoxelGrid& grid, std::int64_t floor_layer);

/// Layer analysis bottom up by the number of occupied cells per layer. Throws InputError when
/// all data lies in fewer than three layers (nothing to separate).
LayerAnalysis analyse_layers(const VoxelGrid& grid, const LayerParams& params);

/// The 2D occupancy of a height band (M_w for the wall band, M_f for the furniture band): a cell is
/// an obstacle where its band column holds points in voxels of at least min_points points. An
/// isolated cell (no occupied 8-neighbour) needs isolated_min_points points in its column: single
/// stray returns (mixed pixels at depth edges, dust) do not become objects, while a thin pole,
/// seen over its height, still does.
Grid<std::uint8_t> project_band(const VoxelGrid& grid, const HeightBand& band, int min_points,
                                int isolated_min_points = 1, int min_extent_layers = 1);

}  // namespace indoormap::cloud
