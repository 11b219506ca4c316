#pragma once
// Internal to im_objects: the stages of extract_objects, one file each (geometry.cpp: footprints
// and fits; heights.cpp: voxel columns and tops; pillars_lamps.cpp: the wall-class and ceiling
// objects; crops.cpp: crop_indices; objects.cpp: the composition).
#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <opencv2/core.hpp>
#include <optional>
#include <utility>
#include <vector>

#include "indoormap/objects/objects.hpp"

namespace indoormap::objects::detail {

constexpr float kNoHeight = std::numeric_limits<float>::quiet_NaN();
// Cells this close to a wall cell whose column reaches the wall band hold the wall's face (the
// wall class comes from the wall band and may sit a cell or two off the lower face).
constexpr int kWallFaceCells = 3;

struct Column {
  std::int64_t bottom = -1, top = -1;  // layers; -1: nothing above the floor
  std::int64_t points = 0;             // points in the layers bottom..top
};

// A column holding at most this many points is a stray return (a mixed pixel behind an edge, a
// ghost the filter's sampled rays missed) rather than a surface: a surface seen from a scanner
// leaves several points in each 5 cm cell it covers (a bin's top 3-12). On a dense scan
// (ScanTraits::dense, from layout.sparse_floor_fill) two: the mixed pixels behind a bin's rim land
// one or two to a cell. A sparse scan's surfaces leave one or two per cell themselves (1 degree).
constexpr std::int64_t kStrayMaxPoints = 1;
constexpr std::int64_t kStrayMaxPointsDense = 2;
// The floor fill of a dense scan when the caller does not say (extract_objects' dense_scan):
// LayoutParams::sparse_floor_fill's default, for the same reason.
constexpr double kDenseFloorFill = 0.6;
// A stray return this many layers or more below the top of the nearest surface (a mixed pixel
// just behind a bin's rim lies one layer down), where a scanner could have seen that top carried
// over, lies where a ray passed under the top's level.
constexpr std::int64_t kStrayBelowTopLayers = 1;

// The occupied run of a voxel column starting above the floor: the first occupied layer at
// least two layers above the floor layer (the floor smears into the next one), then upward
// while empty gaps stay within max_gap layers.
Column column_extent(const cloud::VoxelGrid& g, int col, int row, std::int64_t floor_layer,
                     std::int64_t top_layer, std::int64_t max_gap);

bool floor_seen(const cloud::VoxelGrid& g, int col, int row, std::int64_t floor_layer);

// True when the straight line from the scanner to `target` (map frame) crosses no occupied voxel,
// leaving out the last `skip_end_m` (horizontally) before the target: the target's own column and
// its neighbours hold the surface the line ends on.
bool line_of_sight(const cloud::VoxelGrid& g, const Eigen::Vector3d& scanner,
                   const Eigen::Vector3d& target, double skip_end_m);

// True when the line from the scanner through `target`, continued beyond it for at most max_m,
// meets an occupied voxel before leaving the grid: a return was recorded behind the target on
// that line, so a beam passed there (on a sparse scan most lines fall between the beams, and an
// empty target then proves nothing).
bool return_beyond(const cloud::VoxelGrid& g, const Eigen::Vector3d& scanner,
                   const Eigen::Vector3d& target, double max_m);
// How far beyond a pocket return_beyond looks (a wall or the floor behind a shadow is nearer).
constexpr double kMaxBeyond_m = 10.0;

// A window's lintel over a furniture cell (furniture-extract.md, step 4): above the cell's lowest
// occupied run (or the floor), an empty gap of at least min_gap layers (the opening), then a run
// of at least min_run consecutive occupied layers that reaches the ceiling (ceiling_layer - 2)
// or the grid's top. A lamp is too thin and hangs clear of the ceiling; a wall's face over a
// cabinet has no opening below it.
bool lintel_above(const cloud::VoxelGrid& g, int col, int row, std::int64_t floor_layer,
                  std::int64_t ceiling_layer, std::int64_t min_gap, std::int64_t min_run);
constexpr double kOpeningMinGap_m = 0.3;  // a window is taller (the simulator's: 1.2 m or more)
constexpr double kLintelMin_m = 0.3;      // a lamp (0.06 m) and the ceiling's smear are thinner

// The median occupied cell of the floor layer holds at least this many points: a surface leaves
// several returns to a cell. A sparse scan's floor holds one or two, and so does a cloud
// resampled to the cell size (one point per 5 cm voxel), whose surfaces cannot be told from
// stray returns by their count.
constexpr std::int64_t kSurfaceMinFloorPoints = 4;
bool surfaces_leave_several(const cloud::VoxelGrid& g, std::int64_t floor_layer);

/// Column extents of the furniture cells (scan_columns; `dense`: a dense scan's stray test); cells
/// whose floor is seen and nothing stands on leave the mask.
struct ColumnScan {
  Grid<Column> cols;
  Grid<std::uint8_t> pocket;  // furniture cells without data, floor unseen
  cv::Mat no_data;
  bool any_data = false;
  std::int64_t stray_max_points = kStrayMaxPoints;  // kStrayMaxPointsDense on a dense scan
  // Seen cells of at most stray_max_points are strays, not surface (FurnitureObject::
  // surface_cells): a dense scan whose surfaces leave several returns to a cell, as its floor
  // shows (surfaces_leave_several).
  bool surface_test = false;
  // fill_tops: the nearest surface's top before a stray's (along a path, and without positions),
  // carried as the face's (face_top).
  bool surface_first = false;
  // fill_tops, with surface_first: the surfaces away from the walls (surfaces_off_walls), whose
  // tops cells without data take before those of surfaces beside a wall. Empty: none preferred.
  Grid<std::uint8_t> off_walls;
};

ColumnScan scan_columns(const Grid<Cell>& layout, const cloud::VoxelGrid& voxels,
                        const cloud::LayerAnalysis& layers, const ObjectParams& params,
                        Grid<std::uint8_t>& mask, bool dense);

/// The surface cells of the mask with no wall cell within kWallFaceCells (ColumnScan::off_walls):
/// returns off a wall land beside it (a moving scanner's beams graze the wall above a cabinet);
/// a cabinet's or a shelf's front stands 0.3 m or more from the wall.
Grid<std::uint8_t> surfaces_off_walls(const Grid<Cell>& layout, const ColumnScan& scan,
                                      const Grid<std::uint8_t>& mask);

/// The top of every mask cell (kNoHeight without data); pocket cells a scanner could see into
/// leave the mask.
Grid<float> fill_tops(const GridGeometry& geo, const cloud::VoxelGrid& voxels,
                      const ColumnScan& scan, const std::vector<Eigen::Vector3d>& scanners_map,
                      Grid<std::uint8_t>& mask);

/// The heights of the furniture cells that join_fragments compares (map frame, metres).
struct PieceHeights {
  Grid<float> top;     ///< each cell's top (filled in for cells without data); NaN = unknown
  Grid<float> bottom;  ///< the lowest occupied layer's bottom of the cell's own column; NaN = none
  double floor_z_m = 0.0;
  double layer_m = 0.05;  ///< the voxels' height: the tolerance of "rests on"
};

/// A piece whose median bottom is at least this far above the floor does not stand on the floor
/// by itself (a chair's seat is 0.4 m up, a table's underside 0.7 m; a leg or a box on the floor
/// starts two layers, 0.1 m, above the floor layer's centre).
constexpr double kRestMinClearance_m = 0.15;

/// Joins the fragments of one piece of furniture (fragments.cpp): labels at most
/// params.join_gap_m apart whose median tops differ by at most params.split_height_step_m become
/// one; so does a label resting on another (its median bottom at least kRestMinClearance_m above
/// the floor and within the other's median bottom - 1 layer .. median top + 1 layer); a set
/// still below params.min_area_m2 then joins the largest set within the gap. Labels may come out
/// in several parts; numbered in raster order.
Labels join_fragments(const Labels& in, const PieceHeights& heights, double cell_m,
                      const ObjectParams& params);

/// Splits every object whose cells form two or more cores joined by necks narrower than
/// params.neck_width_m (two shelves end to end, bridged by a few cells between their front
/// corners): the cores are the components of the object's geometric parts opened by a disc
/// neck_width_m across that hold at least params.neck_min_part_m2, and every cell goes to the
/// core nearest to it inside the part. A part stays whole when a `solid` cell (more than a stray
/// return) of one core's cells touches one of another's: a seen face runs across the neck (one
/// shelf with a notch behind its front). Pieces joined across a gap (join_fragments) are not
/// split again. Numbered in raster order.
Labels split_at_necks(const Labels& in, const Grid<std::uint8_t>& solid, double cell_m,
                      const ObjectParams& params);

OrientedBox min_area_box(const std::vector<Eigen::Vector2d>& pts);

// The four corners of a cell (map metres), for minimum-area rectangles of cell sets.
void add_cell_corners(const GridGeometry& geo, CellIndex c, std::vector<Eigen::Vector2d>& out);

// The box's axes: along its length, and across.
std::pair<Eigen::Vector2d, Eigen::Vector2d> box_axes(const OrientedBox& b);

// The box as a counter-clockwise polygon.
std::vector<Eigen::Vector2d> box_polygon(const OrientedBox& b);

// Twice the signed area (counter-clockwise positive).
double signed_area2(const std::vector<Eigen::Vector2d>& poly);

// Outline of the cells of one label, traced on a 4x upsampled mask eroded by one pixel: it runs
// 1/8 cell outside the centres of the boundary cells. A boundary cell holds the object's surface
// somewhere inside it, so its centre is the unbiased estimate; the cell edges would make every
// object half a cell too large on each side (a 0.36 m bin 30 % too large in area). A label that
// the erosion splits (cells joined only at a corner) is traced along its cell edges instead.
std::vector<Eigen::Vector2d> outline(const Grid<std::int32_t>& labels, int id, CellIndex lo,
                                     CellIndex hi, const GridGeometry& geo);

struct Circle {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double radius = 0.0, rms = 0.0;
};

// Circle fit: algebraic (Kasa: x^2 + y^2 + D x + E y + F = 0 in least squares), then refined on
// the geometric distances where that lowers their RMS.
std::optional<Circle> fit_circle(const std::vector<Eigen::Vector2d>& pts);

// Pillars and columns: wall-class components that stand free in the room (few unknown cells
// around them) and are small. They reach the wall band, so the paper's layout makes them wall, and
// a scanner sees only their front: the footprint is the circle fitted to the seen face when it
// fits (a round pillar), else the minimum-area rectangle of the seen cells.
void add_pillars(const Grid<Cell>& layout, const GridGeometry& geo, const cloud::VoxelGrid& voxels,
                 const cloud::LayerAnalysis& layers, const ObjectParams& params,
                 ObjectsResult& res);

// Lamps and other ceiling fixtures: points hanging above the furniture band and below the
// ceiling, over the room (known cells more than kWallFaceCells from a wall), with empty space
// between them and what stands below. The wall band's projection leaves them out (thin slabs, not
// walls) and the furniture band ends below them, so no other class holds them. Their cells may lie
// over a table's: they are listed with their own cell list, not in `labels`.
void add_lamps(const Grid<Cell>& layout, const GridGeometry& geo, const cloud::VoxelGrid& voxels,
               const cloud::LayerAnalysis& layers, const ObjectParams& params, ObjectsResult& res);

}  // namespace indoormap::objects::detail
