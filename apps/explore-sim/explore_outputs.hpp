#pragma once
// explore-sim's output files (written into an app::OutputSet's staging directory: all or nothing).
#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "indoormap/exploration/explore.hpp"

namespace indoormap::app {

/// What the outputs say about the run besides the result.
struct ExploreRunInfo {
  std::string map_name;
  laser::Pose2d start;
  std::string start_rule;  ///< "given" or how the start was chosen
  exploration::GoalRule rule = exploration::GoalRule::kGainPerCost;
  std::uint32_t seed = 1;
  double truth_cell_m = 0.05;
  double control_period_s = 0.1;
  std::size_t path_sample_every = 5;
  int strip_panels = 5;
};

/// explore.json: the figures and the coverage series (no timings: equal for equal inputs).
nlohmann::ordered_json explore_json(const exploration::ExploreResult& r,
                                    const ExploreRunInfo& info);

/// Writes map.pgm + map.yaml, path.geojson, explore.json, explore.png and explore_strip.png into
/// dir (which must exist). Returns the file names written.
std::vector<std::string> write_explore_files(const std::filesystem::path& dir,
                                             const exploration::ExploreResult& r,
                                             const ExploreRunInfo& info);

}  // namespace indoormap::app
