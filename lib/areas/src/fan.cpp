// The fan-of-turns test (van Galen, section 5: turn on the minimum radius, then drive straight
// until the travel length is reached; the footprint must stay on free cells all along).
#include "indoormap/areas/fan.hpp"

#include <cmath>
#include <numbers>

namespace indoormap::areas {

bool footprint_free(const Grid<std::uint8_t>& free, double cell_m, const FootprintParams& fp,
                    const CellPose& pose) {
  const double half_l = 0.5 * fp.robot_length_m / cell_m, half_w = 0.5 * fp.robot_width_m / cell_m;
  const Eigen::Vector2d fwd(std::cos(pose.heading_rad), std::sin(pose.heading_rad));
  const Eigen::Vector2d left(-fwd.y(), fwd.x());
  // Samples at most half a cell apart cover every cell the rectangle overlaps by more than a
  // sliver.
  const int nl = static_cast<int>(std::ceil(2.0 * half_l / 0.5)),
            nw = static_cast<int>(std::ceil(2.0 * half_w / 0.5));
  for (int i = 0; i <= nl; ++i)
    for (int j = 0; j <= nw; ++j) {
      const Eigen::Vector2d q = pose.at + fwd * (-half_l + 2.0 * half_l * i / nl) +
                                left * (-half_w + 2.0 * half_w * j / nw);
      const int c = static_cast<int>(std::floor(q.x())), r = static_cast<int>(std::floor(q.y()));
      if (!free.contains(c, r) || !free.at(c, r)) return false;
    }
  return true;
}

namespace {

/// The pose after travelling s cells on a turn by turn_rad (arc of radius rad, then straight).
CellPose along(const CellPose& p0, double turn_rad, double rad, double s) {
  const double arc = rad * std::abs(turn_rad);
  CellPose p = p0;
  const double sgn = turn_rad >= 0.0 ? 1.0 : -1.0;
  const double on_arc = std::min(s, arc);
  if (on_arc > 0.0 && rad > 0.0) {
    const double a = sgn * on_arc / rad;  // heading change so far
    const Eigen::Vector2d fwd(std::cos(p0.heading_rad), std::sin(p0.heading_rad));
    const Eigen::Vector2d left(-fwd.y(), fwd.x());
    p.at = p0.at + fwd * (rad * std::sin(std::abs(a))) + left * (sgn * rad * (1.0 - std::cos(a)));
    p.heading_rad = p0.heading_rad + a;
  } else {
    p.heading_rad = p0.heading_rad + (rad > 0.0 ? 0.0 : turn_rad);  // zero radius: turn in place
  }
  if (rad <= 0.0) p.heading_rad = p0.heading_rad + turn_rad;
  const double straight = s - on_arc;
  if (straight > 0.0)
    p.at += straight * Eigen::Vector2d(std::cos(p.heading_rad), std::sin(p.heading_rad));
  return p;
}

}  // namespace

std::vector<double> possible_turns(const Grid<std::uint8_t>& free, double cell_m,
                                   const FootprintParams& fp, const CorridorParams& cp,
                                   const CellPose& pose) {
  std::vector<double> ok;
  if (!footprint_free(free, cell_m, fp, pose)) return ok;
  const double rad = fp.turning_radius_m / cell_m, travel = cp.fan_travel_m / cell_m;
  for (double deg = cp.fan_min_deg; deg <= cp.fan_max_deg + 1e-9; deg += cp.fan_step_deg) {
    const double turn = deg * std::numbers::pi / 180.0;
    const double length = std::max(travel, rad * std::abs(turn));
    bool clear = true;
    for (double s = 1.0; clear && s <= length + 1e-9; s += 1.0)
      clear = footprint_free(free, cell_m, fp, along(pose, turn, rad, std::min(s, length)));
    if (clear) ok.push_back(deg);
  }
  return ok;
}

bool can_turn_aside(const Grid<std::uint8_t>& free, double cell_m, const FootprintParams& fp,
                    const CorridorParams& cp, const CellPose& pose) {
  for (double deg : possible_turns(free, cell_m, fp, cp, pose))
    if (std::abs(deg) > cp.side_turn_min_deg) return true;
  return false;
}

}  // namespace indoormap::areas
