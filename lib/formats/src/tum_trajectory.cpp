#include "indoormap/formats/tum_trajectory.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"

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

std::vector<sim::TrajectoryPose> read_tum_trajectory(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string(), "cannot open the trajectory");
  std::vector<sim::TrajectoryPose> out;
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream ss(line);
    std::vector<double> v;
    std::string tok;
    while (ss >> tok) {
      std::size_t used = 0;
      double x = 0;
      try {
        x = std::stod(tok, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != tok.size() || !std::isfinite(x))
        throw InputError(path.string(), "'" + tok + "' is not a number", n);
      v.push_back(x);
    }
    if (v.size() != 8)
      throw InputError(
          path.string(),
          "expected 8 columns (t x y z qx qy qz qw), found " + std::to_string(v.size()), n);
    sim::TrajectoryPose p;
    p.t_s = v[0];
    p.position_m = {v[1], v[2], v[3]};
    p.orientation = Eigen::Quaterniond(v[7], v[4], v[5], v[6]);
    if (std::abs(p.orientation.norm() - 1.0) > 1e-3)
      throw InputError(path.string(), "the quaternion is not of unit length", n);
    out.push_back(p);
  }
  return out;
}

}  // namespace indoormap::formats
