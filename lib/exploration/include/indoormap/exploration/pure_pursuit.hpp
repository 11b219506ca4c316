#pragma once
// Path following (the paper's reactive part): pure pursuit where the path points are look-ahead
// points one after the other (the target moves on once it is within lookahead_m), driving at a
// constant speed on the arc through the target; a target far to the side makes the robot turn on
// the spot first. The obstacle stop looks at the latest scan: an obstacle within stop_distance_m
// of the robot in the corridor it is heading into stops it; it then backs off a little and asks
// for a new goal.
#include <cstddef>
#include <limits>
#include <vector>

#include "indoormap/laser/scan.hpp"

namespace indoormap::exploration {

struct PurePursuitParams {
  double speed_mps = 0.4;  ///< the paper's 0.4 m/s
  double lookahead_m = 0.4;
  double max_turn_rate_radps = 1.5;
  double turn_in_place_above_rad = 1.0;  ///< |bearing to the target| above this: rotate only
  double goal_tolerance_m = 0.1;
  void validate() const;
};

struct PursuitCommand {
  double v_mps = 0.0;
  double omega_radps = 0.0;
  bool finished = false;  ///< within goal_tolerance_m of the last point
};

class PurePursuit {
 public:
  PurePursuit() = default;
  PurePursuit(std::vector<Eigen::Vector2d> path_m, PurePursuitParams params);
  PursuitCommand step(const laser::Pose2d& robot);
  std::size_t target_index() const { return target_; }
  /// Distance from p to the current target point (infinity without a path).
  double target_distance_m(const Eigen::Vector2d& p) const {
    return path_.empty() ? std::numeric_limits<double>::infinity() : (path_[target_] - p).norm();
  }
  const std::vector<Eigen::Vector2d>& path() const { return path_; }
  bool empty() const { return path_.empty(); }

 private:
  std::vector<Eigen::Vector2d> path_;
  PurePursuitParams p_;
  std::size_t target_ = 0;
};

struct ReactiveParams {
  double stop_distance_m = 0.3;  ///< from the robot's edge, in its heading direction (the paper)
  double corridor_half_width_m = 0.2;  ///< lateral extent checked (the robot radius)
  double backoff_m = 0.2;              ///< how far it backs off after a stop
  double backoff_speed_mps = 0.2;
  void validate() const;
};

/// True when a beam of scan hits within stop_distance_m ahead of a robot of radius robot_radius_m
/// moving forward, inside the corridor of half width corridor_half_width_m, and before the point
/// the robot is driving to (target_distance_m from its centre): the path was planned clear of the
/// obstacles known then, so what stops the robot is something in the way to its target.
bool obstacle_ahead(const laser::LaserScan& scan, double robot_radius_m, const ReactiveParams& p,
                    double target_distance_m = std::numeric_limits<double>::infinity());

/// Unicycle motion for dt seconds at (v, omega), exact on the arc.
laser::Pose2d integrate_motion(const laser::Pose2d& pose, double v_mps, double omega_radps,
                               double dt_s);

}  // namespace indoormap::exploration
