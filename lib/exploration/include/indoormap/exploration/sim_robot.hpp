#pragma once
// A simulated world for exploration: the true map (Grid<Cell> + GridGeometry), a round
// differential-drive robot that cannot enter obstacles, and a simulated laser (beam count, field
// of view, maximum range, Gaussian range noise from a caller's seeded std::mt19937).
#include <random>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/exploration/navigator.hpp"
#include "indoormap/laser/scan.hpp"

namespace indoormap::exploration {

struct RobotParams {
  double radius_m = 0.2;
  double speed_mps = 0.4;
  double max_turn_rate_radps = 1.5;
  void validate() const;
};

struct SimLaserParams {
  int beam_count = 271;
  double fov_rad = 4.71238898038469;  ///< 270 degrees, centred on the heading
  double max_range_m = 10.0;
  double range_noise_sd_m = 0.01;
  laser::Pose2d offset;  ///< in the robot frame
  void validate() const;
};

class SimWorld {
 public:
  SimWorld(Grid<Cell> truth, GridGeometry geometry, double robot_radius_m);
  const Grid<Cell>& truth() const { return truth_; }
  const GridGeometry& geometry() const { return geometry_; }
  /// True when a robot centred at p would overlap an obstacle or leave the map.
  bool collides(const Eigen::Vector2d& p_m) const;
  /// A scan from the robot pose: exact ray casting to the middle of the first obstacle cell, plus
  /// noise; beams without a return read max_range_m.
  laser::LaserScan scan(const laser::Pose2d& robot, const SimLaserParams& p, std::mt19937& rng,
                        double time_s) const;

 private:
  Grid<Cell> truth_;
  GridGeometry geometry_;
  Grid<std::uint8_t> blocked_;  ///< 1: a robot centred here overlaps an obstacle
};

}  // namespace indoormap::exploration
