#pragma once
// The one YAML config reader of every app (yaml-cpp lives only in apps/).
//
// - ConfigReader holds the scalar, integer and list rules and the one error style
//   "FILE:LINE: key 'K': problem" (InputError). Table configs use it through ConfigValue; the
//   scene-sim scene file (data, not config) uses it directly from its structure reader.
// - A table is a callable that calls f(section, key, field) for every configurable field, in
//   documentation order (see visit() in config.cpp, visit_plan() in plan_config.hpp). One table
//   serves reading (read_config_file), printing (config_to_yaml, --print-config) and
//   summary.json (config_to_json), so they cannot drift apart. Section "" holds top-level keys
//   (a flat config such as map-eval's).
// - ConfigValue<T> says how one field type is read, printed and written to JSON. bool, integers,
//   floating point, std::optional<double> and Finite<double> are here; an app specialises it for
//   its own types (enums, lists) before it instantiates the table functions.
#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

namespace indoormap::app {

/// The value of an integer node: nullopt unless n holds a whole number within T's range (NaN and
/// Inf fail the range check, which comes first, so the conversion is always defined). Throws
/// YAML::Exception when n is not a number at all. The one integer rule of every YAML reader.
template <class T>
std::optional<T> config_integer(const YAML::Node& n) {
  const auto d = n.as<long double>();
  if (!(d >= static_cast<long double>(std::numeric_limits<T>::min()) &&
        d <= static_cast<long double>(std::numeric_limits<T>::max())) ||
      d != std::floor(d))
    return std::nullopt;
  return static_cast<T>(d);
}

/// Loads a YAML file through indoormap::read_input_file (a missing file, a directory, a FIFO or a
/// file above kMaxTextInputBytes is refused naming the file and role, e.g. "the config file").
/// Throws InputError(path, "invalid YAML: ...", line) on a syntax error and
/// InputError(path, "key 'K' is given twice", line) when a mapping repeats a key.
YAML::Node load_yaml_file(const std::string& path, const std::string& role = "the YAML file");

/// Loads path and checks that every section and key is one of `known` (section -> keys; section
/// "" lists top-level keys). Returns the tree (null for an empty file: all defaults). Throws
/// InputError naming the file, the key and the line on invalid YAML, a non-mapping, a non-name
/// key, or an unknown section or key.
YAML::Node load_config_tree(const std::string& path,
                            const std::map<std::string, std::set<std::string>>& known);

/// load_config_tree's checks on a tree built in memory (the Python bindings' params dict): `name`
/// stands for the file in the errors ("params: unknown key 'voxel.cel_m'"). A null root passes.
void check_config_tree(const YAML::Node& root, const std::string& name,
                       const std::map<std::string, std::set<std::string>>& known);

/// Typed values out of one YAML document. Every error is InputError(file, "key 'K': problem",
/// line of the node).
class ConfigReader {
 public:
  explicit ConfigReader(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  [[noreturn]] void fail(const YAML::Node& n, const std::string& key,
                         const std::string& problem) const;
  /// Any number (NaN and Inf included: ranges are validate()'s job).
  double number(const YAML::Node& n, const std::string& key) const;
  /// A finite number.
  double finite_number(const YAML::Node& n, const std::string& key) const;
  bool boolean(const YAML::Node& n, const std::string& key) const;
  std::string text(const YAML::Node& n, const std::string& key) const;
  /// A whole number within T's range (config_integer).
  template <class T>
  T integer(const YAML::Node& n, const std::string& key) const {
    std::optional<T> k;
    try {
      k = config_integer<T>(n);
    } catch (const YAML::Exception&) {
      fail(n, key, "expected a number");
    }
    if (!k) fail(n, key, "expected an integer in range");
    return *k;
  }
  /// [x, y] and [x, y, z] of finite numbers (elements named key[0], key[1], ...).
  Eigen::Vector2d vec2(const YAML::Node& n, const std::string& key) const;
  Eigen::Vector3d vec3(const YAML::Node& n, const std::string& key) const;
  /// Every key of mapping n must be in allowed (catches typos such as "heigth_m"); key is the
  /// path of n ("" for the root).
  void only_keys(const YAML::Node& n, const std::string& key,
                 const std::vector<std::string>& allowed) const;

 private:
  std::string file_;
};

/// A double field that must be finite (the rule of scene-sim's and map-eval's keys).
struct Finite {
  double& value;
};
inline Finite finite(double& v) {
  return {v};
}

/// How a field type is read, printed as YAML and written to JSON.
template <class T>
struct ConfigValue {
  static void read(const ConfigReader& rd, const YAML::Node& n, const std::string& key, T& v) {
    if constexpr (std::is_same_v<T, bool>) {
      v = rd.boolean(n, key);
    } else if constexpr (std::is_integral_v<T>) {
      v = rd.integer<T>(n, key);
    } else {
      static_assert(std::is_floating_point_v<T>, "specialise ConfigValue for this field type");
      v = static_cast<T>(rd.number(n, key));
    }
  }
  static void emit(YAML::Emitter& out, const T& v) { out << v; }
  static nlohmann::json json(const T& v) { return v; }
};

template <>
struct ConfigValue<Finite> {
  static void read(const ConfigReader& rd, const YAML::Node& n, const std::string& key, Finite v) {
    v.value = rd.finite_number(n, key);
  }
  static void emit(YAML::Emitter& out, const Finite& v) { out << v.value; }
  static nlohmann::json json(const Finite& v) { return v.value; }
};

/// null: no value (the default, e.g. "estimate from the data").
template <>
struct ConfigValue<std::optional<double>> {
  static void read(const ConfigReader& rd, const YAML::Node& n, const std::string& key,
                   std::optional<double>& v) {
    if (n.IsNull())
      v.reset();
    else
      v = rd.number(n, key);
  }
  static void emit(YAML::Emitter& out, const std::optional<double>& v) {
    if (v)
      out << *v;
    else
      out << YAML::Null;
  }
  static nlohmann::json json(const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  }
};

template <class Field>
using ConfigValueOf = ConfigValue<std::remove_cvref_t<Field>>;

/// Section -> keys of a table (what load_config_tree accepts).
template <class Table>
std::map<std::string, std::set<std::string>> config_keys(Table&& table) {
  std::map<std::string, std::set<std::string>> known;
  table([&](const char* s, const char* k, auto&&) { known[s].insert(k); });
  return known;
}

/// Reads an already checked tree (load_config_tree, check_config_tree) over the table's fields;
/// errors name `name` as their file.
template <class Table>
void read_config_tree(const YAML::Node& root, const std::string& name, Table&& table) {
  if (root.IsNull()) return;
  const ConfigReader rd(name);
  table([&](const char* s, const char* k, auto&& v) {
    const YAML::Node sec = *s ? root[s] : root;
    if (!sec) return;
    const YAML::Node n = sec[k];
    if (!n) return;
    ConfigValueOf<decltype(v)>::read(rd, n, *s ? std::string(s) + "." + k : std::string(k), v);
  });
}

/// Reads a YAML config file over the table's fields (fields not in the file keep their values).
/// Throws InputError naming the file, key and line.
template <class Table>
void read_config_file(const std::string& path, Table&& table) {
  read_config_tree(load_config_tree(path, config_keys(table)), path, table);
}

/// The table as YAML (what --print-config prints), readable by read_config_file.
template <class Table>
std::string config_to_yaml(Table&& table) {
  YAML::Emitter out;
  out.SetDoublePrecision(15);  // 0.2, not 0.20000000000000001; still reads back as the same value
  out << YAML::BeginMap;
  std::string open;
  table([&](const char* s, const char* k, auto&& v) {
    if (open != s) {
      if (!open.empty()) out << YAML::EndMap;
      if (*s) out << YAML::Key << s << YAML::Value << YAML::BeginMap;
      open = s;
    }
    out << YAML::Key << k << YAML::Value;
    ConfigValueOf<decltype(v)>::emit(out, v);
  });
  if (!open.empty()) out << YAML::EndMap;
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

/// The table as JSON (summary.json's parameters).
template <class Table>
nlohmann::json config_to_json(Table&& table) {
  nlohmann::json j = nlohmann::json::object();
  table([&](const char* s, const char* k, auto&& v) {
    auto& slot = *s ? j[s][k] : j[k];
    slot = ConfigValueOf<decltype(v)>::json(v);
  });
  return j;
}

}  // namespace indoormap::app
