#pragma once
// Everything grid-areas computes, and the one function that writes it (all files at the end of
// main, so that the set can be made all-or-nothing in one place).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "areas_config.hpp"
#include "indoormap/areas/areas.hpp"
#include "indoormap/areas/score.hpp"
#include "indoormap/formats/ros_map.hpp"

namespace indoormap::app {

struct GridAreasRun {
  std::string map_path;
  std::optional<std::string> truth_path;
  GridAreasConfig config;
  formats::RosMap map;
  areas::AreasResult result;
  std::optional<areas::SegmentationScore> score;
  double split_ms = 0.0, score_ms = 0.0;
};

/// Counts per kind and the figures of summary.json / stderr.
nlohmann::json areas_summary_json(const GridAreasRun& run);
nlohmann::json score_json(const areas::SegmentationScore& s);

/// Writes areas.geojson, areas.json, areas_labels.png, areas.png, the Nav2 masks and (with a
/// ground truth) score.json into dir; returns the file names written.
std::vector<std::string> write_grid_areas_outputs(const std::filesystem::path& dir,
                                                  const GridAreasRun& run);

}  // namespace indoormap::app
