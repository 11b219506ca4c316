#include "indoormap/exploration/sim_robot.hpp"

#include <cmath>
#include <string>

#include "indoormap/core/errors.hpp"
#include "indoormap/laser/raycast.hpp"

namespace indoormap::exploration {

void RobotParams::validate() const {
  if (!(radius_m > 0.0) || !std::isfinite(radius_m))
    throw UsageError("robot: radius_m must be positive");
  if (!(speed_mps > 0.0) || !std::isfinite(speed_mps))
    throw UsageError("robot: speed_mps must be positive");
  if (!(max_turn_rate_radps > 0.0) || !std::isfinite(max_turn_rate_radps))
    throw UsageError("robot: max_turn_rate_radps must be positive");
}

void SimLaserParams::validate() const {
  if (beam_count < 1 || beam_count > 100'000)
    throw UsageError("sim laser: beam_count must be in [1, 100000]");
  if (!(fov_rad > 0.0 && fov_rad <= 2.0 * 3.14159265358979323846 + 1e-9))
    throw UsageError("sim laser: fov_rad must be in (0, 2 pi]");
  if (!(max_range_m > 0.0) || !std::isfinite(max_range_m))
    throw UsageError("sim laser: max_range_m must be positive");
  if (!(range_noise_sd_m >= 0.0) || !std::isfinite(range_noise_sd_m))
    throw UsageError("sim laser: range_noise_sd_m must be >= 0");
}

SimWorld::SimWorld(Grid<Cell> truth, GridGeometry geometry, double robot_radius_m)
    : truth_(std::move(truth)), geometry_(std::move(geometry)) {
  if (truth_.width != geometry_.width() || truth_.height != geometry_.height())
    throw UsageError("sim world: the map does not match its geometry");
  // A centre farther than the radius from every obstacle cell's centre keeps the body (up to
  // half a cell) off it; the 0.5 cell makes the test conservative.
  blocked_ = inflate_obstacles(truth_, geometry_.to_cells(robot_radius_m) + 0.5);
}

bool SimWorld::collides(const Eigen::Vector2d& p_m) const {
  const CellIndex c = geometry_.cell_of(p_m);
  return !geometry_.contains(c) || blocked_.at(c) != 0;
}

laser::LaserScan SimWorld::scan(const laser::Pose2d& robot, const SimLaserParams& p,
                                std::mt19937& rng, double time_s) const {
  laser::LaserScan s;
  s.max_range_m = p.max_range_m;
  s.robot_pose_map = robot;
  s.laser_offset = p.offset;
  s.time_s = time_s;
  const bool full_circle = p.fov_rad >= 2.0 * 3.14159265358979323846 - 1e-9;
  s.angle_min_rad = -p.fov_rad / 2.0;
  s.angle_increment_rad =
      p.beam_count == 1 ? 0.0 : p.fov_rad / (full_circle ? p.beam_count : p.beam_count - 1);
  if (p.beam_count == 1) s.angle_min_rad = 0.0;
  s.ranges_m.resize(static_cast<std::size_t>(p.beam_count));
  const laser::Pose2d lp = s.laser_pose_map();
  std::normal_distribution<double> noise(0.0, p.range_noise_sd_m);
  for (int i = 0; i < p.beam_count; ++i) {
    // The beam ends halfway through the first obstacle cell: a pixel of the true map is an
    // obstacle somewhere inside, and a range exactly on the cell's edge would put the hit in the
    // free cell before it half of the time.
    const laser::RayHit h = laser::cast_ray_cell(
        geometry_, lp.position_m(), lp.theta_rad + s.beam_angle_rad(static_cast<std::size_t>(i)),
        p.max_range_m, [&](CellIndex c) { return laser::is_obstacle(truth_.at(c)); });
    const double r = h.hit ? 0.5 * (h.entry_m + h.exit_m) : p.max_range_m;
    double m = r;
    if (h.hit && r < p.max_range_m) {
      if (p.range_noise_sd_m > 0.0) m = std::max(0.0, r + noise(rng));
      m = std::min(m, p.max_range_m * 0.999);  // a return stays a return
    }
    s.ranges_m[static_cast<std::size_t>(i)] = static_cast<float>(m);
  }
  return s;
}

}  // namespace indoormap::exploration
