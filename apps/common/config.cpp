#include "config.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <optional>

#include "config_reader.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::app {

namespace {

// The level.<key> fields, in documentation order (part of visit).
template <class F>
void visit_level(cloud::LevelParams& lv, F& f) {
  f("level", "enabled", lv.enabled);
  f("level", "max_tilt_deg", lv.max_tilt_deg);
  f("level", "min_support_area_m2", lv.min_support_area_m2);
  f("level", "min_support_surround", lv.min_support_surround);
  f("level", "warn_horizon_share", lv.warn_horizon_share);
  f("level", "warn_floor_share", lv.warn_floor_share);
  f("level", "band_m", lv.band_m);
  f("level", "peak_fraction", lv.peak_fraction);
  f("level", "inlier_m", lv.inlier_m);
  f("level", "iterations", lv.iterations);
  f("level", "sample_points", lv.sample_points);
  f("level", "min_inliers", lv.min_inliers);
  f("level", "min_fill", lv.min_fill);
  f("level", "max_normal_disagreement_deg", lv.max_normal_disagreement_deg);
  f("level", "seed", lv.seed);
}

// The navigation map's fields; its robot keys open the robot section.
template <class F>
void visit_nav(layout::NavParams& nv, F&& f) {
  f("nav", "min_points", nv.min_points);
  f("nav", "min_column_m", nv.min_column_m);
  f("nav", "min_neighbours", nv.min_neighbours);
  f("nav", "floor_tolerance_m", nv.floor_tolerance_m);
  f("nav", "floor_closing_cells", nv.floor_closing_cells);
  f("nav", "floor_hole_max_m2", nv.floor_hole_max_m2);
  f("nav", "floor_hole_min_free_share", nv.floor_hole_min_free_share);
  f("nav", "floor_hole_min_free_share_no_rays", nv.floor_hole_min_free_share_no_rays);
  f("nav", "shadow_max_width_m", nv.shadow_max_width_m);
  f("nav", "shadow_min_depth_m", nv.shadow_min_depth_m);
  f("nav", "floor_max_offset_m", nv.floor_max_offset_m);
  f("nav", "floor_tile_m", nv.floor_tile_m);
  f("nav", "rays", nv.rays);
  f("nav", "max_range_m", nv.max_range_m);
  f("nav", "over_low_max_m", nv.over_low_max_m);
  f("nav", "scanner_clear_m", nv.scanner_clear_m);
  f("nav", "ray_under_min_m", nv.ray_under_min_m);
  f("robot", "min_obstacle_height_m", nv.min_obstacle_height_m);
  f("robot", "height_m", nv.height_m);
}

// Calls f(section, key, field) for every configurable field, in documentation order. One list
// serves reading, printing and validation, so they cannot drift apart.
template <class F>
void visit(PipelineConfig& c, F&& f) {
  f("input", "unit_m", c.load.unit_m);
  f("input", "up_axis", c.load.up_axis);
  f("input", "max_points", c.load.max_points);
  f("input", "scanners", c.scanners);
  visit_level(c.map.level, f);
  auto& al = c.map.align_walls;
  f("align_walls", "enabled", al.enabled);
  f("align_walls", "cell_m", al.cell_m);
  f("align_walls", "min_wall_height_m", al.min_wall_height_m);
  f("align_walls", "sample_points", al.sample_points);
  f("align_walls", "min_wall_points", al.min_wall_points);
  f("align_walls", "min_confidence", al.min_confidence);
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
  f("ghosts", "far_end_m", gh.far_end_m);
  f("ghosts", "end_skip_m", gh.end_skip_m);
  f("ghosts", "max_rays", gh.max_rays);
  auto& vc = c.map.viewpoint_check;
  f("viewpoint_check", "enabled", vc.enabled);
  f("viewpoint_check", "samples", vc.samples);
  f("viewpoint_check", "end_margin_m", vc.end_margin_m);
  f("viewpoint_check", "min_points", vc.min_points);
  f("viewpoint_check", "max_occluded_share", vc.max_occluded_share);
  auto& ly = c.map.layers;
  f("layers", "min_points_per_voxel", ly.min_points_per_voxel);
  f("layers", "isolated_min_points", ly.isolated_min_points);
  f("layers", "floor_min_fraction", ly.floor_min_fraction);
  f("layers", "ceiling_min_fraction", ly.ceiling_min_fraction);
  f("layers", "min_room_height_m", ly.min_room_height_m);
  f("layers", "ceiling_onset_factor", ly.ceiling_onset_factor);
  f("layers", "surface_block_m", ly.surface_block_m);
  f("layers", "floor_clearance_m", ly.floor_clearance_m);
  f("layers", "ceiling_clearance_m", ly.ceiling_clearance_m);
  f("layers", "wall_band_m", ly.wall_band_m);
  f("layers", "wall_min_extent_m", ly.wall_min_extent_m);
  f("layers", "furniture_max_height_m", ly.furniture_max_height_m);
  f("layers", "low_wall_band_m", ly.low_wall_band_m);
  f("layers", "low_wall_min_length_m", ly.low_wall_min_length_m);
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
  f("layout", "wall_max_thickness_m", lo.wall_max_thickness_m);
  f("layout", "hidden_body_max_depth_m", lo.hidden_body_max_depth_m);
  f("layout", "hanging_gap_m", lo.hanging_gap_m);
  f("layout", "free_needs_evidence", lo.free_needs_evidence);
  f("layout", "sparse_floor_fill", lo.sparse_floor_fill);
  f("layout", "passage_bridge_m", lo.passage_bridge_m);
  auto& ob = c.objects;
  f("objects", "min_area_m2", ob.min_area_m2);
  f("objects", "join_gap_m", ob.join_gap_m);
  f("objects", "neck_width_m", ob.neck_width_m);
  f("objects", "neck_min_part_m2", ob.neck_min_part_m2);
  f("objects", "min_seen_area_m2", ob.min_seen_area_m2);
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
  auto& st = c.storeys;
  f("storeys", "enabled", st.enabled);
  f("storeys", "slab_max_fraction", st.slab_max_fraction);
  f("storeys", "min_slab_m", st.min_slab_m);
  f("storeys", "min_height_m", st.min_height_m);
  f("storeys", "surface_min_fraction", st.surface_min_fraction);
  visit_nav(c.map.nav, f);
  visit_plan(c.plan, f);
}

std::string axis_name(cloud_io::UpAxis a) {
  return a == cloud_io::UpAxis::kY ? "y" : "z";
}

}  // namespace

// The pipeline's own field types (the generic ones are in config_reader.hpp).
template <>
struct ConfigValue<objects::Connectivity> {
  static void read(const ConfigReader& rd, const YAML::Node& n, const std::string& key,
                   objects::Connectivity& v) {
    const auto k = rd.integer<int>(n, key);
    if (k != 4 && k != 8) rd.fail(n, key, "expected 4 or 8");
    v = k == 4 ? objects::Connectivity::k4 : objects::Connectivity::k8;
  }
  static void emit(YAML::Emitter& out, objects::Connectivity v) { out << static_cast<int>(v); }
  static nlohmann::json json(objects::Connectivity v) { return static_cast<int>(v); }
};

template <>
struct ConfigValue<cloud_io::UpAxis> {
  static void read(const ConfigReader& rd, const YAML::Node& n, const std::string& key,
                   cloud_io::UpAxis& v) {
    const auto s = rd.text(n, key);
    if (s == "z")
      v = cloud_io::UpAxis::kZ;
    else if (s == "y")
      v = cloud_io::UpAxis::kY;
    else
      rd.fail(n, key, "expected 'z' or 'y', got '" + s + "'");
  }
  static void emit(YAML::Emitter& out, cloud_io::UpAxis v) { out << axis_name(v); }
  static nlohmann::json json(cloud_io::UpAxis v) { return axis_name(v); }
};

/// input.scanners: a list of [x, y, z].
template <>
struct ConfigValue<std::vector<Eigen::Vector3d>> {
  static void read(const ConfigReader& rd, const YAML::Node& n, const std::string& key,
                   std::vector<Eigen::Vector3d>& v) {
    if (!n.IsSequence()) rd.fail(n, key, "expected a list of [x, y, z]");
    v.clear();
    for (const auto& e : n) {
      if (!e.IsSequence() || e.size() != 3) rd.fail(e, key, "each scanner is [x, y, z]");
      v.emplace_back(rd.number(e[0], key), rd.number(e[1], key), rd.number(e[2], key));
    }
  }
  static void emit(YAML::Emitter& out, const std::vector<Eigen::Vector3d>& v) {
    out << YAML::Flow << YAML::BeginSeq;
    for (const auto& p : v)
      out << YAML::Flow << YAML::BeginSeq << p.x() << p.y() << p.z() << YAML::EndSeq;
    out << YAML::EndSeq;
  }
  static nlohmann::json json(const std::vector<Eigen::Vector3d>& v) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& p : v) a.push_back({p.x(), p.y(), p.z()});
    return a;
  }
};

void merge_config_file(PipelineConfig& config, const std::string& path) {
  read_config_file(path, [&](auto&& f) { visit(config, f); });
}

void merge_config_tree(PipelineConfig& config, const YAML::Node& root, const std::string& name) {
  const auto table = [&](auto&& f) { visit(config, f); };
  check_config_tree(root, name, config_keys(table));
  read_config_tree(root, name, table);
}

void validate(const PipelineConfig& c) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw UsageError("invalid parameter " + what);
  };
  cloud_io::validate(c.load);  // throws UsageError naming input.<key>
  for (const auto& s : c.scanners) require(s.allFinite(), "input.scanners: must be finite");
  cloud::validate(c.map.level);        // level.<key>, voxel.<key>, ghosts.<key>, layers.<key>
  cloud::validate(c.map.align_walls);  // align_walls.<key>
  cloud::validate(c.map.voxel);
  cloud::validate(c.map.ghosts);
  layout::validate(c.map.viewpoint_check);  // viewpoint_check.<key>
  cloud::validate(c.map.layers);
  layout::validate(c.map.layout);  // throws UsageError naming layout.<key>
  layout::validate(c.map.nav);
  layout::validate(c.storeys);   // robot.min_obstacle_height_m, robot.height_m, nav.<key>
  objects::validate(c.objects);  // objects.<key>
  border::validate(c.border);    // throws UsageError naming border.<key>
  validate(c.plan);
}

std::string to_yaml(const PipelineConfig& config) {
  PipelineConfig c = config;
  return config_to_yaml([&](auto&& f) { visit(c, f); });
}

nlohmann::json to_json(const PipelineConfig& config) {
  PipelineConfig c = config;
  return config_to_json([&](auto&& f) { visit(c, f); });
}

}  // namespace indoormap::app
