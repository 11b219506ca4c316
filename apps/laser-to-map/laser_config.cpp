#include "laser_config.hpp"

#include "config_reader.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::app {

template <>
struct ConfigValue<laser::MapperKind> {
  static void read(const ConfigReader& rd, const YAML::Node& n, const std::string& key,
                   laser::MapperKind& v) {
    const auto s = rd.text(n, key);
    if (s == "himm")
      v = laser::MapperKind::kHimm;
    else if (s == "logodds" || s == "log_odds")
      v = laser::MapperKind::kLogOdds;
    else
      rd.fail(n, key, "expected 'himm' or 'logodds', got '" + s + "'");
  }
  static std::string name(laser::MapperKind v) {
    return v == laser::MapperKind::kHimm ? "himm" : "logodds";
  }
  static void emit(YAML::Emitter& out, laser::MapperKind v) { out << name(v); }
  static nlohmann::json json(laser::MapperKind v) { return name(v); }
};

void merge_laser_map_config_file(LaserMapConfig& config, const std::string& path) {
  read_config_file(path, [&](auto&& f) { visit_laser_map(config, f); });
}

void validate(const LaserMapConfig& c) {
  c.grid.validate();
  c.himm.validate();
  c.log_odds.validate();
  c.pose_refine.validate();
  c.log.validate();
  laser::ConsistencyParams check = c.consistency;
  check.max_range_m = c.grid.max_range_m;
  check.validate();
  if (c.progress_every_scans < 0)
    throw UsageError("log.progress_every_scans must be >= 0 (0: no progress lines)");
}

laser::MapperKind parse_method(const std::string& name) {
  if (name == "himm") return laser::MapperKind::kHimm;
  if (name == "logodds" || name == "log_odds") return laser::MapperKind::kLogOdds;
  throw UsageError("--method must be 'himm' or 'logodds', got '" + name + "'");
}

std::string to_yaml(const LaserMapConfig& config) {
  LaserMapConfig c = config;
  return config_to_yaml([&](auto&& f) { visit_laser_map(c, f); });
}

nlohmann::json to_json(const LaserMapConfig& config) {
  LaserMapConfig c = config;
  return config_to_json([&](auto&& f) { visit_laser_map(c, f); });
}

}  // namespace indoormap::app
