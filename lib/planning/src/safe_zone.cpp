#include "indoormap/planning/safe_zone.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "indoormap/core/errors.hpp"

namespace indoormap::planning {

void validate(const RobotParams& robot) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw UsageError("invalid parameter " + what);
  };
  require(std::isfinite(robot.width_m) && robot.width_m > 0, "robot.width_m: must be > 0");
  require(std::isfinite(robot.length_m) && robot.length_m > 0, "robot.length_m: must be > 0");
  require(std::isfinite(robot.extra_m) && robot.extra_m >= 0, "robot.extra_m: must be >= 0");
}

double d_save_m(const RobotParams& robot) {
  return std::max(robot.width_m / 2.0, robot.length_m / 2.0) + robot.extra_m;
}

namespace {
std::string shortest(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}
}  // namespace

void check_disk_size(const RobotParams& robot, double cell_m) {
  const double cells = d_save_m(robot) / cell_m;
  if (!(cells > kMaxDiskRadiusCells)) return;
  throw BudgetError(
      "the robot's clearance d_save = max(robot.width_m, robot.length_m) / 2 + "
      "robot.extra_m = " +
      shortest(d_save_m(robot)) + " m is " + shortest(cells) + " cells of the map resolution " +
      shortest(cell_m) + " m, above the limit of " + shortest(kMaxDiskRadiusCells) +
      " cells: check the robot size (metres) and the map resolution");
}

DiskTemplate make_disk_template(double d_save, double cell_m) {
  if (!(cell_m > 0) || !std::isfinite(cell_m))
    throw UsageError("disk template: cell_m must be > 0");
  if (!(d_save >= 0) || !std::isfinite(d_save))
    throw UsageError("disk template: d_save must be >= 0");
  DiskTemplate t;
  t.radius_cells = d_save / cell_m;
  if (t.radius_cells > kMaxDiskRadiusCells)
    throw BudgetError("disk template: d_save / cell_m > 2000 cells");
  // The paper enumerates the circle's points by (R, phi) (formula 2); the set of unique offsets
  // it produces is the integer disk, which we enumerate directly. The tolerance keeps offsets
  // whose squared length equals r^2 up to rounding (0.15 / 0.05 is 2.9999999999999996).
  const double r2 = t.radius_cells * t.radius_cells + 1e-9;
  const int r = static_cast<int>(std::floor(t.radius_cells + 1e-9));
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx)
      if (double(dx) * dx + double(dy) * dy <= r2) t.offsets.push_back({dx, dy});
  return t;
}

namespace {

bool is_obstacle(Cell c, bool unknown_is_obstacle) {
  return c == Cell::kWall || c == Cell::kFurniture || (unknown_is_obstacle && c == Cell::kUnknown);
}

}  // namespace

Grid<SafeCell> safe_zone(const Grid<Cell>& layout, const DiskTemplate& disk,
                         const SafeZoneParams& params) {
  const int w = layout.width, h = layout.height;
  Grid<SafeCell> out(w, h, SafeCell::kOutside);
  for (std::size_t i = 0; i < layout.data.size(); ++i) {
    const Cell c = layout.data[i];
    out.data[i] = c == Cell::kFree                              ? SafeCell::kSafe
                  : (c == Cell::kWall || c == Cell::kFurniture) ? SafeCell::kObstacle
                                                                : SafeCell::kOutside;
  }
  auto obstacle = [&](int col, int row) {
    if (!layout.contains(col, row)) return true;  // beyond the edge: obstacle
    return is_obstacle(layout.at(col, row), params.unknown_is_obstacle);
  };
  auto stamp = [&](int col, int row) {
    for (const auto& o : disk.offsets) {
      const int c = col + o.col, r = row + o.row;
      if (out.contains(c, r) && out.at(c, r) == SafeCell::kSafe) out.at(c, r) = SafeCell::kUnsafe;
    }
  };
  // The nearest obstacle to a free cell always borders a non-obstacle cell (a step towards the
  // free cell would be closer otherwise), so only border obstacles need a stamp.
  for (int row = -1; row <= h; ++row)
    for (int col = -1; col <= w; ++col) {
      if (!obstacle(col, row)) continue;
      const bool inside = layout.contains(col, row);
      // Cells outside the grid matter only next to it.
      if (!inside && (row < -1 || row > h || col < -1 || col > w)) continue;
      bool border = false;
      for (const auto& [dc, dr] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const int c = col + dc, r = row + dr;
        if (layout.contains(c, r) && !obstacle(c, r)) border = true;
      }
      if (border) stamp(col, row);
    }
  return out;
}

}  // namespace indoormap::planning
