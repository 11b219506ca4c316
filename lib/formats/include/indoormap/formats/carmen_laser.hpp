#pragma once
// A CARMEN FLASER message as a laser::LaserScan: the one adapter of the CARMEN reader to the
// occupancy mappers (laser-to-map, the tests).
//
// CARMEN's robot laser message (carmen_robot_laser_message, what FLASER logs) holds in
// `x y theta` the pose of the laser, not of the robot's centre: the robot module adds the
// robot_frontlaser_offset before the message is sent (`odom_*` is the centre's odometry). The
// scan therefore gets the laser pose from x y theta as it is, and the robot pose is that pose
// moved back by the PARAM offset; composing the PARAM offset onto x y theta again would shift
// every beam by the offset twice (on freiburg-079, -0.04 m, that cost 7 points of consistency).
#include "indoormap/formats/carmen.hpp"
#include "indoormap/laser/scan.hpp"

namespace indoormap::formats {

/// The scan of one FLASER message: ranges, beam angles and maximum range as read; laser_offset
/// = the PARAM offset; robot_pose_map such that laser_pose_map() equals the message's x y theta.
laser::LaserScan to_laser_scan(const CarmenScan& c);

}  // namespace indoormap::formats
