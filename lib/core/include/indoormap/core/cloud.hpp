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
  /// Which scanner saw which points, where the input says so (a 3DTK scan file, one PCD file
  /// with a VIEWPOINT): each span is a run of consecutive points and the index of its scanner in
  /// `scanners` (SIZE_MAX: not known for this run). Empty when unknown; when set, the spans
  /// cover every point in order.
  struct OriginSpan {
    std::size_t first = 0, count = 0;
    std::size_t scanner = 0;
  };
  std::vector<OriginSpan> origins;
  /// The positions are a moving scanner's path (a trajectory): rays from along it cover the
  /// free space, so free space needs their evidence (make_map).
  bool scanners_on_path = false;
};

}  // namespace indoormap
