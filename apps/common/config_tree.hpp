#pragma once
// Reading a sectioned YAML config file (section.key: value), shared by the pipeline and the
// planner configs.
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace indoormap::app {

/// Loads path and checks that every section and key is one of `known` (section -> keys). Returns
/// the tree (null for an empty file: all defaults). Throws InputError naming the file, the key
/// and the line on invalid YAML, a non-mapping, a non-name key, or an unknown section or key.
YAML::Node load_config_tree(const std::string& path,
                            const std::map<std::string, std::set<std::string>>& known);

/// The value of an integer key: nullopt unless n holds a whole number within T's range (NaN and
/// Inf fail the range check, which comes first, so the conversion is always defined). Throws
/// YAML::Exception when n is not a number at all.
template <class T>
std::optional<T> config_integer(const YAML::Node& n) {
  const auto d = n.as<long double>();
  if (!(d >= static_cast<long double>(std::numeric_limits<T>::min()) &&
        d <= static_cast<long double>(std::numeric_limits<T>::max())) ||
      d != std::floor(d))
    return std::nullopt;
  return static_cast<T>(d);
}

}  // namespace indoormap::app
