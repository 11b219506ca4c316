#include "indoormap/exploration/pure_pursuit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "indoormap/core/errors.hpp"

namespace indoormap::exploration {

namespace {
void positive(double v, const char* what, const char* key) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw UsageError(std::string(what) + ": " + key + " must be positive");
}
}  // namespace

void PurePursuitParams::validate() const {
  positive(speed_mps, "pure pursuit", "speed_mps");
  positive(lookahead_m, "pure pursuit", "lookahead_m");
  positive(max_turn_rate_radps, "pure pursuit", "max_turn_rate_radps");
  positive(turn_in_place_above_rad, "pure pursuit", "turn_in_place_above_rad");
  positive(goal_tolerance_m, "pure pursuit", "goal_tolerance_m");
}

void ReactiveParams::validate() const {
  positive(stop_distance_m, "reactive", "stop_distance_m");
  positive(corridor_half_width_m, "reactive", "corridor_half_width_m");
  positive(backoff_speed_mps, "reactive", "backoff_speed_mps");
  if (!(backoff_m >= 0.0)) throw UsageError("reactive: backoff_m must be >= 0");
}

PurePursuit::PurePursuit(std::vector<Eigen::Vector2d> path_m, PurePursuitParams params)
    : path_(std::move(path_m)), p_(params) {
  p_.validate();
}

PursuitCommand PurePursuit::step(const laser::Pose2d& robot) {
  PursuitCommand cmd;
  if (path_.empty()) {
    cmd.finished = true;
    return cmd;
  }
  const Eigen::Vector2d pos = robot.position_m();
  if ((path_.back() - pos).norm() <= p_.goal_tolerance_m) {
    target_ = path_.size() - 1;
    cmd.finished = true;
    return cmd;
  }
  // The path points are look-ahead points one after the other: move on while the current one
  // is within the look-ahead distance (never back).
  while (target_ + 1 < path_.size() && (path_[target_] - pos).norm() < p_.lookahead_m) ++target_;
  const Eigen::Vector2d d = path_[target_] - pos;
  const double c = std::cos(robot.theta_rad), s = std::sin(robot.theta_rad);
  const double x = c * d.x() + s * d.y(), y = -s * d.x() + c * d.y();  // robot frame
  const double bearing = std::atan2(y, x);
  if (std::abs(bearing) > p_.turn_in_place_above_rad) {
    cmd.omega_radps = std::copysign(p_.max_turn_rate_radps, bearing);
    return cmd;
  }
  // Pure pursuit: the arc through the target has curvature 2 y / L^2.
  const double l2 = x * x + y * y;
  const double kappa = l2 > 0.0 ? 2.0 * y / l2 : 0.0;
  cmd.v_mps = p_.speed_mps;
  cmd.omega_radps = cmd.v_mps * kappa;
  if (std::abs(cmd.omega_radps) > p_.max_turn_rate_radps) {  // keep the arc, slow down
    cmd.v_mps = p_.max_turn_rate_radps / std::abs(kappa);
    cmd.omega_radps = std::copysign(p_.max_turn_rate_radps, kappa);
  }
  return cmd;
}

bool obstacle_ahead(const laser::LaserScan& scan, double robot_radius_m, const ReactiveParams& p,
                    double target_distance_m) {
  const laser::Pose2d& off = scan.laser_offset;
  for (std::size_t i = 0; i < scan.size(); ++i) {
    if (!scan.is_hit(i)) continue;
    const double a = off.theta_rad + scan.beam_angle_rad(i), r = scan.ranges_m[i];
    const double x = off.x_m + r * std::cos(a), y = off.y_m + r * std::sin(a);  // robot frame
    if (x > 0.0 && std::abs(y) <= p.corridor_half_width_m &&
        x - robot_radius_m < p.stop_distance_m && x < target_distance_m)
      return true;
  }
  return false;
}

laser::Pose2d integrate_motion(const laser::Pose2d& pose, double v_mps, double omega_radps,
                               double dt_s) {
  const double th = pose.theta_rad, dth = omega_radps * dt_s;
  laser::Pose2d out = pose;
  if (std::abs(dth) < 1e-9) {
    out.x_m += v_mps * dt_s * std::cos(th);
    out.y_m += v_mps * dt_s * std::sin(th);
  } else {
    const double r = v_mps / omega_radps;
    out.x_m += r * (std::sin(th + dth) - std::sin(th));
    out.y_m -= r * (std::cos(th + dth) - std::cos(th));
  }
  out.theta_rad = laser::wrap_angle(th + dth);
  return out;
}

}  // namespace indoormap::exploration
