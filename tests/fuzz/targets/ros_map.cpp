// ROS map (map.yaml + the image it names), through read_ros_map: part 1 is the YAML, part 2
// the image, written as map.pgm and map.png (OpenCV decodes by content, not by name).
#include <stdexcept>

#include "fuzz_target.hpp"
#include "map_yaml.hpp"

INDOORMAP_FUZZ_TARGET(ros_map) {
  using namespace indoormap::fuzz;
  const auto dir = fresh_dir();
  const auto parts = split_parts(bytes, 2);
  const auto yaml = write_file(dir, "map.yaml", parts[0]);
  if (parts.size() > 1) {
    write_file(dir, "map.pgm", parts[1]);
    write_file(dir, "map.png", parts[1]);
  }
  const indoormap::formats::RosMap m = indoormap::app::read_ros_map(yaml, kMaxCells);
  if (m.cells.width != m.geometry.width() || m.cells.height != m.geometry.height() ||
      m.cells.size() == 0 || static_cast<std::int64_t>(m.cells.size()) > kMaxCells)
    throw std::logic_error("map size inconsistent with its geometry or budget");
}
