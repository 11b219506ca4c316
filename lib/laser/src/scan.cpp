#include "indoormap/laser/scan.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "indoormap/core/errors.hpp"

namespace indoormap::laser {

Eigen::Vector2d Pose2d::transform(const Eigen::Vector2d& p) const {
  const double c = std::cos(theta_rad), s = std::sin(theta_rad);
  return {x_m + c * p.x() - s * p.y(), y_m + s * p.x() + c * p.y()};
}

Pose2d Pose2d::compose(const Pose2d& child) const {
  const Eigen::Vector2d p = transform(child.position_m());
  return {p.x(), p.y(), wrap_angle(theta_rad + child.theta_rad)};
}

double wrap_angle(double a_rad) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double a = std::fmod(a_rad + std::numbers::pi, kTwoPi);
  if (a <= 0.0) a += kTwoPi;
  return a - std::numbers::pi;
}

void validate(const LaserScan& scan) {
  auto finite = [](double v) { return std::isfinite(v); };
  if (scan.ranges_m.empty()) throw UsageError("laser scan: no beams");
  if (!finite(scan.angle_min_rad) || !finite(scan.angle_increment_rad))
    throw UsageError("laser scan: angle_min_rad / angle_increment_rad must be finite");
  if (!(scan.max_range_m > 0.0) || !finite(scan.max_range_m))
    throw UsageError("laser scan: max_range_m must be positive and finite, got " +
                     std::to_string(scan.max_range_m));
  for (const Pose2d& p : {scan.robot_pose_map, scan.laser_offset})
    if (!finite(p.x_m) || !finite(p.y_m) || !finite(p.theta_rad))
      throw UsageError("laser scan: robot pose and laser offset must be finite");
}

std::vector<Eigen::Vector2d> hit_points_map(const LaserScan& scan) {
  const Pose2d laser = scan.laser_pose_map();
  std::vector<Eigen::Vector2d> out;
  out.reserve(scan.size());
  for (std::size_t i = 0; i < scan.size(); ++i) {
    if (!scan.is_hit(i)) continue;
    const double a = laser.theta_rad + scan.beam_angle_rad(i), r = scan.ranges_m[i];
    out.emplace_back(laser.x_m + r * std::cos(a), laser.y_m + r * std::sin(a));
  }
  return out;
}

}  // namespace indoormap::laser
