#pragma once
// The YAML configuration of the pipeline apps. The tree mirrors the parameter structs:
// input.*, level.*, voxel.*, layers.*, layout.*, objects.*, border.*, robot.*, safe_zone.*,
// planner.*; defaults are the structs' defaults and are
// documented in config/default.yaml. Unknown keys are errors (a typo must not be ignored).
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "indoormap/border/border.hpp"
#include "indoormap/cloud_io/load.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "indoormap/layout/storeys.hpp"
#include "indoormap/objects/objects.hpp"
#include "plan_config.hpp"

namespace YAML {
class Node;
}

namespace indoormap::app {

struct PipelineConfig {
  cloud_io::LoadOptions load;
  /// Scanner positions (input frame after unit / axis conversion, metres). When set they replace
  /// the positions found in the files.
  std::vector<Eigen::Vector3d> scanners;
  layout::MapParams map;
  layout::StoreyParams storeys;  ///< storeys.*
  objects::ObjectParams objects;
  border::BorderParams border;  ///< room border closure (border.*)
  PlanConfig plan;              ///< robot.*, safe_zone.*, planner.*: the route of --start / --goal
};

/// Reads a YAML file over the defaults. Throws InputError naming the file, key and line.
void merge_config_file(PipelineConfig& config, const std::string& path);
/// The same from a tree built in memory (the Python bindings' params dict), checked by the same
/// rules (unknown sections and keys refused); `name` stands for the file in the errors.
void merge_config_tree(PipelineConfig& config, const YAML::Node& root, const std::string& name);
/// Checks ranges (cell_m > 0, ...). Throws UsageError naming the key.
void validate(const PipelineConfig& config);
/// The effective configuration as YAML (what --print-config prints) and as JSON (summary.json).
std::string to_yaml(const PipelineConfig& config);
nlohmann::json to_json(const PipelineConfig& config);

}  // namespace indoormap::app
