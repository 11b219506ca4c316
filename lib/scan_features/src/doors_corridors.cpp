// Doors (gaps between collinear walls, or at a breakpoint) and corridors (long facing walls).
#include <algorithm>
#include <cmath>

#include "indoormap/scan_features/features.hpp"

namespace indoormap::scan_features {

namespace {

Eigen::Vector2d direction(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (b - a).normalized();
}

/// Signed distance of p to the line through a along unit d (positive on the left).
double side(const Eigen::Vector2d& a, const Eigen::Vector2d& d, const Eigen::Vector2d& p) {
  const Eigen::Vector2d ap = p - a;
  return d.x() * ap.y() - d.y() * ap.x();
}

double angle_between(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return std::acos(std::clamp(u.dot(v), -1.0, 1.0));
}

/// True when every beam strictly between the two jambs (in wall order) passes the door line a-b:
/// no return, or a return at least min_depth behind the line (on the side away from the sensor).
/// False when no beam passes between them.
bool gap_is_open(const laser::LaserScan& scan, int from_beam, int to_beam, const Eigen::Vector2d& a,
                 const Eigen::Vector2d& b, const DoorParams& p) {
  const int n = static_cast<int>(scan.size());
  const int step = scan.angle_increment_rad < 0.0 ? -1 : 1;
  const int count = ((to_beam - from_beam) * step + n) % n - 1;
  if (count < 1) return false;
  const Eigen::Vector2d d = direction(a, b);
  for (int k = 1; k <= count; ++k) {
    const int i = ((from_beam + k * step) % n + n) % n;
    if (!scan.is_hit(static_cast<std::size_t>(i))) continue;
    const double r = scan.ranges_m[static_cast<std::size_t>(i)];
    const double phi = scan.beam_angle_rad(static_cast<std::size_t>(i));
    if (side(a, d, {r * std::cos(phi), r * std::sin(phi)}) > -p.min_depth_m) return false;
  }
  return true;
}

}  // namespace

namespace {

/// The kind of door between the end a of wall u and the start b of a later wall v, if any.
bool door_between(const Wall& u, const Wall& v, const DoorParams& p, DoorKind& kind) {
  const Eigen::Vector2d a = u.end_laser, b = v.start_laser;
  const double width = (b - a).norm();
  if (width < p.min_width_m || width > p.max_width_m) return false;
  const Eigen::Vector2d du = u.direction_laser(), dv = v.direction_laser(), dg = direction(a, b);
  if (angle_between(du, dv) <= p.max_angle_rad && std::abs(side(a, du, b)) <= p.max_offset_m &&
      std::abs(side(b, dv, a)) <= p.max_offset_m) {
    kind = DoorKind::kCollinear;
    return true;
  }
  if ((angle_between(du, dg) <= p.max_angle_rad && std::abs(side(a, du, b)) <= p.max_offset_m) ||
      (angle_between(dv, dg) <= p.max_angle_rad && std::abs(side(b, dv, a)) <= p.max_offset_m)) {
    kind = DoorKind::kBreakpoint;
    return true;
  }
  return false;
}

/// Walls seen through an opening (a closet's back wall) lie between its jambs in wall order.
constexpr std::size_t kMaxWallsThroughDoor = 4;

}  // namespace

std::vector<Door> find_doors(const laser::LaserScan& scan, const Segmentation& seg,
                             const std::vector<Wall>& walls, const DoorParams& p) {
  std::vector<Door> doors;
  const std::size_t n = walls.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Wall& u = walls[i];
    if (u.end == Boundary::kSplit || u.end == Boundary::kScanEnd) continue;
    for (std::size_t k = 1; k <= kMaxWallsThroughDoor && k < n; ++k) {
      if (!seg.full_circle && i + k >= n) break;
      const std::size_t j = (i + k) % n;
      const Wall& v = walls[j];
      DoorKind kind;
      if (!door_between(u, v, p, kind)) continue;
      if (!gap_is_open(scan, u.last_beam, v.first_beam, u.end_laser, v.start_laser, p)) continue;
      Door d;
      d.a_laser = u.end_laser;
      d.b_laser = v.start_laser;
      d.wall_before = static_cast<int>(i);
      d.wall_after = static_cast<int>(j);
      d.kind = kind;
      doors.push_back(d);
      break;
    }
  }
  return doors;
}

namespace {

/// The walls (indices) running along wall k: same direction within the angle, on its line.
std::vector<int> side_walls(const std::vector<Wall>& walls, int k, const CorridorParams& p) {
  std::vector<int> out;
  const Eigen::Vector2d dk = walls[static_cast<std::size_t>(k)].direction_laser();
  const Eigen::Vector2d ak = walls[static_cast<std::size_t>(k)].start_laser;
  for (int j = 0; j < static_cast<int>(walls.size()); ++j) {
    const Wall& w = walls[static_cast<std::size_t>(j)];
    const Eigen::Vector2d mid = 0.5 * (w.start_laser + w.end_laser);
    if (j == k || (angle_between(dk, w.direction_laser()) <= p.max_angle_rad &&
                   std::abs(side(ak, dk, mid)) <= p.side_offset_m))
      out.push_back(j);
  }
  return out;
}

}  // namespace

std::vector<Corridor> find_corridors(const std::vector<Wall>& walls, const CorridorParams& p) {
  std::vector<Corridor> out;
  const int n = static_cast<int>(walls.size());
  std::vector<int> used(static_cast<std::size_t>(n), -1);  // corridor of a wall, if any
  for (int i = 0; i < n; ++i) {
    const Wall& u = walls[static_cast<std::size_t>(i)];
    if (u.length_m() < p.min_wall_length_m || used[static_cast<std::size_t>(i)] >= 0) continue;
    const Eigen::Vector2d du = u.direction_laser();
    for (int k = i + 1; k < n; ++k) {
      const Wall& v = walls[static_cast<std::size_t>(k)];
      if (v.length_m() < p.min_wall_length_m || used[static_cast<std::size_t>(k)] >= 0) continue;
      const Eigen::Vector2d dv = v.direction_laser();
      if (angle_between(du, -dv) > p.max_angle_rad) continue;  // facing: opposite directions
      const Eigen::Vector2d mu = 0.5 * (u.start_laser + u.end_laser);
      const Eigen::Vector2d mv = 0.5 * (v.start_laser + v.end_laser);
      const double width = side(u.start_laser, du, mv);
      if (width < p.min_width_m || width > p.max_width_m) continue;
      if (side(v.start_laser, dv, mu) < p.min_width_m) continue;  // free sides face each other
      const double v0 = du.dot(v.end_laser - u.start_laser),
                   v1 = du.dot(v.start_laser - u.start_laser);
      const double overlap = std::min(u.length_m(), v1) - std::max(0.0, v0);
      if (overlap < p.min_overlap_m) continue;
      Corridor c;
      c.side_a = side_walls(walls, i, p);
      c.side_b = side_walls(walls, k, p);
      c.width_m = width;
      c.overlap_m = overlap;
      const int id = static_cast<int>(out.size());
      for (int j : c.side_a) used[static_cast<std::size_t>(j)] = id;
      for (int j : c.side_b) used[static_cast<std::size_t>(j)] = id;
      out.push_back(std::move(c));
      break;
    }
  }
  return out;
}

}  // namespace indoormap::scan_features
