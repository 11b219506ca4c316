// pcd-to-map's --trajectory FILE (TUM `t x y z qx qy qz qw` or plain `x y z` lines), through
// read_trajectory: the whole input is the file. Every pose it returns is finite and has its line.
#include "indoormap/formats/trajectory.hpp"

#include <cmath>
#include <stdexcept>

#include "fuzz_target.hpp"

INDOORMAP_FUZZ_TARGET(trajectory) {
  using namespace indoormap::fuzz;
  const auto path = write_file(fresh_dir(), "trajectory.txt", bytes);
  const indoormap::formats::Trajectory t = indoormap::formats::read_trajectory(path);
  if (t.positions.empty() || t.positions.size() != t.lines.size())
    throw std::logic_error("a trajectory without poses, or a pose without its line");
  for (const auto& p : t.positions)
    if (!p.allFinite()) throw std::logic_error("a position that is not finite");
}
