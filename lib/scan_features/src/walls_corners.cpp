// Walls from fitted lines, and the corners where consecutive walls meet.
#include <algorithm>
#include <cmath>

#include "indoormap/scan_features/features.hpp"

namespace indoormap::scan_features {

namespace {

/// Where the lines of walls u and v cross; false when (nearly) parallel.
bool intersect(const Wall& u, const Wall& v, Eigen::Vector2d& x) {
  const Eigen::Vector2d du = u.direction_laser(), dv = v.direction_laser();
  const double den = du.x() * dv.y() - du.y() * dv.x();
  if (std::abs(den) < 1e-9) return false;
  const Eigen::Vector2d w0 = v.start_laser - u.start_laser;
  const double t = (w0.x() * dv.y() - w0.y() * dv.x()) / den;
  x = u.start_laser + t * du;
  return true;
}

}  // namespace

std::vector<Wall> make_walls(const laser::LaserScan& scan, const Segmentation& seg,
                             const std::vector<Line>& lines) {
  std::vector<Wall> walls;
  walls.reserve(lines.size());
  const bool reversed = scan.angle_increment_rad < 0.0;  // scan order then runs clockwise
  for (const Line& l : lines) {
    Wall w;
    w.start_laser = l.start_laser;
    w.end_laser = l.end_laser;
    w.start = l.start;
    w.end = l.end;
    w.points = l.last - l.first + 1;
    w.first_beam = seg.points[static_cast<std::size_t>(l.first)].beam;
    w.last_beam = seg.points[static_cast<std::size_t>(l.last)].beam;
    w.rms_m = l.fit.rms_m;
    if (reversed) {
      std::swap(w.start_laser, w.end_laser);
      std::swap(w.start, w.end);
      std::swap(w.first_beam, w.last_beam);
    }
    walls.push_back(w);
  }
  if (reversed) std::reverse(walls.begin(), walls.end());
  return walls;
}

std::vector<Corner> find_corners(std::vector<Wall>& walls, bool full_circle,
                                 const CornerParams& params) {
  std::vector<Corner> corners;
  const std::size_t n = walls.size();
  const std::size_t pairs = full_circle ? n : (n > 0 ? n - 1 : 0);
  for (std::size_t i = 0; i < pairs && n > 1; ++i) {
    Wall& u = walls[i];
    Wall& v = walls[(i + 1) % n];
    const double angle =
        std::acos(std::clamp(u.direction_laser().dot(v.direction_laser()), -1.0, 1.0));
    if (angle < params.min_angle_rad) continue;
    Eigen::Vector2d x;
    if (!intersect(u, v, x)) continue;
    const bool connected = u.end == Boundary::kSplit;
    if (!connected && u.end == Boundary::kScanEnd) continue;
    const double gap = connected ? params.max_gap_m : params.potential_max_gap_m;
    if ((x - u.end_laser).norm() > gap || (x - v.start_laser).norm() > gap) continue;
    Corner c;
    c.wall_in = static_cast<int>(i);
    c.wall_out = static_cast<int>((i + 1) % n);
    c.angle_rad = angle;
    c.type = corner_type_three_distances(Eigen::Vector2d::Zero(), u.start_laser, x, v.end_laser,
                                         &c.d_rc_m, &c.d_rl_m, &c.d_cl_m);
    if (connected) {
      u.end_laser = x;  // the corner is both walls' end point
      v.start_laser = x;
    } else {
      // The vertex is not seen: it must lie on the walls' extensions, beyond both ends.
      if (u.direction_laser().dot(x - u.end_laser) < -params.max_gap_m ||
          v.direction_laser().dot(v.start_laser - x) < -params.max_gap_m)
        continue;
      c.type = CornerType::kPotential;
    }
    c.p_laser = x;
    corners.push_back(c);
  }
  return corners;
}

}  // namespace indoormap::scan_features
