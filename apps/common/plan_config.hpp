#pragma once
// YAML configuration of the route planner: sections robot.*, safe_zone.*, planner.*, mirroring
// planning::RobotParams, SafeZoneParams and PlannerParams. plan-route reads it on its own
// (config/plan-route.yaml); the pipeline apps embed the same sections (config/default.yaml).
#include <nlohmann/json.hpp>
#include <string>

#include "config_reader.hpp"
#include "indoormap/planning/planner.hpp"

namespace indoormap::app {

/// planner.search: "min_link", "exact" or "paper".
template <>
struct ConfigValue<planning::RouteSearch> {
  static void read(const ConfigReader& rd, const YAML::Node& n, const std::string& key,
                   planning::RouteSearch& v) {
    const auto s = rd.text(n, key);
    const auto kind = planning::route_search_from(s);
    if (!kind) rd.fail(n, key, "expected 'min_link', 'exact' or 'paper', got '" + s + "'");
    v = *kind;
  }
  static void emit(YAML::Emitter& out, planning::RouteSearch v) {
    out << std::string(planning::to_string(v));
  }
  static nlohmann::json json(planning::RouteSearch v) {
    return std::string(planning::to_string(v));
  }
};

struct PlanConfig {
  planning::RobotParams robot;
  planning::SafeZoneParams safe_zone;
  planning::PlannerParams planner;
};

/// Calls f(section, key, field) for every configurable field, in documentation order.
template <class C, class F>
void visit_plan(C& c, F&& f) {
  f("robot", "width_m", c.robot.width_m);
  f("robot", "length_m", c.robot.length_m);
  f("robot", "extra_m", c.robot.extra_m);
  f("safe_zone", "unknown_is_obstacle", c.safe_zone.unknown_is_obstacle);
  f("planner", "d_min_m", c.planner.d_min_m);
  f("planner", "d_max_m", c.planner.d_max_m);
  f("planner", "paper_rules", c.planner.paper_rules);
  f("planner", "search", c.planner.search);
  f("planner", "max_routes", c.planner.max_routes);
  f("planner", "extra_moves", c.planner.extra_moves);
  f("planner", "max_nodes", c.planner.max_nodes);
  f("planner", "max_seconds", c.planner.max_seconds);
}

/// Reads a YAML file with only robot / safe_zone / planner sections over config. Unknown
/// sections and keys are errors. Throws InputError naming the file, key and line.
void merge_plan_config_file(PlanConfig& config, const std::string& path);
/// Throws UsageError naming the key.
void validate(const PlanConfig& config);
std::string to_yaml(const PlanConfig& config);
nlohmann::json to_json(const PlanConfig& config);

}  // namespace indoormap::app
