#include "plan_config.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <type_traits>

#include "config_tree.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::app {

void merge_plan_config_file(PlanConfig& config, const std::string& path) {
  std::map<std::string, std::set<std::string>> known;
  visit_plan(config, [&](const char* s, const char* k, auto&) { known[s].insert(k); });
  const YAML::Node root = load_config_tree(path, known);
  if (root.IsNull()) return;
  visit_plan(config, [&](const char* s, const char* k, auto& v) {
    using T = std::decay_t<decltype(v)>;
    const YAML::Node sec = root[s];
    if (!sec) return;
    const YAML::Node n = sec[k];
    if (!n) return;
    const std::string full = std::string(s) + "." + k;
    auto fail = [&](const std::string& what) {
      throw InputError(path, "key '" + full + "': " + what,
                       static_cast<std::size_t>(n.Mark().line + 1));
    };
    try {
      if constexpr (std::is_same_v<T, bool>) {
        v = n.as<bool>();
      } else if constexpr (std::is_integral_v<T>) {
        const auto k = config_integer<T>(n);  // NaN used to reach a double-to-integer cast (UB)
        if (!k) fail("expected an integer in range");
        v = *k;
      } else {
        v = n.as<T>();
      }
    } catch (const YAML::Exception&) {
      fail(std::is_same_v<T, bool> ? "expected true or false" : "expected a number");
    }
  });
}

void validate(const PlanConfig& c) {
  planning::validate(c.robot, c.planner);
}

std::string to_yaml(const PlanConfig& config) {
  YAML::Emitter out;
  out.SetDoublePrecision(15);  // 0.2, not 0.20000000000000001; still reads back as the same value
  out << YAML::BeginMap;
  std::string open;
  visit_plan(config, [&](const char* s, const char* k, const auto& v) {
    if (open != s) {
      if (!open.empty()) out << YAML::EndMap;
      out << YAML::Key << s << YAML::Value << YAML::BeginMap;
      open = s;
    }
    out << YAML::Key << k << YAML::Value << v;
  });
  out << YAML::EndMap << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

nlohmann::json to_json(const PlanConfig& config) {
  nlohmann::json j = nlohmann::json::object();
  visit_plan(config, [&](const char* s, const char* k, const auto& v) { j[s][k] = v; });
  return j;
}

}  // namespace indoormap::app
