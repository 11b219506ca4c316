#pragma once
// Scanner trajectories: the positions a mobile scanner passed through, as positions of known
// scanners for the navigation map's free-space rays. Formats (one pose a line; blank lines and
// lines starting with '#' are skipped; words separated by spaces, tabs or commas):
//  - TUM: `t x y z qx qy qz qw` (8 numbers), the quaternion of unit norm within
//    kQuaternionNormTolerance (a sloppy writer rounds to 4-6 digits; a wrong column order does
//    not pass);
//  - plain: `x y z` (3 numbers).
// Every line of a file has the same format. Positions in metres, the cloud's input frame.
#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <vector>

#include "indoormap/sim/mobile.hpp"

namespace indoormap::formats {

inline constexpr double kQuaternionNormTolerance = 1e-3;

enum class TrajectoryFormat { kTum, kPlain };

struct Trajectory {
  TrajectoryFormat format = TrajectoryFormat::kPlain;
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::size_t> lines;  ///< the file line of each position (1-based)
};

/// Reads a trajectory. Throws InputError naming the file and line: a word that is not a finite
/// number, a line of another column count than 3 or 8 (or than the file's first pose line), a
/// TUM quaternion off unit norm; and for a missing, unreadable or empty file (no pose line).
Trajectory read_trajectory(const std::filesystem::path& path);

/// Writes poses in the TUM format above (9 significant digits, a header comment naming the
/// frame), atomically: scene-sim's trajectory.txt, which read_trajectory reads back.
void write_tum_trajectory(const std::filesystem::path& path,
                          const std::vector<sim::TrajectoryPose>& poses);

}  // namespace indoormap::formats
