#include "config_reader.hpp"

#include "indoormap/core/errors.hpp"
#include "indoormap/core/input_file.hpp"

namespace indoormap::app {

namespace {

std::size_t line_of(const YAML::Node& n) {
  return n.IsDefined() && n.Mark().line >= 0 ? static_cast<std::size_t>(n.Mark().line) + 1 : 0;
}

std::string joined(const std::set<std::string>& names, const char* separator) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : separator) + n;
  return out;
}

}  // namespace

// yaml-cpp keeps both entries of a key given twice and node[key] finds the first, so the second
// would be ignored without a word: every mapping, at any depth, is checked. Aliases make the node
// tree a graph (an anchor may even contain its own alias: a cycle), so the walk is bounded in depth
// and in nodes visited; a file beyond either bound is refused (no config comes near them).
namespace {

constexpr int kMaxYamlDepth = 64;
constexpr std::size_t kMaxYamlVisits = 1'000'000;

struct KeyCheck {
  const std::string& path;
  std::size_t visits = 0;

  void walk(const YAML::Node& n, const std::string& where, int depth) {
    if (depth > kMaxYamlDepth)
      throw InputError(path,
                       "nested deeper than " + std::to_string(kMaxYamlDepth) + " levels at '" +
                           where + "' (or an alias that refers to itself)",
                       line_of(n));
    if (++visits > kMaxYamlVisits)
      throw InputError(path, "more than " + std::to_string(kMaxYamlVisits) +
                                 " nodes once its aliases are expanded");
    if (n.IsSequence()) {
      for (std::size_t i = 0; i < n.size(); ++i)
        walk(n[i], where + "[" + std::to_string(i) + "]", depth + 1);
      return;
    }
    if (!n.IsMap()) return;
    std::set<std::string> seen;
    for (const auto& kv : n) {
      if (!kv.first.IsScalar()) continue;  // refused by name where keys are read
      const std::string key = where.empty() ? kv.first.Scalar() : where + "." + kv.first.Scalar();
      if (!seen.insert(kv.first.Scalar()).second)
        throw InputError(path, "key '" + key + "' is given twice", line_of(kv.first));
      walk(kv.second, key, depth + 1);
    }
  }
};

}  // namespace

YAML::Node load_yaml_file(const std::string& path, const std::string& role) {
  const std::string bytes = read_input_file(path, kMaxTextInputBytes, role);
  try {
    YAML::Node root = YAML::Load(bytes);
    KeyCheck{path}.walk(root, "", 0);
    return root;
  } catch (const YAML::Exception& e) {
    throw InputError(path, "invalid YAML: " + e.msg,
                     e.mark.line >= 0 ? static_cast<std::size_t>(e.mark.line) + 1 : 0);
  }
}

YAML::Node load_config_tree(const std::string& path,
                            const std::map<std::string, std::set<std::string>>& known) {
  const YAML::Node root = load_yaml_file(path, "the config file");
  check_config_tree(root, path, known);
  return root;
}

void check_config_tree(const YAML::Node& root, const std::string& path,
                       const std::map<std::string, std::set<std::string>>& known) {
  if (root.IsNull()) return;  // an empty file means "all defaults"
  std::set<std::string> section_names;
  for (const auto& [name, keys] : known)
    if (!name.empty()) section_names.insert(name);
  const auto top = known.find("");
  const std::set<std::string> no_keys;
  const std::set<std::string>& top_keys = top == known.end() ? no_keys : top->second;
  if (!root.IsMap())
    throw InputError(path, section_names.empty() ? "the config must be a mapping of keys"
                                                 : "the config must be a mapping of sections");
  // A key that is not a string (a list or a mapping used as a key) is refused by name.
  auto key_of = [&](const YAML::Node& k) {
    if (!k.IsScalar())
      throw InputError(path, "keys must be names, not lists or mappings", line_of(k));
    return k.Scalar();
  };
  for (const auto& sec : root) {
    const auto name = key_of(sec.first);
    if (top_keys.count(name)) continue;  // a top-level key, read by its field's rule
    const auto it = name.empty() ? known.end() : known.find(name);
    if (it == known.end()) {
      if (section_names.empty())
        throw InputError(path,
                         "unknown key '" + name + "' (expected " + joined(top_keys, ", ") + ")",
                         line_of(sec.first));
      throw InputError(
          path, "unknown section '" + name + "' (sections: " + joined(section_names, ", ") + ")",
          line_of(sec.first));
    }
    if (sec.second.IsNull()) continue;
    if (!sec.second.IsMap())
      throw InputError(path, "section '" + name + "' must be a mapping", line_of(sec.second));
    for (const auto& kv : sec.second) {
      const auto key = key_of(kv.first);
      if (!it->second.count(key))
        throw InputError(path, "unknown key '" + name + "." + key + "'", line_of(kv.first));
    }
  }
}

void ConfigReader::fail(const YAML::Node& n, const std::string& key,
                        const std::string& problem) const {
  throw InputError(file_, "key '" + key + "': " + problem, line_of(n));
}

double ConfigReader::number(const YAML::Node& n, const std::string& key) const {
  try {
    return n.as<double>();
  } catch (const YAML::Exception&) {
    if (n.IsScalar()) fail(n, key, "expected a number, got '" + n.Scalar() + "'");
    fail(n, key, "expected a number");
  }
}

double ConfigReader::finite_number(const YAML::Node& n, const std::string& key) const {
  if (!n.IsScalar()) fail(n, key, "expected a number");
  const double v = number(n, key);
  if (!std::isfinite(v)) fail(n, key, "must be finite");
  return v;
}

bool ConfigReader::boolean(const YAML::Node& n, const std::string& key) const {
  try {
    return n.as<bool>();
  } catch (const YAML::Exception&) {
    fail(n, key, "expected true or false");
  }
}

std::string ConfigReader::text(const YAML::Node& n, const std::string& key) const {
  if (!n.IsScalar()) fail(n, key, "expected a string");
  return n.Scalar();
}

Eigen::Vector2d ConfigReader::vec2(const YAML::Node& n, const std::string& key) const {
  if (!n.IsSequence() || n.size() != 2) fail(n, key, "expected [x, y]");
  return {finite_number(n[0], key + "[0]"), finite_number(n[1], key + "[1]")};
}

Eigen::Vector3d ConfigReader::vec3(const YAML::Node& n, const std::string& key) const {
  if (!n.IsSequence() || n.size() != 3) fail(n, key, "expected [x, y, z]");
  return {finite_number(n[0], key + "[0]"), finite_number(n[1], key + "[1]"),
          finite_number(n[2], key + "[2]")};
}

void ConfigReader::only_keys(const YAML::Node& n, const std::string& key,
                             const std::vector<std::string>& allowed) const {
  if (!n.IsMap()) fail(n, key, "expected a mapping");
  for (const auto& kv : n) {
    const std::string k = kv.first.as<std::string>();
    bool ok = false;
    for (const auto& a : allowed) ok = ok || k == a;
    if (!ok) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      fail(kv.first, key.empty() ? k : key + "." + k,
           "unknown key (expected one of: " + list + ")");
    }
  }
}

}  // namespace indoormap::app
