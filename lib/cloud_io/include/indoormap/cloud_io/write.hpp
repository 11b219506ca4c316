#pragma once
// Point-cloud writers: binary PCD and 3DTK scan directories, by hand (no PCL). The readers of the
// same formats are in indoormap/cloud_io/load.hpp. Every file is written atomically (temporary
// name, then rename).
#include <Eigen/Core>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace indoormap::cloud_io {

/// Writes points (metres, given frame) as a binary PCD with fields x y z. viewpoint_m is written
/// to the VIEWPOINT line. Throws OutputError.
void write_pcd_binary(const std::string& path, const std::vector<Eigen::Vector3f>& points,
                      const Eigen::Vector3d& viewpoint_m = Eigen::Vector3d::Zero());

/// One scan of a 3DTK directory: its points and the scanner position, both in the same frame
/// (metres, right-handed, z up).
struct TdtkScan {
  std::span<const Eigen::Vector3f> points_m;
  Eigen::Vector3d scanner_m = Eigen::Vector3d::Zero();
};

/// Writes a 3DTK scan directory (created if missing): per scan k, scanNNN.3d (NNN = k, three
/// digits) with the points in the scan's local frame (point minus scanner position, no rotation)
/// converted to 3DTK's left-handed, y-up centimetres (x = -100 Y, y = 100 Z, z = 100 X; "%.3f"),
/// and scanNNN.pose holding the scanner position in the same units with zero Euler angles.
/// load_cloud(dir) reads it back. Returns the file names written (relative to dir), in order.
/// Throws OutputError.
std::vector<std::string> write_3dtk_scans(const std::filesystem::path& dir,
                                          const std::vector<TdtkScan>& scans);

}  // namespace indoormap::cloud_io
