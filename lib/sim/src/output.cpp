#include "indoormap/sim/output.hpp"

#include <cstdio>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::sim {

namespace fs = std::filesystem;

namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace

std::vector<std::string> write_3dtk(const fs::path& dir, const SimResult& sim) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw OutputError(dir.string(), ec.message());
  std::vector<std::string> files;
  for (std::size_t k = 0; k < sim.scans.size(); ++k) {
    const ScanBlock& b = sim.scans[k];
    const Eigen::Vector3d s = sim.scanner_positions_m[b.scanner];
    char name[32];
    std::snprintf(name, sizeof name, "scan%03zu", k);
    write_stream_atomic(dir / (std::string(name) + ".3d"), [&](std::ostream& out) {
      char line[96];
      for (std::size_t i = b.begin; i < b.end; ++i) {
        const Eigen::Vector3d p = sim.points[i].cast<double>() - s;
        const int len = std::snprintf(line, sizeof line, "%.3f %.3f %.3f\n", -100.0 * p.y(), 100.0 * p.z(), 100.0 * p.x());
        out.write(line, len);
      }
    });
    const std::string pose = fmt("%.3f", -100.0 * s.y()) + " " + fmt("%.3f", 100.0 * s.z()) + " " +
                             fmt("%.3f", 100.0 * s.x()) + "\n0 0 0\n";
    write_file_atomic(dir / (std::string(name) + ".pose"), pose);
    files.push_back(std::string(name) + ".3d");
    files.push_back(std::string(name) + ".pose");
  }
  return files;
}

}  // namespace indoormap::sim
