// CARMEN laser logs (laser-to-map's input), through the streaming reader: the bytes as a file
// (plain text or gzip: zlib tells them apart by content), every message read to the end. Byte 0
// of a seed is not special: the whole input is the log.
#include "indoormap/formats/carmen.hpp"

#include <cmath>
#include <stdexcept>

#include "fuzz_target.hpp"

INDOORMAP_FUZZ_TARGET(carmen) {
  using namespace indoormap::fuzz;
  indoormap::formats::CarmenReadOptions options;
  options.max_line_bytes = 1 << 14;
  options.max_beams = 1024;
  const auto path = write_file(fresh_dir(), "log.gz", bytes);
  indoormap::formats::CarmenReader reader(path.string(), options);
  indoormap::formats::CarmenScan scan;
  while (reader.next(scan)) {
    if (scan.ranges_m.empty() || scan.ranges_m.size() > 1024 || !std::isfinite(scan.x_m) ||
        !std::isfinite(scan.angle_increment_rad) || !(scan.max_range_m > 0.0) || scan.line == 0)
      throw std::logic_error("scan inconsistent with the reader's contract");
    for (float r : scan.ranges_m)
      if (!(r >= 0.0f) || !std::isfinite(r)) throw std::logic_error("range not finite or negative");
  }
  if (reader.stats().scans > reader.stats().lines) throw std::logic_error("more scans than lines");
}
