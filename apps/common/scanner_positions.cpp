#include "scanner_positions.hpp"

#include <cstdio>

#include "indoormap/core/errors.hpp"
#include "indoormap/formats/trajectory.hpp"

namespace indoormap::app {

void add_trajectory(const std::string& file, const CloudExtent& extent, PointCloud& cloud) {
  const formats::Trajectory t = formats::read_trajectory(file);
  for (std::size_t i = 0; i < t.positions.size(); ++i) {
    const Eigen::Vector3d& p = t.positions[i];
    const Eigen::Vector3d m = Eigen::Vector3d::Constant(kTrajectoryMarginM);
    if (!extent.empty && ((p.array() < (extent.lo_m - m).array()).any() ||
                          (p.array() > (extent.hi_m + m).array()).any())) {
      char msg[256];
      std::snprintf(msg, sizeof msg,
                    "position (%.3f, %.3f, %.3f) lies more than %g m outside the cloud "
                    "(x %.2f..%.2f, y %.2f..%.2f, z %.2f..%.2f): wrong frame or unit?",
                    p.x(), p.y(), p.z(), kTrajectoryMarginM, extent.lo_m.x(), extent.hi_m.x(),
                    extent.lo_m.y(), extent.hi_m.y(), extent.lo_m.z(), extent.hi_m.z());
      throw InputError(file, msg, t.lines[i]);
    }
    cloud.scanners.push_back(p);
  }
  cloud.origins.clear();
  cloud.scanners_on_path = !t.positions.empty();
}

}  // namespace indoormap::app
