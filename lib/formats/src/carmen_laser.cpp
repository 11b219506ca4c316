#include "indoormap/formats/carmen_laser.hpp"

#include <cmath>

namespace indoormap::formats {

laser::LaserScan to_laser_scan(const CarmenScan& c) {
  laser::LaserScan s;
  s.ranges_m = c.ranges_m;
  s.angle_min_rad = c.angle_min_rad;
  s.angle_increment_rad = c.angle_increment_rad;
  s.max_range_m = c.max_range_m;
  s.laser_offset = {c.laser_offset.x_m, c.laser_offset.y_m, c.laser_offset.theta_rad};
  // robot = laser * offset^-1: heading first, then the offset's position turned into the map.
  const double th = laser::wrap_angle(c.theta_rad - s.laser_offset.theta_rad);
  const double ct = std::cos(th), st = std::sin(th);
  s.robot_pose_map = {c.x_m - (ct * s.laser_offset.x_m - st * s.laser_offset.y_m),
                      c.y_m - (st * s.laser_offset.x_m + ct * s.laser_offset.y_m), th};
  s.time_s = c.logger_timestamp_s;
  return s;
}

}  // namespace indoormap::formats
