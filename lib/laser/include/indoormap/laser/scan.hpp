#pragma once
// A 2D laser scan as a value: ranges, beam angles, maximum range, the robot pose in the map frame
// and the laser's mounting offset in the robot frame.
//
// Frames: the map frame is metric and right-handed; the robot frame has x forward, y left; the
// laser frame is the robot frame moved by laser_offset. Beam i points at
// angle_min_rad + i * angle_increment_rad in the laser frame (counter-clockwise from its x axis).
#include <Eigen/Core>
#include <vector>

namespace indoormap::laser {

/// A planar pose: position (metres) and heading (radians, counter-clockwise from +x).
struct Pose2d {
  double x_m = 0.0;
  double y_m = 0.0;
  double theta_rad = 0.0;

  Eigen::Vector2d position_m() const { return {x_m, y_m}; }
  /// The point p given in this pose's frame, expressed in the parent frame.
  Eigen::Vector2d transform(const Eigen::Vector2d& p) const;
  /// This pose followed by `child` (child given in this pose's frame).
  Pose2d compose(const Pose2d& child) const;
  friend bool operator==(const Pose2d&, const Pose2d&) = default;
};

/// Wraps an angle to (-pi, pi].
double wrap_angle(double a_rad);

struct LaserScan {
  std::vector<float> ranges_m;  ///< one per beam; <= 0, non-finite or >= max_range_m: no return
  double angle_min_rad = 0.0;
  double angle_increment_rad = 0.0;
  double max_range_m = 0.0;  ///< the sensor's maximum: readings at or beyond it are no return
  Pose2d robot_pose_map;     ///< the robot in the map frame
  Pose2d laser_offset;       ///< the laser in the robot frame
  double time_s = 0.0;

  std::size_t size() const { return ranges_m.size(); }
  double beam_angle_rad(std::size_t i) const {
    return angle_min_rad + static_cast<double>(i) * angle_increment_rad;
  }
  /// The laser in the map frame (robot pose composed with the offset).
  Pose2d laser_pose_map() const { return robot_pose_map.compose(laser_offset); }
  /// True when beam i measured an obstacle (a finite range in (0, max_range_m)).
  bool is_hit(std::size_t i) const {
    const float r = ranges_m[i];
    return r > 0.0f && r < max_range_m;  // NaN compares false
  }
};

/// Throws indoormap::UsageError when the scan cannot be used (no beams, non-finite angles or pose,
/// max_range_m not positive).
void validate(const LaserScan& scan);

/// Map-frame end points of the beams that hit (is_hit), in beam order.
std::vector<Eigen::Vector2d> hit_points_map(const LaserScan& scan);

}  // namespace indoormap::laser
