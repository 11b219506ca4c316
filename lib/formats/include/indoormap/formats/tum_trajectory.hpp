#pragma once
// scene-sim's trajectory.txt: the TUM RGB-D format, one pose a line,
// "t x y z qx qy qz qw" (seconds, metres, unit quaternion sensor -> cloud frame), '#' comments.
#include <filesystem>
#include <vector>

#include "indoormap/sim/mobile.hpp"

namespace indoormap::formats {

/// Writes the poses (9 significant digits, a header comment naming the frame), atomically.
void write_tum_trajectory(const std::filesystem::path& path,
                          const std::vector<sim::TrajectoryPose>& poses);

/// Reads a TUM trajectory: 8 numbers a line, blank lines and '#' comments skipped. Throws
/// InputError naming the file and line for non-numbers, a wrong column count or a quaternion
/// whose norm is not 1 within 1e-3.
std::vector<sim::TrajectoryPose> read_tum_trajectory(const std::filesystem::path& path);

}  // namespace indoormap::formats
