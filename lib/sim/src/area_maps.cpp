// Generated maps with known corridors, crossings and rooms (see area_maps.hpp).
#include "indoormap/sim/area_maps.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "indoormap/core/errors.hpp"

namespace indoormap::sim {
namespace {

struct Box {
  Eigen::Vector2d lo, hi;
  AreaTruth kind;
  bool contains(const Eigen::Vector2d& p) const {
    return p.x() >= lo.x() && p.y() >= lo.y() && p.x() < hi.x() && p.y() < hi.y();
  }
};

/// The design: free boxes with their truth (later boxes win where they overlap: crossings last).
struct Design {
  std::vector<Box> boxes;
  std::vector<Eigen::Vector2d> crossings;
  std::vector<Box> rooms;  ///< for clutter
};

Box box(double x0, double y0, double x1, double y1, AreaTruth k) {
  return {{std::min(x0, x1), std::min(y0, y1)}, {std::max(x0, x1), std::max(y0, y1)}, k};
}

void crossing(Design& d, double x, double y, double w) {
  d.boxes.push_back(box(x, y, x + w, y + w, AreaTruth::kCrossing));
  d.crossings.emplace_back(x + 0.5 * w, y + 0.5 * w);
}

Design design(AreaMapShape shape, double w, double a) {
  using enum AreaTruth;
  Design d;
  switch (shape) {
    case AreaMapShape::kStraight:
      d.boxes.push_back(box(0, 0, 2 * a + w, w, kCorridor));
      break;
    case AreaMapShape::kCorner:
      d.boxes.push_back(box(0, 0, a + w, w, kCorridor));
      d.boxes.push_back(box(a, 0, a + w, a + w, kCorridor));
      crossing(d, a, 0, w);
      break;
    case AreaMapShape::kTJunction:
      d.boxes.push_back(box(0, 0, 2 * a + w, w, kCorridor));
      d.boxes.push_back(box(a, 0, a + w, a + w, kCorridor));
      crossing(d, a, 0, w);
      break;
    case AreaMapShape::kXJunction:
      d.boxes.push_back(box(0, a, 2 * a + w, a + w, kCorridor));
      d.boxes.push_back(box(a, 0, a + w, 2 * a + w, kCorridor));
      crossing(d, a, a, w);
      break;
    case AreaMapShape::kFloor: {
      // A main corridor along y in [a, a + w]: an X-junction at x = a, a T (stem up) at
      // x = 3a + w, a corner at its east end (down), and two rooms behind doors.
      const double east = 4 * a + 2 * w;
      d.boxes.push_back(box(0, a, east + w, a + w, kCorridor));
      d.boxes.push_back(box(a, 0, a + w, 2 * a + w, kCorridor));
      d.boxes.push_back(box(3 * a + w, a, 3 * a + 2 * w, 2 * a + w, kCorridor));
      d.boxes.push_back(box(east, 0, east + w, a + w, kCorridor));
      for (double x0 : {a + w + 1.0, 2 * a + w + 0.5}) {
        const double x1 = std::min(x0 + 4.0, 3 * a + w - 0.2);
        const Box room = box(x0, a + w + 0.15, x1, a + w + 4.15, kRoom);
        d.boxes.push_back(room);
        d.rooms.push_back(room);
        const double door = 0.5 * (x0 + x1);
        d.boxes.push_back(box(door - 0.45, a + w - 0.01, door + 0.45, a + w + 0.16, kRoom));
      }
      crossing(d, a, a, w);
      crossing(d, 3 * a + w, a, w);
      crossing(d, east, a, w);
      break;
    }
  }
  return d;
}

}  // namespace

void validate(const AreaMapParams& p) {
  if (!(p.cell_m > 0.0)) throw UsageError("area map: cell_m must be positive");
  if (!(p.corridor_width_m >= 4 * p.cell_m))
    throw UsageError("area map: corridor_width_m must be at least 4 cells");
  if (!(p.arm_length_m >= p.corridor_width_m))
    throw UsageError("area map: arm_length_m must be at least the corridor width");
  if (!(p.wall_noise >= 0.0 && p.wall_noise <= 0.5))
    throw UsageError("area map: wall_noise must be within 0..0.5");
  if (p.clutter_per_room < 0) throw UsageError("area map: clutter_per_room must be >= 0");
  if (!std::isfinite(p.rotation_deg)) throw UsageError("area map: rotation_deg must be finite");
}

AreaMap make_area_map(AreaMapShape shape, const AreaMapParams& p) {
  validate(p);
  Design d = design(shape, p.corridor_width_m, p.arm_length_m);
  std::mt19937 rng(p.seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Box> clutter;
  for (const Box& room : d.rooms)
    for (int i = 0; i < p.clutter_per_room; ++i) {
      const double s = 0.2 + 0.2 * u(rng);
      const double x = room.lo.x() + 0.6 + (room.hi.x() - room.lo.x() - 1.2 - s) * u(rng);
      const double y = room.lo.y() + 0.6 + (room.hi.y() - room.lo.y() - 1.2 - s) * u(rng);
      clutter.push_back(box(x, y, x + s, y + s, AreaTruth::kNone));
    }
  Eigen::Vector2d lo(1e9, 1e9), hi(-1e9, -1e9);
  for (const Box& b : d.boxes) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  const Eigen::Vector2d centre = 0.5 * (lo + hi);
  const double half_diag = 0.5 * (hi - lo).norm() + 1.0;
  const double th = p.rotation_deg * std::numbers::pi / 180.0;
  Eigen::Matrix2d rot_inv;
  rot_inv << std::cos(th), std::sin(th), -std::sin(th), std::cos(th);  // rotation by -th
  const int n = static_cast<int>(std::ceil(2.0 * half_diag / p.cell_m));
  AreaMap m;
  m.geometry = GridGeometry(Eigen::Vector2d(-half_diag, -half_diag), p.cell_m, n, n);
  m.cells = Grid<Cell>(n, n, Cell::kWall);
  m.truth = Grid<std::uint8_t>(n, n, 0);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const Eigen::Vector2d q = rot_inv * m.geometry.center_of({c, r}) + centre;
      AreaTruth t = AreaTruth::kNone;
      for (const Box& b : d.boxes)
        if (b.contains(q)) t = (t == AreaTruth::kCrossing) ? t : b.kind;
      for (const Box& b : clutter)
        if (b.contains(q)) t = AreaTruth::kNone;
      if (t == AreaTruth::kNone) continue;
      m.cells.at(c, r) = Cell::kFree;
      m.truth.at(c, r) = static_cast<std::uint8_t>(t);
    }
  if (p.wall_noise > 0.0) {
    const Grid<Cell> before = m.cells;
    for (int r = 1; r + 1 < n; ++r)
      for (int c = 1; c + 1 < n; ++c) {
        if (before.at(c, r) != Cell::kFree) continue;
        const bool by_wall =
            before.at(c + 1, r) != Cell::kFree || before.at(c - 1, r) != Cell::kFree ||
            before.at(c, r + 1) != Cell::kFree || before.at(c, r - 1) != Cell::kFree;
        if (by_wall && u(rng) < p.wall_noise) {
          m.cells.at(c, r) = Cell::kWall;
          m.truth.at(c, r) = 0;
        }
      }
  }
  const Eigen::Matrix2d rot = rot_inv.transpose();
  for (const auto& x : d.crossings) m.crossings_m.push_back(rot * (x - centre));
  return m;
}

}  // namespace indoormap::sim
