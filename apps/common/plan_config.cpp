#include "plan_config.hpp"

#include "config_reader.hpp"

namespace indoormap::app {

void merge_plan_config_file(PlanConfig& config, const std::string& path) {
  read_config_file(path, [&](auto&& f) { visit_plan(config, f); });
}

void validate(const PlanConfig& c) {
  planning::validate(c.robot, c.planner);
}

std::string to_yaml(const PlanConfig& config) {
  PlanConfig c = config;
  return config_to_yaml([&](auto&& f) { visit_plan(c, f); });
}

nlohmann::json to_json(const PlanConfig& config) {
  PlanConfig c = config;
  return config_to_json([&](auto&& f) { visit_plan(c, f); });
}

}  // namespace indoormap::app
