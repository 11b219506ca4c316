#pragma once
// Room border closure (paper section 3.2.C; docs/border-closure.md): the broken, noisy border of a
// scanned room becomes one closed chain of cells in traversal order, a simple counter-clockwise
// polygon in map metres, and the list of the openings (doors, scan gaps) it runs across.
//
// Steps: (1) the heavy border: the marked cells of M_r dilated (full 5x5, then a 3x3 cross),
// minus that dilation eroded twice (full 5x5); (2) M_Lee (LeeMark): border, room space, virgin;
// (3) 8-connected components of the border with their bounding boxes, classified by counting the
// "switches" along their horizontal mid-line; (4) for every ring: opening lines (kOpenStart /
// kOpenEnd), the Lee wave around the ring, the backward pass preferring cells that touch room
// space; (5) the ring whose polygon contains the scanner is the room border; (6) openings, and the
// polygon fitted to the wall faces beside the chain, with its area and perimeter.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "indoormap/border/params.hpp"
#include "indoormap/border/polygon.hpp"
#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::layout {
struct MapResult;
}

namespace indoormap::border {

/// The marks of M_Lee (paper 3.2.C): the values of BorderResult::lee / LeeMarking::lee that are
/// not component labels (kFirstLeeLabel, kFirstLeeLabel - 1, ...) or wave distances (> 0).
enum class LeeMark : std::int32_t {
  kBorder = -1,     ///< heavy border, before the components are labelled
  kOpenStart = -2,  ///< the opening line of a traced ring, which the wave must not cross
  kOpenEnd = -3,    ///< the line beside it that marks the end of the wave's path
  kRoom = -4,       ///< marked (not unknown) cell outside the heavy border: room space
  kVirgin = -5,     ///< unknown cell outside the heavy border
};
/// The M_Lee label of the first border component; the i-th (0-based) has kFirstLeeLabel - i.
inline constexpr std::int32_t kFirstLeeLabel = -6;
/// The M_Lee value of a mark.
constexpr std::int32_t lee_value(LeeMark m) {
  return static_cast<std::int32_t>(m);
}
/// Whether an M_Lee value is a component label (of a cell the wave did not reach).
constexpr bool is_lee_label(std::int32_t v) {
  return v <= kFirstLeeLabel;
}
/// Whether an M_Lee value is a wave distance (1 at the start of the wave).
constexpr bool is_lee_distance(std::int32_t v) {
  return v > 0;
}

/// What a border component was classified as.
enum class ComponentKind : std::uint8_t {
  kRoomBorder,  ///< the closed ring whose polygon contains the scanner
  kRing,        ///< another closed ring (a column, an installation, a second room)
  kObject,      ///< fewer than two switches on its mid-line, or not closed: an interior object
};
std::string_view to_string(ComponentKind k);

/// One 8-connected component of the heavy border (M_Lee label kFirstLeeLabel, ... - 1, ...).
struct BorderComponent {
  int label = 0;           ///< M_Lee label (negative, from kFirstLeeLabel down)
  CellIndex start;         ///< first cell in row-major scan order
  CellIndex min, max;      ///< inclusive bounding box
  std::int64_t cells = 0;  ///< cell count
  int switches = 0;        ///< runs of the component along its horizontal mid-line
  ComponentKind kind = ComponentKind::kObject;
  std::string note;              ///< why a ring candidate could not be closed (empty otherwise)
  std::vector<CellIndex> chain;  ///< the closed chain (rings only), counter-clockwise
};

/// A stretch of the room border with no obstacle: a door, a passage or a gap in the scan.
struct Opening {
  Eigen::Vector2d a_m = Eigen::Vector2d::Zero();  ///< end points on the obstacle faces (map m)
  Eigen::Vector2d b_m = Eigen::Vector2d::Zero();
  double width_m = 0.0;            ///< |b - a|: the clear width between the obstacles
  bool is_door_candidate = false;  ///< door_min_m <= width_m <= door_max_m
  std::size_t chain_first = 0;     ///< open chain cells: chain[first .. last] (cyclic)
  std::size_t chain_last = 0;
};

/// An interior object: a border component that is not the room border.
struct InteriorObject {
  Eigen::Vector2d min_m = Eigen::Vector2d::Zero(), max_m = Eigen::Vector2d::Zero();  ///< bbox
  CellIndex min, max;
  std::int64_t cells = 0;
  ComponentKind kind = ComponentKind::kObject;
};

struct BorderResult {
  bool closed = false;  ///< a closed border containing the scanner was found
  std::string reason;   ///< why not, when !closed (an expected outcome, e.g. an open scan)
  /// The room border: a closed chain of distinct cells in traversal order, counter-clockwise;
  /// each cell is an 8-neighbour of the next, and the last of the first.
  std::vector<CellIndex> chain;
  std::vector<Eigen::Vector2d> chain_m;  ///< cell centres of chain (map metres)
  /// The room polygon on the wall faces: one line fitted per face, corners where consecutive
  /// faces meet, doors bridged along their wall; simple, counter-clockwise (map m).
  Polygon polygon_m;
  Polygon chain_polygon_m;   ///< the simplified chain polygon (at the back of the wall band)
  double area_m2 = 0.0;      ///< of polygon_m
  double perimeter_m = 0.0;  ///< of polygon_m
  std::vector<Opening> openings;
  std::vector<BorderComponent> components;  ///< every component, in label order
  std::vector<InteriorObject> interior_objects;
  int room_component = -1;                              ///< index into components, -1 when !closed
  Eigen::Vector2d scanner_m = Eigen::Vector2d::Zero();  ///< the position used for the choice
  std::vector<std::string> warnings;
  // Intermediate maps (same size as the layout), for pictures and inspection.
  Grid<std::uint8_t> heavy;  ///< step 1: 1 = heavy border
  Grid<std::int32_t> lee;    ///< M_Lee after the waves: LeeMark values, labels, wave distances
};

/// Step 1: the heavy border of the marked (non-unknown) cells of the layout. Throws UsageError
/// for invalid structuring elements.
Grid<std::uint8_t> heavy_border(const Grid<Cell>& layout, const BorderParams& params = {});

/// Steps 2-3: M_Lee (LeeMark::kRoom, kVirgin; the heavy border's cells then labelled
/// kFirstLeeLabel, kFirstLeeLabel - 1, ... per 8-connected component) and the components with
/// bounding boxes and switch counts. Components with two or more switches are returned as kRing
/// candidates, others as kObject.
struct LeeMarking {
  Grid<std::int32_t> lee;
  std::vector<BorderComponent> components;
};
LeeMarking mark_border_components(const Grid<Cell>& layout, const Grid<std::uint8_t>& heavy);

/// What tracing one ring candidate gave: the closed chain, or why there is none.
struct RingTrace {
  std::vector<CellIndex> chain;  ///< counter-clockwise, at least 4 cells; empty when it failed
  std::string why;               ///< why the ring could not be closed (empty when it was)
  explicit operator bool() const { return !chain.empty(); }
};

/// Step 4 for one ring candidate: opening lines (LeeMark::kOpenStart / kOpenEnd), Lee wave,
/// backward pass. Writes the lines and the wave into lee (the grid of mark_border_components).
RingTrace trace_ring(Grid<std::int32_t>& lee, const BorderComponent& comp);

/// The whole closure. scanners_map: scanner positions (map metres); the room border is the
/// smallest closed ring whose polygon contains the first scanner that lies inside any ring.
/// Without scanners the largest ring is taken, with a warning. open_below (optional, same size
/// as the layout): 1 where an obstacle cell is open below door height (see door_clear_height_m).
/// Throws UsageError for invalid params, Error when the sizes disagree, BudgetError when the
/// layout exceeds params.max_cells.
BorderResult close_border(const Grid<Cell>& layout, const GridGeometry& geometry,
                          const std::vector<Eigen::Vector2d>& scanners_map,
                          const BorderParams& params = {},
                          const Grid<std::uint8_t>* open_below = nullptr);

/// Step 6 alone, for a room whose outline was found another way (the rooms of a floor,
/// docs/border-closure.md): outline_m (a simple polygon in the map frame, on or near the room's
/// wall faces) is simplified and fitted to the wall faces of the layout as the closure's own
/// polygon is: one line per face, door recesses and the shadows of objects along a wall bridged,
/// corners where the faces meet. nullopt when the fit fails (a corner strays, the result is not
/// simple); the caller keeps its outline. Throws UsageError for invalid params.
std::optional<Polygon> fit_to_wall_faces(const Polygon& outline_m, const Grid<Cell>& layout,
                                         const GridGeometry& geometry,
                                         const BorderParams& params = {});

/// The closure on a pipeline result: scanners from cloud_map (or the estimated flood seeds), and
/// open_below from the voxel grid between the furniture band's bottom and door_clear_height_m.
BorderResult close_border(const layout::MapResult& map, const BorderParams& params = {});

/// Obstacle (wall / furniture) cells of the layout that are open below door height: their voxel
/// column is empty from the furniture band's bottom to door_clear_height_m above the floor, and
/// a scanner's ray through them finds points below that height within door_probe_m beyond them
/// (so the foot of a wall merely hidden behind a cabinet does not count).
Grid<std::uint8_t> open_below_mask(const layout::MapResult& map,
                                   const std::vector<Eigen::Vector2d>& scanners_map,
                                   const BorderParams& params = {});

}  // namespace indoormap::border
