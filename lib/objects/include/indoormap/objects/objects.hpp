#pragma once
// The furniture objects of a room (paper section 3.2.B and its stated purpose: hand "only the data
// that corresponds to an area of interest" to a recogniser): connected components of the furniture
// class of M_r, each with its size, place, height range from the voxel grid, and its own points.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "indoormap/cloud/voxel.hpp"
#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/core/object_kind.hpp"
#include "indoormap/objects/label.hpp"

namespace indoormap::objects {

struct ObjectParams {
  /// No object smaller than this is listed, of any kind (smaller pieces stay furniture in M_r and
  /// are counted as left over). The smallest real item of the simulator's scenes is a bin of
  /// 0.12 m radius (0.045 m2); seen from one side with its hidden back filled in it covers
  /// 0.035 m2 or more (docs/furniture-extract.md), so 0.03 keeps every bin and drops the specks.
  double min_area_m2 = 0.03;
  /// Pieces at most this far apart (one cell: the empty cells between them) whose median tops
  /// differ by at most split_height_step_m are one object (a shadow or a missed row of samples cut
  /// it); a piece still below min_area_m2 joins the largest object within this gap. 0: no joining.
  double join_gap_m = 0.05;
  /// Objects whose cells form cores joined by a neck narrower than this are split, when each
  /// core holds at least neck_min_part_m2 and no seen face runs across the neck (two shelves end
  /// to end, bridged between their corners by mixed pixels or an unseen pocket). 0: no splitting.
  double neck_width_m = 0.25;
  double neck_min_part_m2 = 0.2;
  /// An object needs this much seen area (seen_cells): less is a pocket the layout filled along a
  /// wall, or a wall's face, with a few stray points, not furniture (it is left over).
  /// 0.04: the smallest simulated bin (0.045 m2) is lower than the scanner, so its whole top is
  /// seen. As much of it must be surface, unless most of it is (drop_stray_pieces).
  double min_seen_area_m2 = 0.04;
  Connectivity connectivity = Connectivity::k4;  ///< the paper's choice
  double crop_margin_m = 0.05;  ///< crops take the footprint dilated by this much, and z +- it
  /// Touching objects of different heights are split: neighbouring cells whose tops differ by
  /// more than this belong to different objects (a chair at a table). 0 = the paper's plain
  /// 2D labelling.
  double split_height_step_m = 0.15;  ///< pieces smaller than min_area_m2 after the split rejoin
                                      ///< the neighbour they share the longest border with
  double top_percentile = 90.0;  ///< [%] z_max: this percentile of the tops of the object's cells
  /// An object whose lowest point is at least this far above the floor hangs (a ceiling lamp
  /// low enough to reach the furniture band, a wall cupboard): kind "hanging", not furniture
  /// standing on the floor. It stays an obstacle in M_r.
  double hanging_min_clearance_m = 1.0;
  /// Pillars and columns: a wall-class component no larger than this (bounding box) that stands
  /// free in the room is listed with kind "pillar". 0: none are listed.
  double pillar_max_extent_m = 1.5;
  /// Lamps: points hanging between the furniture band and the ceiling, over the room, with at
  /// least 0.2 m of empty space below them; components no larger than this are listed with kind
  /// "lamp". 0: none are listed.
  double lamp_max_extent_m = 2.5;
  double max_vertical_gap_m = 0.3;  ///< a column's top is the highest point reachable from below
                                    ///< without an empty gap longer than this (a lamp above a table
                                    ///< is not the table's top)
};

/// What the caller knows of the scan (from layout::MapResult and the cloud).
struct ScanTraits {
  /// layout::MapResult::dense_scan (set by layout.sparse_floor_fill): two returns to a cell are
  /// a stray. nullopt: the voxels' floor fill decides, at 0.6.
  std::optional<bool> dense;
  /// The positions are a moving scanner's path (PointCloud::scanners_on_path): a cell without
  /// data takes the nearest surface's top before a nearer stray's (furniture-extract.md, step 2).
  bool moving = false;
  /// Leave out the cells of stray returns (FurnitureObject::surface_cells) before labelling: for
  /// a scan whose stray returns no ray evidence removed (no scanner positions, no ghost filter),
  /// their mixed pixels spread the objects beyond their faces. Off: every piece whole (the rooms of
  /// a floor need the inner walls' strips). Only where the count tells a stray
  /// (ColumnScan::surface_test); there a cell without data also takes the top of the nearest
  /// surface away from the walls before a stray's or a wall's returns' (furniture-extract.md, step
  /// 2).
  bool peel_strays = false;
};

/// Checks ranges. Throws UsageError naming the key ("invalid parameter objects.<key>: ...").
/// Called by extract_objects.
void validate(const ObjectParams& params);

/// A minimum-area rectangle; length_m runs along angle_deg (counter-clockwise from map +x,
/// in [0, 180)), width_m across it.
struct OrientedBox {
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();
  double width_m = 0.0, length_m = 0.0, angle_deg = 0.0;
};

struct FurnitureObject {
  int id = 0;  ///< 1.. in raster order of start_cell
  /// furniture (stands on or near the floor), hanging (in the furniture band, 1 m or more above
  /// the floor), pillar (a free-standing wall component) or lamp (above the furniture band, below
  /// the ceiling); the apps add column / installation from the border analysis.
  ObjectKind kind = ObjectKind::kFurniture;
  std::int64_t cells = 0;
  CellIndex start_cell;          ///< first cell in raster order (row 0 first)
  CellIndex min_cell, max_cell;  ///< bounding box in cells (inclusive)
  Eigen::Vector2d min_m = Eigen::Vector2d::Zero(), max_m = Eigen::Vector2d::Zero();  ///< map frame
  double area_m2 = 0.0;
  OrientedBox box;
  std::vector<Eigen::Vector2d> footprint_m;  ///< outline, map frame, counter-clockwise
  bool has_height = false;              ///< false: no voxels above the footprint (filled-in cells)
  double z_min_m = 0.0, z_max_m = 0.0;  ///< map frame; z_min = floor height when it stands on it
  bool on_floor = false;
  std::uint64_t point_count = 0;  ///< points above the footprint within [z_min, z_max]
  /// Cells whose own column holds the object's points (not filled in from a neighbour, not a
  /// wall's face): the part of the footprint the scanner saw.
  std::int64_t seen_cells = 0;
  /// Seen cells whose column holds more than a stray return (a mixed pixel, range noise): the
  /// part of the footprint where the scanner saw a surface (drop_stray_pieces). Where surfaces
  /// themselves leave one or two returns to a cell (a sparse scan, ScanTraits::dense false; a
  /// cloud whose median floor cell holds fewer than 4 points, such as one resampled to 5 cm),
  /// every seen cell.
  std::int64_t surface_cells = 0;
  bool touches_wall = false;  ///< a cell is 8-adjacent to a wall cell
  /// The object's cells when they are not those of `labels` (a lamp over a table shares its
  /// cells with it); empty otherwise.
  std::vector<CellIndex> own_cells;
};

struct ObjectsResult {
  std::vector<FurnitureObject> objects;
  Grid<std::int32_t> labels;  ///< object id per cell (0: none, or below min_area); lamps are not
                              ///< in it (see own_cells)
  /// Furniture cells of the layout that no listed object holds: pieces below min_area_m2 with no
  /// object within join_gap_m, and cells whose floor was seen or that a scanner saw into (no data,
  /// nothing stands there). furniture cells = cells of the furniture-class objects + these.
  std::int64_t left_over_cells = 0;
  double left_over_area_m2 = 0.0;
  std::int64_t left_over_pieces = 0;  ///< pieces not listed (too small, too little seen, wall)
  /// 1 on the cells of the pieces taken for wall, not objects: the wall under a window (a
  /// parapet under a lintel) and a wall's face seen in the furniture band (a thin strip along a
  /// wall). Wall to the rooms of a floor too (a room's polygon ends at the wall's face).
  Grid<std::uint8_t> wall_cells;
};

/// Finds the objects of the furniture class. voxels supplies heights; it must cover the layout's
/// grid (same 2D geometry); heights are searched between the floor and the ceiling layers of
/// `layers`. Furniture cells within three cells of a wall whose column reaches the wall band hold
/// the wall's face, not the object: they take the height of the nearest other cell.
/// Furniture cells without data whose floor was seen are no part of any object; with the
/// scanner positions (map frame), neither are those where the neighbouring object's top would
/// have been in a scanner's line of sight (docs/furniture-extract.md). Pillars and lamps follow
/// the furniture objects in the list (params.pillar_max_extent_m, params.lamp_max_extent_m).
/// `traits` says what the caller knows of the scan (ScanTraits).
ObjectsResult extract_objects(const Grid<Cell>& layout, const GridGeometry& geometry,
                              const cloud::VoxelGrid& voxels, const cloud::LayerAnalysis& layers,
                              const ObjectParams& params = {},
                              const std::vector<Eigen::Vector3d>& scanners_map = {},
                              const ScanTraits& traits = {});

/// Drops the objects (furniture and hanging) with less than params.min_seen_area_m2 of surface
/// cells (FurnitureObject::surface_cells) that are also less than half of their seen cells: what
/// they hold is stray returns (mixed pixels behind an edge, range noise that no ray evidence
/// removed; a moving scan without positions has no ghost filter), no surface. A surface leaves
/// several points in each 5 cm cell it covers; a bin seen from one side, only on its near half.
/// They count as left over. extract_objects lists them, since a step that needs every piece of
/// the furniture class (the inner walls of a floor, seen only as sparse strips) must see them
/// first; call this after it.
void drop_stray_pieces(ObjectsResult& result, const GridGeometry& geometry,
                       const ObjectParams& params = {});

/// Indices of the points (map frame, same order as given) inside each object's crop region: the
/// footprint cells dilated by crop_margin_m, heights within [z_min - margin, z_max + margin].
/// One list per object, in the order of result.objects. A point may belong to several crops.
std::vector<std::vector<std::size_t>> crop_indices(const ObjectsResult& result,
                                                   const GridGeometry& geometry,
                                                   const std::vector<Eigen::Vector3f>& points_map,
                                                   double crop_margin_m);

}  // namespace indoormap::objects
