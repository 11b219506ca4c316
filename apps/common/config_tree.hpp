#pragma once
// Reading a sectioned YAML config file (section.key: value), shared by the pipeline and the
// planner configs.
#include <yaml-cpp/yaml.h>

#include <map>
#include <set>
#include <string>

namespace indoormap::app {

/// Loads path and checks that every section and key is one of `known` (section -> keys). Returns
/// the tree (null for an empty file: all defaults). Throws InputError naming the file, the key
/// and the line on invalid YAML, a non-mapping, a non-name key, or an unknown section or key.
YAML::Node load_config_tree(const std::string& path,
                            const std::map<std::string, std::set<std::string>>& known);

}  // namespace indoormap::app
