#pragma once
// Parameters of the room border closure (docs/border-closure.md, "Parameters"). Lengths are in
// metres and angles in degrees; close_border converts them to cells of the layout once. The
// defaults of the face-fit thresholds are the values the closure was tuned with at the default
// cell size (0.05 m): 0.2 m = 4 cells, 0.075 m = 1.5 cells.
#include <cstdint>

namespace indoormap::border {

struct BorderParams {
  int dilate_full_size = 5;   ///< [cells] side of the full square dilation element (odd; 1 = skip)
  int dilate_cross_size = 3;  ///< [cells] side of the cross-shaped dilation element (odd; 1 = skip)
  int erode_full_size = 5;    ///< [cells] side of the full square erosion element (odd, >= 3)
  int erode_iterations = 2;   ///< erosions with that element (>= 1)
  double simplify_tolerance_m = 0.05;  ///< [m] Douglas-Peucker tolerance of polygon_m (0 = raw)
  /// [m] the chain runs at the back of the wall; the polygon is fitted to the wall faces found up
  /// to this far inside the chain polygon (0 = off: polygon_m is the chain polygon).
  double face_snap_max_m = 0.3;
  /// [m] the polygon runs straight along a wall across the shadow of an object standing in the
  /// room (an inward detour of the chain round a mostly unknown region, both ends on one wall
  /// face, flanks without wall faces) at most this wide along the wall and deep across it. A 0.6 m
  /// pillar 1 m before the wall, seen from 1-2 m, hides 0.9-1.2 m of it. A shadow over a convex
  /// corner of the room is bridged to the two walls' crossing when that lies at most this far
  /// beyond the shadow's ends along both walls (0 = off).
  double shadow_max_m = 2.0;
  /// [m] a chain cell is closed when a wall or furniture cell lies within this distance of it;
  /// chain cells with none are open (the chain runs at the back of the wall, sometimes a cell off).
  double opening_search_m = 0.2;
  double opening_min_m = 0.3;  ///< [m] narrower gaps between obstacles are not reported
  double door_min_m = 0.6;     ///< [m] openings this wide or wider are door candidates ...
  double door_max_m = 1.2;     ///< [m] ... up to this width
  /// [m] above the floor (used by the MapResult overload only): an obstacle cell whose voxel
  /// column is empty from the furniture band's bottom up to this height is open below, e.g. a
  /// door under its lintel, which the wall and furniture bands both see as an obstacle.
  double door_clear_height_m = 1.8;
  double door_probe_m =
      3.0;  ///< [m] how far beyond such a cell a ray looks for points seen through it
  /// A ring whose openings add up to more than this share of its perimeter is not a room border
  /// (an open scan): closed = false, with the reason; chain and polygon are still given.
  double max_open_fraction = 0.4;
  std::int64_t max_cells = 100'000'000;  ///< refuse larger layouts before allocating

  // ---- Fit of the polygon to the wall faces (used when face_snap_max_m > 0) -----------------
  /// [m] the wall face points of a chain edge are taken from this far outside the edge (behind
  /// the chain: the chain may run a cell or two inside the wall band) ...
  double face_out_reach_m = 0.2;
  /// [m] ... to face_snap_max_m plus this inside it.
  double face_in_margin_m = 0.075;
  /// [m] a face point this close to a line lies on it; two lines whose centres lie this close to
  /// each other's line (and within same_face_max_deg) are one straight face; a shadow's detour
  /// runs into the room by more than this.
  double face_tol_m = 0.075;
  /// [deg] a line fitted to an edge's face points turns at most this far from the edge;
  /// otherwise it keeps the edge's direction (the chain wanders where it cuts a corner).
  double face_max_turn_deg = 30.0;
  /// [deg] two lines within this angle (and face_tol_m of each other) are one straight face.
  double same_face_max_deg = 8.0;
  /// [deg] consecutive lines within this angle are parallel: a step in the wall, joined where
  /// the chain joins them, not at their (far) crossing.
  double parallel_max_deg = 10.0;
  /// [m] the longest chamfer the chain cuts at a corner, and its largest depth behind the face,
  /// is 2 face_snap_max_m plus this: a line whose neighbours cross within that of its ends is
  /// dropped, the short edges of a door recess are at most that long, a shadow's detour runs at
  /// most that far behind the wall, and a corner further than twice that from the chain fails
  /// the fit (the face snapping is used instead).
  double chamfer_margin_m = 0.2;
  /// [m] a door recess bridged along its wall spans at most door_max_m + 2 face_snap_max_m plus
  /// this (the door and its two jambs).
  double recess_margin_m = 0.2;
  /// A detour of the chain is a shadow only when more than this share of the cells it cuts off
  /// (between the detour and the wall line, or the walls' crossing) is unknown.
  double shadow_min_unknown_share = 0.6;
  /// [m] an opening whose chain cells all lie within this distance of a bridged shadow's region
  /// runs along the shadow and is dropped (Douglas-Peucker keeps the region's corners within
  /// simplify_tolerance_m of the chain, plus half a cell).
  double shadow_chain_tol_m = 0.075;
  /// [deg] a shadow over a convex corner: the two walls turn left by at least this ...
  double corner_shadow_min_turn_deg = 60.0;
  double corner_shadow_max_turn_deg = 120.0;  ///< [deg] ... and at most this.

  /// Throws UsageError naming the key ("invalid parameter border.door_min_m: ...") for invalid
  /// parameters. close_border, heavy_border and open_below_mask call it.
  void validate() const;
};

/// Same as params.validate() (the config reader validates every section this way).
void validate(const BorderParams& params);

}  // namespace indoormap::border
