#pragma once
// The room layout M_r (paper section 3.2.A, steps 4-6): the passage area from horizontal and
// vertical passes over the wall map M_w, the free space flood-filled from the scanner position(s)
// over the furniture map M_f, and the furniture class, joined by a 3x3 cross closing.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::layout {

struct LayoutParams {
  int furniture_closing_iterations = 1;  ///< 3x3 cross dilation-erosion chain (0: off)
  /// Closings (3x3 square) of the furniture map before it bounds the free-space flood, so that
  /// the flood does not leak through the gaps of a speckled object face (0: off, the paper).
  int flood_barrier_closing = 2;
  /// Unreachable pockets of the passage area that touch furniture and are at most this large
  /// become furniture (space behind / between objects); larger ones stay unknown. The paper makes
  /// every pocket furniture, which turns e.g. the notch of a U-shaped room into one big object.
  double enclosed_max_area_m2 = 4.0;
  /// Passage area rule (passage_area): 0 = the paper's row AND column passes; k = bracketed by
  /// obstacles along at least k of the 4 lines (row, column, diagonals). With the paper's rule one
  /// gap in a wall (a doorway, the shadow of a pillar) drops every row through it from the room;
  /// 3 of 4 keeps them, while an L-shaped room's notch (bracketed along one line) stays outside.
  int passage_min_lines = 3;
  /// When no scanner position lies in the passage area, the test runs again over the obstacles
  /// closed with a square this wide (metres; the nearest odd number of cells): a sparse scan (2
  /// degree steps) leaves walls as dotted lines, whole rows and diagonals through the gaps hold
  /// no obstacle, and the room fell out of the passage area. Gaps narrower than this are bridged
  /// for the test only (no cell becomes wall or furniture); doors are wider. 0: off.
  double passage_bridge_m = 0.25;
  double seed_search_radius_m = 1.0;  ///< an occupied scanner cell moves to the nearest free one
  /// Wall-band objects that do not continue downwards are hanging (ceiling lamps, ducts): the
  /// wall cells with no support cell (see build_layout) within one cell form components; one
  /// that covers at most hanging_max_area_m2, spans at most hanging_max_extent_m and lies inside
  /// the room (not within two cells of the passage area's edge: the wall above a window or a door
  /// has nothing below it either) is hanging. It is no obstacle for a robot on the floor; the
  /// paper leaves it in the wall class.
  double hanging_max_area_m2 = 2.0;
  double hanging_max_extent_m = 1.5;  ///< longer components are walls seen above an occlusion
  double hanging_gap_m = 0.3;         ///< thickness of the support slice below the wall band
  /// The inside of an inner wall (issue 16): a scanner sees a wall's two faces from the two
  /// rooms, never what lies between them, and in a building that strip lies inside the passage
  /// area. A cell the flood did not reach, whose floor the scan did not see (build_layout's
  /// `seen`), that lies between two wall cells at most this far apart along a row, column or
  /// diagonal is wall (else the strip became furniture: the walls between rooms listed as
  /// objects). Furniture stands in front of a wall, with free floor, not a second wall, on its
  /// other side; a doorway is wider and the flood reaches it; the floor of a room's corner (cut
  /// off by a diagonal) is seen. An inside no longer than twice this along both grid axes is
  /// left as it is: a pillar's, which the objects step describes by its ring of faces. The same
  /// thickness bounds a wall one of whose faces only the furniture band holds (wall_slabs: a
  /// mobile scanner's beams end below the wall band near a room's walls). 0: off.
  double wall_max_thickness_m = 0.5;
  /// Free space needs evidence (issue 17, sparse scans): the flood runs only over cells where
  /// the scan shows free space (build_layout's `evidence`: the navigation map's free cells, whose
  /// floor was observed or which a ray from a scanner crossed), closed once with a 3x3 square so
  /// that one-cell holes do not cut it. Unseen passage cells are pockets (furniture when small
  /// and next to furniture: the body behind a shelf's face; else unknown). false: the paper's
  /// flood over every passage cell, which on a sparse scan bridges gaps into unseen space.
  bool free_needs_evidence = true;
  /// make_map applies free_needs_evidence only to a sparse scan: one whose floor points fill less
  /// than this share of the cells of the 0.2 m blocks they touch (MapResult::floor_fill: about
  /// 0.74-0.85 at the default 0.25 degree step, 0.4-0.5 at 1 degree, 0.2 at 2). On dense scans it
  /// cost object precision (shadows behind chairs became furniture). 1.01: always; 0: never.
  double sparse_floor_fill = 0.6;
  /// The unseen body of furniture taller than the scanner (make_map, dense scans; a dense scan
  /// sees a tall shelf as its front face, and the paper's flood ran in round its unseen end and
  /// called its body free): from each furniture cell with points above the lowest scanner
  /// position less 0.1 m whose nearest wall lies within this depth, the cells on the straight
  /// line to that wall (three cells wide) are not flooded when the scan saw the floor of none of
  /// them; they become a pocket of that furniture. The deepest simulated cabinet is 0.6 m. Without
  /// scanner positions every furniture cell counts (no height tells which tops were seen). Needs
  /// free_needs_evidence. 0: off.
  double hidden_body_max_depth_m = 0.7;
};

/// Checks ranges. Throws UsageError naming the key ("invalid parameter layout.<key>: ...").
/// Called by build_layout and make_map.
void validate(const LayoutParams& params);

/// A wall-band object with free floor beneath it (a lamp), removed from the wall class.
struct HangingObject {
  int min_col = 0, min_row = 0, max_col = 0, max_row = 0;  ///< bounding box, cells (inclusive)
  std::int64_t cells = 0;
};

/// Passage area (step 4). min_lines <= 0, the paper's rule: a cell is inside when, in its row and
/// in its column, it lies between the first and the last obstacle (logical AND of the horizontal
/// and vertical passes). min_lines = k in 1..4: inside when it lies between obstacles along at
/// least k of the four lines through it (row, column, both diagonals). Obstacle cells themselves
/// are inside. Values: 0 outside, 1 inside.
Grid<std::uint8_t> passage_area(const Grid<std::uint8_t>& walls, int min_lines = 0);

/// Cells between two wall cells at most max_span_m apart (centre to centre) along a row, column
/// or diagonal, the wall cells excluded (LayoutParams::wall_max_thickness_m). With `open` (free
/// or seen cells), only where open space lies just past one of the two wall pieces (each at most
/// max_span_m long along the line) and past the `furniture` cells in front of it (as long at
/// most; a face seen in the furniture band only): the faces of a wall look at two rooms, the
/// two faces of a room's corner at each other. Values: 0 / 1.
Grid<std::uint8_t> wall_inside(const Grid<std::uint8_t>& walls, double cell_m, double max_span_m,
                               const Grid<std::uint8_t>* open = nullptr,
                               const Grid<std::uint8_t>* furniture = nullptr);

/// Cells of a wall one of whose faces only the furniture band holds (LayoutParams::
/// wall_max_thickness_m): along a row, column or diagonal, a run of cells not `seen` (the scan
/// shows them free) between two seen cells, at most max_span_m long (cells times step), whose
/// wall cells are one unbroken piece at one end and whose cell at the other end is a furniture
/// cell. The scan saw a slab from both sides, the wall band on one face only (a mobile
/// scanner's beams end below the wall band near a room's walls): a wall.
/// Furniture against a wall makes the run at least its depth plus the wall's thickness; a pillar
/// or a table holds no wall cell. Values: 0 / 1.
Grid<std::uint8_t> wall_slabs(const Grid<std::uint8_t>& walls, const Grid<std::uint8_t>& furniture,
                              const Grid<std::uint8_t>& seen, double cell_m, double max_span_m);

/// M_f without the columns that the navigation map calls free (nav: its map) over floor the scan
/// saw (observed_free): the veils of mixed pixels beside door jambs and furniture edges, columns of
/// a few points at unrelated heights, which the navigation map's scatter rule already leaves out
/// (docs/pipeline.md, section 7) and which M_f took for furniture. Wall-band cells stay. Grids of
/// another size leave furniture as it is; `dropped` counts the cells taken out.
Grid<std::uint8_t> without_veils(const Grid<std::uint8_t>& furniture,
                                 const Grid<std::uint8_t>& walls, const Grid<Cell>& nav,
                                 const Grid<std::uint8_t>& observed_free,
                                 std::int64_t* dropped = nullptr);

struct LayoutResult {
  Grid<Cell> layout;                   ///< M_r
  Grid<std::uint8_t> passage;          ///< step 4 result (1 = inside)
  std::vector<CellIndex> seeds;        ///< flood-fill seeds actually used
  std::vector<HangingObject> hanging;  ///< wall-band objects not counted as wall
  bool seeds_estimated = false;        ///< no scanner position known; seed estimated
  bool passage_bridged = false;        ///< no scanner in the passage area: gaps were bridged
  std::vector<std::string> warnings;
  std::int64_t cells_wall = 0, cells_furniture = 0, cells_free = 0, cells_unknown = 0;
};

/// Builds M_r from M_w (walls) and M_f (furniture), both 0/1 grids of the same size, flooding
/// free space from the scanners (map-frame x, y). With no scanner, the seed is the free cell
/// farthest from any obstacle inside the passage area, and the result says so; with `seen`, each
/// other floodable piece holding at least 2 m2 of seen cells gets a seed too (the rooms of a
/// floor scanned without positions).
/// support: the obstacle map of the slice hanging_gap_m thick just below the wall band (a wall
/// or a pillar continues there, a lamp does not); when null, the furniture map stands in for it.
/// evidence: cells the scan shows free (1; see LayoutParams::free_needs_evidence); when null,
/// or with free_needs_evidence false, every passage cell may be flooded.
/// seen: cells the scan shows free (the same map as evidence, given for every scan): a cell whose
/// floor was seen is never the inside of a wall (LayoutParams::wall_max_thickness_m); when null,
/// no cell is known seen.
LayoutResult build_layout(const Grid<std::uint8_t>& walls, const Grid<std::uint8_t>& furniture,
                          const GridGeometry& geometry,
                          const std::vector<Eigen::Vector2d>& scanners_map,
                          const LayoutParams& params = {},
                          const Grid<std::uint8_t>* support = nullptr,
                          const Grid<std::uint8_t>* evidence = nullptr,
                          const Grid<std::uint8_t>* seen = nullptr);

}  // namespace indoormap::layout
