#pragma once
// The point-cloud value type passed between modules: plain vectors, no PCL.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace indoormap {

struct PointCloud {
  /// Points in metres. The frame is stated by whoever produced the cloud (loaders: the input
  /// frame after unit / axis conversion, z up; the pipeline: the levelled map frame).
  std::vector<Eigen::Vector3f> points;
  /// Known scanner positions, same frame as points. Empty when unknown.
  std::vector<Eigen::Vector3d> scanners;
};

}  // namespace indoormap
