#include "config.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <type_traits>

#include "config_tree.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::app {

namespace {

// Calls f(section, key, field) for every configurable field, in documentation order. One list
// serves reading, printing and validation, so they cannot drift apart.
template <class F>
void visit(PipelineConfig& c, F&& f) {
  f("input", "unit_m", c.load.unit_m);
  f("input", "up_axis", c.load.up_axis);
  f("input", "max_points", c.load.max_points);
  f("input", "scanners", c.scanners);
  auto& lv = c.map.level;
  f("level", "enabled", lv.enabled);
  f("level", "max_tilt_deg", lv.max_tilt_deg);
  f("level", "band_m", lv.band_m);
  f("level", "peak_fraction", lv.peak_fraction);
  f("level", "inlier_m", lv.inlier_m);
  f("level", "iterations", lv.iterations);
  f("level", "sample_points", lv.sample_points);
  f("level", "min_inliers", lv.min_inliers);
  f("level", "min_fill", lv.min_fill);
  f("level", "max_normal_disagreement_deg", lv.max_normal_disagreement_deg);
  f("level", "seed", lv.seed);
  auto& vx = c.map.voxel;
  f("voxel", "cell_m", vx.cell_m);
  f("voxel", "max_cells", vx.max_cells);
  f("voxel", "bounds_gap_m", vx.bounds_gap_m);
  f("voxel", "bounds_sample", vx.bounds_sample);
  auto& gh = c.map.ghosts;
  f("ghosts", "enabled", gh.enabled);
  f("ghosts", "max_points", gh.max_points);
  f("ghosts", "min_pass_ratio", gh.min_pass_ratio);
  f("ghosts", "min_passes", gh.min_passes);
  f("ghosts", "min_layer_offset", gh.min_layer_offset);
  f("ghosts", "end_skip_m", gh.end_skip_m);
  f("ghosts", "max_rays", gh.max_rays);
  auto& ly = c.map.layers;
  f("layers", "min_points_per_voxel", ly.min_points_per_voxel);
  f("layers", "isolated_min_points", ly.isolated_min_points);
  f("layers", "floor_min_fraction", ly.floor_min_fraction);
  f("layers", "ceiling_min_fraction", ly.ceiling_min_fraction);
  f("layers", "min_room_height_m", ly.min_room_height_m);
  f("layers", "ceiling_onset_factor", ly.ceiling_onset_factor);
  f("layers", "floor_clearance_m", ly.floor_clearance_m);
  f("layers", "ceiling_clearance_m", ly.ceiling_clearance_m);
  f("layers", "wall_band_m", ly.wall_band_m);
  f("layers", "wall_min_extent_m", ly.wall_min_extent_m);
  f("layers", "furniture_max_height_m", ly.furniture_max_height_m);
  f("layers", "floor_z_m", ly.floor_z_m);
  f("layers", "ceiling_z_m", ly.ceiling_z_m);
  f("layers", "wall_band_lo_m", ly.wall_band_lo_m);
  f("layers", "wall_band_hi_m", ly.wall_band_hi_m);
  f("layers", "furniture_band_lo_m", ly.furniture_band_lo_m);
  f("layers", "furniture_band_hi_m", ly.furniture_band_hi_m);
  auto& lo = c.map.layout;
  f("layout", "furniture_closing_iterations", lo.furniture_closing_iterations);
  f("layout", "flood_barrier_closing", lo.flood_barrier_closing);
  f("layout", "enclosed_max_area_m2", lo.enclosed_max_area_m2);
  f("layout", "passage_min_lines", lo.passage_min_lines);
  f("layout", "seed_search_radius_m", lo.seed_search_radius_m);
  f("layout", "hanging_max_area_m2", lo.hanging_max_area_m2);
  f("layout", "hanging_max_extent_m", lo.hanging_max_extent_m);
  f("layout", "hanging_gap_m", lo.hanging_gap_m);
  auto& ob = c.objects;
  f("objects", "min_area_m2", ob.min_area_m2);
  f("objects", "connectivity", ob.connectivity);
  f("objects", "crop_margin_m", ob.crop_margin_m);
  f("objects", "split_height_step_m", ob.split_height_step_m);
  f("objects", "max_vertical_gap_m", ob.max_vertical_gap_m);
  f("objects", "hanging_min_clearance_m", ob.hanging_min_clearance_m);
  f("objects", "pillar_max_extent_m", ob.pillar_max_extent_m);
  f("objects", "lamp_max_extent_m", ob.lamp_max_extent_m);
  f("objects", "top_percentile", ob.top_percentile);
  auto& bd = c.border;
  f("border", "dilate_full_size", bd.dilate_full_size);
  f("border", "dilate_cross_size", bd.dilate_cross_size);
  f("border", "erode_full_size", bd.erode_full_size);
  f("border", "erode_iterations", bd.erode_iterations);
  f("border", "simplify_tolerance_m", bd.simplify_tolerance_m);
  f("border", "face_snap_max_m", bd.face_snap_max_m);
  f("border", "shadow_max_m", bd.shadow_max_m);
  f("border", "opening_search_m", bd.opening_search_m);
  f("border", "opening_min_m", bd.opening_min_m);
  f("border", "door_min_m", bd.door_min_m);
  f("border", "door_max_m", bd.door_max_m);
  f("border", "door_clear_height_m", bd.door_clear_height_m);
  f("border", "door_probe_m", bd.door_probe_m);
  f("border", "max_open_fraction", bd.max_open_fraction);
  f("border", "max_cells", bd.max_cells);
  f("border", "face_out_reach_m", bd.face_out_reach_m);
  f("border", "face_in_margin_m", bd.face_in_margin_m);
  f("border", "face_tol_m", bd.face_tol_m);
  f("border", "face_max_turn_deg", bd.face_max_turn_deg);
  f("border", "same_face_max_deg", bd.same_face_max_deg);
  f("border", "parallel_max_deg", bd.parallel_max_deg);
  f("border", "chamfer_margin_m", bd.chamfer_margin_m);
  f("border", "recess_margin_m", bd.recess_margin_m);
  f("border", "shadow_min_unknown_share", bd.shadow_min_unknown_share);
  f("border", "shadow_chain_tol_m", bd.shadow_chain_tol_m);
  f("border", "corner_shadow_min_turn_deg", bd.corner_shadow_min_turn_deg);
  f("border", "corner_shadow_max_turn_deg", bd.corner_shadow_max_turn_deg);
  visit_plan(c.plan, f);
}

std::string axis_name(cloud_io::UpAxis a) {
  return a == cloud_io::UpAxis::kY ? "y" : "z";
}

struct Reader {
  const YAML::Node& root;
  const std::string& file;

  [[noreturn]] void fail(const std::string& key, const YAML::Node& n,
                         const std::string& what) const {
    throw InputError(file, "key '" + key + "': " + what,
                     static_cast<std::size_t>(n.Mark().line + 1));
  }

  template <class T>
  void operator()(const char* section, const char* key, T& v) const {
    const YAML::Node sec = root[section];
    if (!sec) return;
    const YAML::Node n = sec[key];
    if (!n) return;
    const std::string full = std::string(section) + "." + key;
    try {
      if constexpr (std::is_same_v<T, objects::Connectivity>) {
        const auto k = n.as<int>();
        if (k != 4 && k != 8) fail(full, n, "expected 4 or 8");
        v = k == 4 ? objects::Connectivity::k4 : objects::Connectivity::k8;
      } else if constexpr (std::is_same_v<T, cloud_io::UpAxis>) {
        const auto s = n.as<std::string>();
        if (s == "z")
          v = cloud_io::UpAxis::kZ;
        else if (s == "y")
          v = cloud_io::UpAxis::kY;
        else
          fail(full, n, "expected 'z' or 'y', got '" + s + "'");
      } else if constexpr (std::is_same_v<T, std::optional<double>>) {
        if (n.IsNull())
          v.reset();
        else
          v = n.as<double>();
      } else if constexpr (std::is_same_v<T, std::vector<Eigen::Vector3d>>) {
        if (!n.IsSequence()) fail(full, n, "expected a list of [x, y, z]");
        v.clear();
        for (const auto& e : n) {
          if (!e.IsSequence() || e.size() != 3) fail(full, e, "each scanner is [x, y, z]");
          v.emplace_back(e[0].as<double>(), e[1].as<double>(), e[2].as<double>());
        }
      } else if constexpr (std::is_same_v<T, bool>) {
        v = n.as<bool>();
      } else if constexpr (std::is_integral_v<T>) {
        const auto k = config_integer<T>(n);
        if (!k) fail(full, n, "expected an integer in range");
        v = *k;
      } else {
        v = n.as<T>();
      }
    } catch (const YAML::Exception&) {
      fail(full, n, std::is_same_v<T, bool> ? "expected true or false" : "expected a number");
    }
  }
};

}  // namespace

YAML::Node load_config_tree(const std::string& path,
                            const std::map<std::string, std::set<std::string>>& known) {
  YAML::Node root;
  try {
    std::ifstream in(path);
    if (!in) throw InputError(path, "cannot open the config file");
    root = YAML::Load(in);
  } catch (const YAML::Exception& e) {
    throw InputError(path, "invalid YAML: " + e.msg, static_cast<std::size_t>(e.mark.line + 1));
  }
  if (root.IsNull()) return root;  // an empty file means "all defaults"
  if (!root.IsMap()) throw InputError(path, "the config must be a mapping of sections");
  std::string sections;
  for (const auto& [name, keys] : known) sections += (sections.empty() ? "" : ", ") + name;
  // A key that is not a string (a list or a mapping used as a key) is refused by name.
  auto key_of = [&](const YAML::Node& k) {
    if (!k.IsScalar())
      throw InputError(path, "keys must be names, not lists or mappings",
                       static_cast<std::size_t>(k.Mark().line + 1));
    return k.Scalar();
  };
  for (const auto& sec : root) {
    const auto name = key_of(sec.first);
    const auto it = known.find(name);
    if (it == known.end())
      throw InputError(path, "unknown section '" + name + "' (sections: " + sections + ")",
                       static_cast<std::size_t>(sec.first.Mark().line + 1));
    if (sec.second.IsNull()) continue;
    if (!sec.second.IsMap())
      throw InputError(path, "section '" + name + "' must be a mapping",
                       static_cast<std::size_t>(sec.second.Mark().line + 1));
    for (const auto& kv : sec.second) {
      const auto key = key_of(kv.first);
      if (!it->second.count(key))
        throw InputError(path, "unknown key '" + name + "." + key + "'",
                         static_cast<std::size_t>(kv.first.Mark().line + 1));
    }
  }
  return root;
}

void merge_config_file(PipelineConfig& config, const std::string& path) {
  std::map<std::string, std::set<std::string>> known;
  visit(config, [&](const char* s, const char* k, auto&) { known[s].insert(k); });
  const YAML::Node root = load_config_tree(path, known);
  if (root.IsNull()) return;
  visit(config, Reader{root, path});
}

void validate(const PipelineConfig& c) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw UsageError("invalid parameter " + what);
  };
  cloud_io::validate(c.load);  // throws UsageError naming input.<key>
  for (const auto& s : c.scanners) require(s.allFinite(), "input.scanners: must be finite");
  cloud::validate(c.map.level);  // level.<key>, voxel.<key>, ghosts.<key>, layers.<key>
  cloud::validate(c.map.voxel);
  cloud::validate(c.map.ghosts);
  cloud::validate(c.map.layers);
  const auto& lo = c.map.layout;
  require(lo.furniture_closing_iterations >= 0 && lo.furniture_closing_iterations <= 20,
          "layout.furniture_closing_iterations: must be in [0, 20]");
  require(lo.flood_barrier_closing >= 0 && lo.flood_barrier_closing <= 10,
          "layout.flood_barrier_closing: must be in [0, 10]");
  require(lo.enclosed_max_area_m2 >= 0, "layout.enclosed_max_area_m2: must be >= 0");
  require(lo.passage_min_lines >= 0 && lo.passage_min_lines <= 4,
          "layout.passage_min_lines: must be in [0, 4] (0: the paper's row and column passes)");
  require(lo.seed_search_radius_m >= 0, "layout.seed_search_radius_m: must be >= 0");
  require(lo.hanging_max_area_m2 >= 0, "layout.hanging_max_area_m2: must be >= 0");
  require(lo.hanging_gap_m > 0, "layout.hanging_gap_m: must be > 0");
  require(lo.hanging_max_extent_m >= 0, "layout.hanging_max_extent_m: must be >= 0");
  const auto& ob = c.objects;
  require(ob.min_area_m2 >= 0, "objects.min_area_m2: must be >= 0");
  require(ob.crop_margin_m >= 0 && ob.crop_margin_m <= 10,
          "objects.crop_margin_m: must be in [0, 10]");
  require(ob.split_height_step_m >= 0, "objects.split_height_step_m: must be >= 0 (0: off)");
  require(ob.hanging_min_clearance_m > 0, "objects.hanging_min_clearance_m: must be > 0");
  require(ob.pillar_max_extent_m >= 0, "objects.pillar_max_extent_m: must be >= 0");
  require(ob.lamp_max_extent_m >= 0, "objects.lamp_max_extent_m: must be >= 0");
  require(ob.max_vertical_gap_m > 0, "objects.max_vertical_gap_m: must be > 0");
  require(ob.top_percentile >= 0 && ob.top_percentile <= 100,
          "objects.top_percentile: must be in [0, 100]");
  border::validate(c.border);  // throws UsageError naming border.<key>
  validate(c.plan);
}

std::string to_yaml(const PipelineConfig& config) {
  PipelineConfig c = config;
  YAML::Emitter out;
  out.SetDoublePrecision(15);  // 0.2, not 0.20000000000000001; still reads back as the same value
  out << YAML::BeginMap;
  std::string open;
  visit(c, [&](const char* s, const char* k, auto& v) {
    using T = std::decay_t<decltype(v)>;
    if (open != s) {
      if (!open.empty()) out << YAML::EndMap;
      out << YAML::Key << s << YAML::Value << YAML::BeginMap;
      open = s;
    }
    out << YAML::Key << k << YAML::Value;
    if constexpr (std::is_same_v<T, objects::Connectivity>) {
      out << static_cast<int>(v);
    } else if constexpr (std::is_same_v<T, cloud_io::UpAxis>) {
      out << axis_name(v);
    } else if constexpr (std::is_same_v<T, std::optional<double>>) {
      if (v)
        out << *v;
      else
        out << YAML::Null;
    } else if constexpr (std::is_same_v<T, std::vector<Eigen::Vector3d>>) {
      out << YAML::Flow << YAML::BeginSeq;
      for (const auto& p : v)
        out << YAML::Flow << YAML::BeginSeq << p.x() << p.y() << p.z() << YAML::EndSeq;
      out << YAML::EndSeq;
    } else {
      out << v;
    }
  });
  out << YAML::EndMap << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

nlohmann::json to_json(const PipelineConfig& config) {
  PipelineConfig c = config;
  nlohmann::json j = nlohmann::json::object();
  visit(c, [&](const char* s, const char* k, auto& v) {
    using T = std::decay_t<decltype(v)>;
    auto& slot = j[s][k];
    if constexpr (std::is_same_v<T, objects::Connectivity>) {
      slot = static_cast<int>(v);
    } else if constexpr (std::is_same_v<T, cloud_io::UpAxis>) {
      slot = axis_name(v);
    } else if constexpr (std::is_same_v<T, std::optional<double>>) {
      slot = v ? nlohmann::json(*v) : nlohmann::json(nullptr);
    } else if constexpr (std::is_same_v<T, std::vector<Eigen::Vector3d>>) {
      slot = nlohmann::json::array();
      for (const auto& p : v) slot.push_back({p.x(), p.y(), p.z()});
    } else {
      slot = v;
    }
  });
  return j;
}

}  // namespace indoormap::app
