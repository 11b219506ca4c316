// plan-route's plain image map (--map FILE.png|.pgm --resolution M --free-min V), through
// read_plain_map. Byte 0 picks the file name's extension and the resolution, byte 1 is
// --free-min (0..255, as CLI11 lets through); the rest is the image. The decoders are chosen by
// content (PGM P5 / P2, PNG), so both are reached whatever the name.
#include <array>
#include <limits>
#include <stdexcept>

#include "fuzz_target.hpp"
#include "indoormap/formats/ros_map.hpp"

INDOORMAP_FUZZ_TARGET(plain_map) {
  using namespace indoormap::fuzz;
  static constexpr std::array<const char*, 4> kNames = {"map.pgm", "map.png", "map.PNG", "map"};
  // Resolutions the app passes on (> 0 per its check) plus the ones the reader must refuse itself.
  static constexpr std::array<double, 8> kResolutions = {
      0.05, 0.1, 1.0, 1e-9, 1e9, 0.0, -1.0, std::numeric_limits<double>::quiet_NaN()};
  const auto select = bytes.empty() ? 0u : static_cast<unsigned char>(bytes[0]);
  const int free_min = bytes.size() < 2 ? 250 : static_cast<unsigned char>(bytes[1]);
  const auto image = bytes.substr(std::min<std::size_t>(bytes.size(), 2));
  const auto path = write_file(fresh_dir(), kNames[select & 3u], image);
  const double resolution = kResolutions[(select >> 2) & 7u];
  const indoormap::formats::RosMap m =
      indoormap::formats::read_plain_map(path, resolution, free_min, kMaxCells);
  if (m.cells.width != m.geometry.width() || m.cells.height != m.geometry.height() ||
      m.cells.size() == 0 || static_cast<std::int64_t>(m.cells.size()) > kMaxCells ||
      m.geometry.cell_m() != resolution)
    throw std::logic_error("map size inconsistent with its geometry, budget or resolution");
}
