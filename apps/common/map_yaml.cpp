#include "map_yaml.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "config_reader.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::app {

namespace fs = std::filesystem;

namespace {

std::string shortest(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

double number_at(const YAML::Node& root, const char* key, const fs::path& file,
                 std::optional<double> fallback) {
  const YAML::Node n = root[key];
  if (!n) {
    if (fallback) return *fallback;
    throw InputError(file.string(), std::string("missing key '") + key + "'");
  }
  try {
    return n.as<double>();
  } catch (const YAML::Exception&) {
    throw InputError(file.string(), std::string("key '") + key + "' is not a number",
                     static_cast<std::size_t>(n.Mark().line + 1));
  }
}

}  // namespace

formats::RosMapMeta read_map_yaml(const fs::path& yaml_path) {
  const YAML::Node root = load_yaml_file(yaml_path.string(), "the map YAML");
  if (!root.IsMap()) throw InputError(yaml_path.string(), "the map YAML is not a mapping");
  formats::RosMap m;  // the keys go to m.meta
  if (!root["image"] || !root["image"].IsScalar())
    throw InputError(yaml_path.string(), "missing key 'image'");
  m.meta.image = root["image"].as<std::string>();
  // The image is read the trinary way (map_server's default); any other mode would be misread.
  if (const YAML::Node mode = root["mode"];
      mode && !(mode.IsScalar() && mode.Scalar() == "trinary"))
    throw InputError(yaml_path.string(),
                     "key 'mode': '" + (mode.IsScalar() ? mode.Scalar() : std::string("?")) +
                         "' is not supported (only 'trinary'; 'scale' and 'raw' maps are not "
                         "read)",
                     static_cast<std::size_t>(mode.Mark().line + 1));
  m.meta.resolution_m = number_at(root, "resolution", yaml_path, std::nullopt);
  if (!(m.meta.resolution_m > 0.0) || !std::isfinite(m.meta.resolution_m))
    throw InputError(yaml_path.string(), "key 'resolution' must be a positive number");
  const YAML::Node origin = root["origin"];
  if (!origin || !origin.IsSequence() || origin.size() != 3)
    throw InputError(yaml_path.string(), "key 'origin' must be a list [x, y, yaw]");
  for (int i = 0; i < 3; ++i) {
    try {
      m.meta.origin[i] = origin[i].as<double>();
    } catch (const YAML::Exception&) {
      throw InputError(yaml_path.string(), "key 'origin' must hold three numbers");
    }
  }
  if (!m.meta.origin.allFinite())
    throw InputError(yaml_path.string(), "key 'origin' is not finite");
  const double negate = number_at(root, "negate", yaml_path, 0.0);
  if (negate != 0.0 && negate != 1.0)
    throw InputError(yaml_path.string(), "key 'negate' must be 0 or 1");
  m.meta.negate = static_cast<int>(negate);
  m.meta.occupied_thresh = number_at(root, "occupied_thresh", yaml_path, 0.65);
  m.meta.free_thresh = number_at(root, "free_thresh", yaml_path, 0.196);
  if (!(m.meta.free_thresh >= 0.0 && m.meta.free_thresh <= m.meta.occupied_thresh &&
        m.meta.occupied_thresh <= 1.0))
    throw InputError(yaml_path.string(),
                     "keys 'free_thresh' <= 'occupied_thresh' must be numbers in [0, 1]");

  return m.meta;
}

formats::RosMap read_ros_map(const fs::path& yaml_path, std::int64_t max_cells) {
  const formats::RosMapMeta meta = read_map_yaml(yaml_path);
  // The grid is axis-aligned in the map frame; a rotated map would be read misplaced and its
  // outputs (safe.yaml, ...) written with yaw 0: refused instead of carried through.
  if (meta.origin[2] != 0.0)
    throw InputError(yaml_path.string(),
                     "key 'origin': yaw " + shortest(meta.origin[2]) +
                         " rad is not supported (a rotated map); only maps with origin yaw 0 "
                         "are read: rotate the image so its rows run along the map's x axis");
  return formats::decode_ros_map(meta, yaml_path, max_cells);
}

formats::RosMap load_map_argument(const std::string& path, double resolution_m, int free_min,
                                  bool free_min_given) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".yaml" || ext == ".yml") {
    if (resolution_m != 0.0)
      throw UsageError("--resolution is for plain PNG/PGM maps; " + path + " is a map YAML");
    if (free_min_given)
      throw UsageError("--free-min is for plain PNG/PGM maps; " + path +
                       " is a map YAML (its free_thresh and occupied_thresh decide)");
    return read_ros_map(path);
  }
  if (resolution_m == 0.0)
    throw UsageError("map " + path + " is an image: give its --resolution in metres per pixel");
  if (!(resolution_m > 0 && std::isfinite(resolution_m)))
    throw UsageError("--resolution " + shortest(resolution_m) +
                     ": must be a positive finite number of metres per pixel (map " + path + ")");
  return formats::read_plain_map(path, resolution_m, free_min);
}

std::vector<std::string> map_argument_files(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext != ".yaml" && ext != ".yml") return {path};
  const fs::path image = read_map_yaml(path).image;
  return {path, (image.is_absolute() ? image : fs::path(path).parent_path() / image).string()};
}

}  // namespace indoormap::app
