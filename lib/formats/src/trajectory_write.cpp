#include <cstdio>
#include <string>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/formats/trajectory.hpp"

namespace indoormap::formats {

void write_tum_trajectory(const std::filesystem::path& path,
                          const std::vector<sim::TrajectoryPose>& poses) {
  std::string s = "# TUM trajectory: t x y z qx qy qz qw (s, m, sensor -> cloud frame)\n";
  char line[256];
  for (const auto& p : poses) {
    const auto& q = p.orientation;
    std::snprintf(line, sizeof line, "%.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", p.t_s,
                  p.position_m.x(), p.position_m.y(), p.position_m.z(), q.x() + 0.0, q.y() + 0.0,
                  q.z() + 0.0, q.w() + 0.0);  // + 0.0: no "-0"
    s += line;
  }
  write_file_atomic(path, s);
}

}  // namespace indoormap::formats
