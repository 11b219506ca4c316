// Binary PCD writer (v0.7, fields x y z as float32), by hand: no PCL needed to write our clouds.
#include <bit>
#include <cmath>
#include <cstdio>
#include <string>

#include "indoormap/cloud_io/write.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::cloud_io {

namespace {
static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "Vector3f must be three packed floats");
static_assert(std::endian::native == std::endian::little, "binary PCD is written little-endian");

std::string number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}
}  // namespace

void write_pcd_binary(const std::string& path, const std::vector<Eigen::Vector3f>& points,
                      const Eigen::Vector3d& viewpoint_m) {
  if (!viewpoint_m.allFinite()) throw OutputError(path, "viewpoint is not finite");
  const std::string n = std::to_string(points.size());
  std::string header;
  header += "# .PCD v0.7 - Point Cloud Data file format\n";
  header += "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  header += "WIDTH " + n + "\nHEIGHT 1\n";
  header += "VIEWPOINT " + number(viewpoint_m.x()) + " " + number(viewpoint_m.y()) + " " +
            number(viewpoint_m.z()) + " 1 0 0 0\n";
  header += "POINTS " + n + "\nDATA binary\n";
  write_stream_atomic(path, [&](std::ostream& out) {
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    if (!points.empty())
      out.write(reinterpret_cast<const char*>(points.data()),
                static_cast<std::streamsize>(points.size() * sizeof(Eigen::Vector3f)));
  });
}

}  // namespace indoormap::cloud_io
