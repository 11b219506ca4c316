// 3DTK scan directory, through load_cloud(dir): parts (separated by kPartSeparator lines) are
// scan000.3d, scan000.pose, scan001.3d, scan001.frames; an empty part is not written, so every
// combination of pose files (none, .pose, .frames, both) is reachable.
#include "cloud_check.hpp"

INDOORMAP_FUZZ_TARGET(tdtk) {
  using namespace indoormap::fuzz;
  const auto dir = fresh_dir();
  const char* names[] = {"scan000.3d", "scan000.pose", "scan001.3d", "scan001.frames"};
  const auto parts = split_parts(bytes, 4);
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (!parts[i].empty() || i == 0) write_file(dir, names[i], parts[i]);
  load_and_check(dir.string());
}
