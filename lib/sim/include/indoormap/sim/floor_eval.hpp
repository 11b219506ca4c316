#pragma once
// Whole-floor evaluation (docs/evaluation.md, "Floors"): free-space IoU over the cells some
// scanner could see, walls by face distance, doors a robot passes, scanner positions reachable
// from each other. Values in, values out; map-eval reads the files.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::sim {

/// A mask on a grid: 1 where the property holds.
using Mask = Grid<std::uint8_t>;

/// Cells of a grid equal to cls (1) or not (0).
Mask class_mask(const Grid<Cell>& cells, Cell cls);

struct SeenIou {
  double intersection_m2 = 0.0, union_m2 = 0.0, seen_m2 = 0.0;
  std::optional<double> iou;  ///< empty when the union is empty
};

/// Free-space IoU over the seen cells: intersection = seen truth cells the result calls free;
/// union = seen truth cells plus result-free cells whose centre lies on a truth cell that is not
/// free (wall, furniture, unknown, or outside the truth grid). Result-free cells on truth-free
/// cells nobody could see are left out: a map may not be punished for leaving them unknown, nor
/// rewarded for guessing them. truth_free and seen share the truth geometry.
SeenIou evaluate_seen_free(const GridGeometry& truth_geometry, const Mask& truth_free,
                           const Mask& seen, const GridGeometry& result_geometry,
                           const Mask& result_free);

struct FarFree {
  double free_m2 = 0.0;  ///< result free area (cells inside the truth grid or not)
  double far_m2 = 0.0;   ///< of it, cells whose centre is farther than far_m from every seen cell
  std::optional<double> share;  ///< far / free; empty without free cells
};

/// Free space far from any observation (issue 17, sparse scans): result free cells whose centre
/// lies farther than far_m from the centre of every seen truth cell (cells outside the truth grid
/// count as far when no seen cell is near). A map that calls free only what the rays showed has
/// none; a streak of "free" bridged between isolated hits into unseen space is counted here.
FarFree evaluate_far_free(const GridGeometry& truth_geometry, const Mask& seen,
                          const GridGeometry& result_geometry, const Mask& result_free,
                          double far_m = 0.5);

struct FurnitureFree {
  double furniture_m2 = 0.0;    ///< truth furniture area (cells of the truth grid)
  double free_m2 = 0.0;         ///< of it, cells whose centre lies on a result free cell
  std::optional<double> share;  ///< free / furniture; empty without truth furniture
};

/// Furniture the result calls free: truth furniture cells (Cell::kFurniture) whose centre lies
/// on a result free cell. A robot planned there drives into a table top or a chair; unknown or
/// occupied is safe. Misregistration along an item's edge counts too (a cell or so).
FurnitureFree evaluate_furniture_free(const GridGeometry& truth_geometry, const Grid<Cell>& truth,
                                      const GridGeometry& result_geometry, const Mask& result_free);

struct FaceScores {
  int truth_faces = 0;                   ///< truth wall cells with a 4-neighbour that is truth free
  int result_walls = 0;                  ///< result wall cells
  std::optional<double> face_recall;     ///< faces within one result cell of a result wall
  std::optional<double> wall_precision;  ///< result walls within one truth cell of a face
};

/// Walls by face distance ("within one cell": the 3 x 3 neighbourhood of the cell holding the
/// other side's cell centre, in the grid being looked up).
FaceScores evaluate_wall_faces(const GridGeometry& truth_geometry, const Grid<Cell>& truth,
                               const GridGeometry& result_geometry, const Mask& result_wall);

/// Cells where a disc of radius_m centred at the cell centre covers only free cells (centres
/// within radius_m). Cells outside the grid count as not free.
Mask erode_free(const Mask& free, double cell_m, double radius_m);

/// A truth door: the opening's segment on the host room's inner wall face, and the outward
/// normal (into the wall; the passage spans [0, wall_thickness_m] along it).
struct TruthDoor {
  std::string id;
  Eigen::Vector2d a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero();
  Eigen::Vector2d outward = Eigen::Vector2d::UnitY();
  double wall_thickness_m = 0.2;
};

struct DoorResult {
  std::string id;
  bool open = false;
};

struct DoorScores {
  int doors = 0, open = 0;
  std::optional<double> open_share;
  std::vector<DoorResult> list;
};

/// A door is open when the centre of a disc robot (diameter robot_width_m) can move, through
/// cells of erode_free(free), from a cell at least 0.3 m before the door's inner face to one at
/// least 0.3 m beyond the wall, staying within the door's span widened by 0.3 m on each side
/// (and 0.6 m before / beyond): a local window, so a way round through another door does not
/// count. free: the result map's free cells (1); unknown and occupied both block.
DoorScores evaluate_doors(const std::vector<TruthDoor>& doors, const GridGeometry& geometry,
                          const Mask& free, double robot_width_m = 0.4);

struct ReachScores {
  int scanners = 0;
  int components = 0;  ///< distinct free-space components holding scanners (+1 per unplaced)
  int unplaced = 0;    ///< scanners with no robot-free cell within snap_m
  bool all_reachable = false;
  std::vector<int> component;  ///< per scanner; -1 unplaced
};

/// Every scanner (map-frame xy) is placed on the nearest cell of erode_free(free, robot radius)
/// within snap_m (a scanner's own spot may be unknown: no ray sees straight down), and the
/// scanners are grouped by the 8-connected components of that eroded free space.
ReachScores evaluate_reachability(const std::vector<Eigen::Vector2d>& scanners_m,
                                  const GridGeometry& geometry, const Mask& free,
                                  double robot_width_m = 0.4, double snap_m = 1.0);

}  // namespace indoormap::sim
