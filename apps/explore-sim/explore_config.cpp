#include "explore_config.hpp"

#include <numbers>

#include "config_reader.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::app {

template <>
struct ConfigValue<exploration::GoalRule> {
  static void read(const ConfigReader& rd, const YAML::Node& n, const std::string& key,
                   exploration::GoalRule& v) {
    const auto s = rd.text(n, key);
    if (s == "gain_per_cost")
      v = exploration::GoalRule::kGainPerCost;
    else if (s == "nearest_frontier")
      v = exploration::GoalRule::kNearestFrontier;
    else
      rd.fail(n, key, "expected 'gain_per_cost' or 'nearest_frontier', got '" + s + "'");
  }
  static void emit(YAML::Emitter& out, exploration::GoalRule v) {
    out << std::string(exploration::to_string(v));
  }
  static nlohmann::json json(exploration::GoalRule v) {
    return std::string(exploration::to_string(v));
  }
};

template <>
struct ConfigValue<laser::MapperKind> {
  static void read(const ConfigReader& rd, const YAML::Node& n, const std::string& key,
                   laser::MapperKind& v) {
    const auto s = rd.text(n, key);
    if (s == "himm")
      v = laser::MapperKind::kHimm;
    else if (s == "log_odds")
      v = laser::MapperKind::kLogOdds;
    else
      rd.fail(n, key, "expected 'himm' or 'log_odds', got '" + s + "'");
  }
  static void emit(YAML::Emitter& out, laser::MapperKind v) {
    out << std::string(laser::to_string(v));
  }
  static nlohmann::json json(laser::MapperKind v) { return std::string(laser::to_string(v)); }
};

void merge_explore_config_file(ExploreSimConfig& config, const std::string& path) {
  read_config_file(path, [&](auto&& f) { visit_explore(config, f); });
}

void resolve(ExploreSimConfig& c) {
  if (!(c.laser_fov_deg > 0.0 && c.laser_fov_deg <= 360.0))
    throw UsageError("laser.fov_deg must be in (0, 360]");
  if (c.strip_panels < 1 || c.strip_panels > 12)
    throw UsageError("output.strip_panels must be 1 .. 12");
  c.explore.laser.fov_rad = c.laser_fov_deg * std::numbers::pi / 180.0;
  c.explore.validate();
}

std::string to_yaml(const ExploreSimConfig& config) {
  ExploreSimConfig c = config;
  return config_to_yaml([&](auto&& f) { visit_explore(c, f); });
}

nlohmann::json to_json(const ExploreSimConfig& config) {
  ExploreSimConfig c = config;
  return config_to_json([&](auto&& f) { visit_explore(c, f); });
}

}  // namespace indoormap::app
