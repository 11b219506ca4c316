#pragma once
// laser-to-map's run as values (the map built, the self-consistency check, the log's counts) and
// the files written from it. Everything is computed before the first file is written, so a bad
// log leaves no output at all.
#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "indoormap/formats/carmen.hpp"
#include "indoormap/laser/occupancy.hpp"
#include "indoormap/laser/raycast.hpp"
#include "laser_config.hpp"

namespace indoormap::app {

/// One pose refinement pass (laser/pose_refine.hpp): how far it moved the scans.
struct PoseRefineStats {
  std::size_t scans = 0;        ///< scans aligned
  std::size_t scans_moved = 0;  ///< of them, with a correction applied
  double median_shift_m = 0.0, max_shift_m = 0.0, max_turn_deg = 0.0;  ///< over the moved ones
};

struct LaserMapRun {
  std::string log_path;
  LaserMapConfig config;
  laser::OccupancyMap map;
  laser::ConsistencyResult check;
  formats::CarmenStats stats;           ///< of the mapping pass
  std::size_t scans_mapped = 0;         ///< FLASER messages integrated
  std::size_t scans_skipped = 0;        ///< FLASER messages with an unusable pose or angles
  std::vector<Eigen::Vector2d> path_m;  ///< robot path (map frame), a point per cell moved
  std::vector<PoseRefineStats> refine;  ///< one per pose refinement pass (none: the log's poses)
  double map_ms = 0.0, check_ms = 0.0;
};

/// laser_map.json: the check's figures and the log's counts.
nlohmann::json laser_map_json(const LaserMapRun& run);

/// Writes map.pgm, map.yaml, map.png and laser_map.json into out (each atomically); returns their
/// names in writing order.
std::vector<std::string> write_laser_map_outputs(const std::filesystem::path& out,
                                                 const LaserMapRun& run);

}  // namespace indoormap::app
