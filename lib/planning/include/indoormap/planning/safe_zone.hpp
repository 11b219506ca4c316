#pragma once
// The safe zone of paper section 3.2.D: every free cell of M_r farther than d_save from the
// nearest obstacle, where d_save = max(w/2, l/2) + d_extra (formula 1). The robot can turn on the
// spot at any safe cell without touching an obstacle.
#include <cstdint>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::planning {

/// The robot's footprint and turning margin (metres).
struct RobotParams {
  double width_m = 0.4;   ///< across the direction of travel
  double length_m = 0.5;  ///< along the direction of travel
  double extra_m = 0.05;  ///< d_extra: deviation from the current point while turning on the spot
};

/// Checks that the sizes are finite and positive (extra_m >= 0). Throws UsageError naming the key
/// ("invalid parameter robot.<key>: ..."). Called by make_templates.
void validate(const RobotParams& robot);

/// d_save = max(width/2, length/2) + extra (formula 1), metres.
double d_save_m(const RobotParams& robot);

/// Cell classes of the safe-zone layout M_t (paper marks in brackets).
enum class SafeCell : std::uint8_t {
  kOutside = 0,   ///< unknown / virgin area of M_r, outside the room ("-3")
  kObstacle = 1,  ///< wall or furniture of M_r ("1", "3")
  kUnsafe = 2,    ///< free, but within d_save of an obstacle ("-1")
  kSafe = 3,      ///< free and farther than d_save from every obstacle ("-2")
};

/// The "impassable area mask": offsets (dx, dy) in cells with dx^2 + dy^2 <= r^2, r = d_save /
/// cell_m. Built once per (d_save, cell_m) and reused for every map.
struct DiskTemplate {
  double radius_cells = 0.0;
  std::vector<CellIndex> offsets;  ///< sorted by row then column
};
DiskTemplate make_disk_template(double d_save_m, double cell_m);

/// Largest disk radius make_disk_template builds, in cells.
inline constexpr double kMaxDiskRadiusCells = 2000;

/// Throws BudgetError when the robot's d_save is above kMaxDiskRadiusCells cells of cell_m,
/// naming the robot keys, d_save and the cell size (a robot size in the wrong unit, or a map
/// resolution far too fine). Called by make_templates before make_disk_template.
void check_disk_size(const RobotParams& robot, double cell_m);

struct SafeZoneParams {
  /// Unknown cells of M_r count as obstacles (the robot keeps d_save from unexplored space).
  /// Cells beyond the grid's edge always count as obstacles.
  bool unknown_is_obstacle = true;
};

/// Stamps the disk around every obstacle cell that borders a non-obstacle cell (and around the
/// cells just outside the grid) over the free cells of M_r. A free cell is kUnsafe iff an
/// obstacle cell centre lies within d_save (Euclidean, centre to centre), else kSafe.
Grid<SafeCell> safe_zone(const Grid<Cell>& layout, const DiskTemplate& disk,
                         const SafeZoneParams& params = {});

}  // namespace indoormap::planning
