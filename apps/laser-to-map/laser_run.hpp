#pragma once
// laser-to-map's passes over the log: mapping, the optional pose refinement (map, align every scan
// to the map, map again; laser/pose_refine.hpp), and the self-consistency check, which casts every
// scan from the pose its map was built with. The log is streamed again for each pass (memory stays
// bounded by the map and one pose per scan).
#include <string>

#include "laser_outputs.hpp"

namespace indoormap::app {

/// Everything laser-to-map computes for one log (nothing written). quiet: no progress.
LaserMapRun map_log(const std::string& path, const LaserMapConfig& cfg, bool quiet);

}  // namespace indoormap::app
