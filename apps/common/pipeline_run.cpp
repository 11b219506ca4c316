#include "pipeline_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "cloud_hints.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/draw/layout_png.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/formats/pgm.hpp"
#include "indoormap/formats/ros_map.hpp"
#include "indoormap/version.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "report.hpp"
#include "scanner_positions.hpp"

namespace indoormap::app {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json vec(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

json plane_json(const cloud::PlaneFit& p) {
  if (!p.found) return nullptr;
  return {{"normal", vec(p.normal)},
          {"offset_m", p.offset_m},
          {"inliers", p.inliers},
          {"rms_m", p.rms_m}};
}

json band_json(const cloud::HeightBand& b) {
  return {{"lo_m", b.lo_m}, {"hi_m", b.hi_m}, {"layers", {b.lo_layer, b.hi_layer}}};
}

std::string fmt_m(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

json matrix_json(const Eigen::Matrix3d& m) {
  json rows = json::array();
  for (int r = 0; r < 3; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2)});
  return rows;
}

// map.yaml's note on the frame when the walls were aligned: how to go back to the input frame.
std::vector<std::string> frame_comments(const cloud::LevelResult& lv) {
  if (!lv.align.applied) return {};
  const Eigen::Matrix3d& r = lv.map_from_input;
  char yaw[160], row[3][96];
  std::snprintf(yaw, sizeof yaw,
                "frame: levelled, then turned %.4f deg about +z (--align-walls) so the walls run "
                "along x and y",
                lv.align.yaw_deg);
  for (int i = 0; i < 3; ++i)
    std::snprintf(row[i], sizeof row[i], "%s[%.9f, %.9f, %.9f]%s", i == 0 ? "[" : " ", r(i, 0),
                  r(i, 1), r(i, 2), i == 2 ? "]" : ",");
  return {yaw,
          "map = R * input, input = R^T * map (metres, about the input frame's origin); R = "
          "summary.json levelling.map_from_input:",
          std::string("R = ") + row[0], std::string("    ") + row[1], std::string("    ") + row[2]};
}

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

std::optional<AppSetup> setup_pipeline_app(CLI::App& app, PipelineCli& cli, int argc, char** argv,
                                           int* exit_code) {
  *exit_code = 0;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    *exit_code = app.exit(e) == 0 ? 0 : static_cast<int>(ExitCode::kBadInput);
    return std::nullopt;
  }
  AppSetup s{cli, resolve_config(cli), cli.out_dir, std::chrono::steady_clock::now()};
  if (cli.print_config) {
    std::cout << to_yaml(s.config);
    return std::nullopt;
  }
  if (cli.inputs.empty()) throw UsageError("no input given (see --help)");
  if (cli.out_dir.empty()) throw UsageError("no output directory given: use -o DIR");
  ensure_writable_dir(s.out);
  return s;
}

bool strays_unfiltered(const layout::MapResult& m) {
  return m.cloud_map.scanners.empty();
}

objects::ObjectsResult timed_objects(const layout::MapResult& m,
                                     const objects::ObjectParams& params, double* ms,
                                     bool strays_out) {
  const auto t = std::chrono::steady_clock::now();
  objects::ObjectsResult r = objects::extract_objects(
      m.layout.layout, m.geometry, m.voxels, m.layers, params, m.cloud_map.scanners,
      objects::ScanTraits{m.dense_scan, m.cloud_map.scanners_on_path,
                          strays_out && strays_unfiltered(m)});
  if (strays_out) objects::drop_stray_pieces(r, m.geometry, params);
  *ms += ms_since(t);
  return r;
}

border::BorderResult timed_border(const layout::MapResult& m, const border::BorderParams& params,
                                  double* ms) {
  const auto t = std::chrono::steady_clock::now();
  border::BorderResult r = border::close_border(m, params);
  *ms = ms_since(t);
  return r;
}

void finish_summary(json& summary, const fs::path& out, std::vector<std::string> outputs,
                    std::chrono::steady_clock::time_point write_start,
                    std::chrono::steady_clock::time_point start) {
  summary["timings_ms"]["write"] = ms_since(write_start);
  summary["timings_ms"]["total"] = ms_since(start);
  outputs.push_back(kReportFile);
  outputs.push_back("summary.json");
  summary["outputs"] = outputs;
  formats::write_json(out / "summary.json", summary);
  write_report(out, summary, outputs);
}

PipelineRun run_pipeline(const PipelineCli& cli, PipelineConfig& cfg, bool keep_input_points) {
  const auto t0 = std::chrono::steady_clock::now();
  start_digests(cli.inputs);  // summary.json's provenance, hashed beside the run's work
  cfg.load.progress = load_progress(cli.quiet);
  cloud_io::LoadResult loaded = cloud_io::load_clouds(cli.inputs, cfg.load);
  cfg.load.progress = nullptr;  // ends the last file's bar line
  return map_loaded(std::move(loaded), cli, cfg, keep_input_points, ms_since(t0));
}

PipelineRun map_loaded(cloud_io::LoadResult loaded, const PipelineCli& cli, PipelineConfig& cfg,
                       bool keep_input_points, double load_ms) {
  PipelineRun run;
  run.load_ms = load_ms;
  run.inputs = loaded.inputs;
  run.source_offset = loaded.source_offset;
  std::vector<std::string> input_warnings;
  for (const auto& in : loaded.inputs)
    input_warnings.insert(input_warnings.end(), in.warnings.begin(), in.warnings.end());
  if (!cfg.scanners.empty()) {  // given positions replace the files': origins no longer apply
    loaded.cloud.scanners = cfg.scanners;
    loaded.cloud.origins.clear();
  }
  const CloudExtent extent = extent_of(loaded);
  if (!cli.trajectory.empty()) add_trajectory(cli.trajectory, extent, loaded.cloud);
  run.scanner_source = loaded.cloud.scanners.empty() ? "estimated"
                       : !cli.trajectory.empty()     ? "trajectory"
                       : cfg.scanners.empty()        ? "file"
                                                     : "config";
  run.kept = loaded.cloud.points.size();
  if (keep_input_points) run.input_points = loaded.cloud.points;
  std::string names;  // the data as a whole: every input
  for (const auto& in : cli.inputs) names += (names.empty() ? "" : ", ") + in;
  const std::string unit = unit_hint(extent, cfg.load.unit_m);  // empty unless over 1 km wide
  try {
    const ProgressReporter ghost_bar("ghost filter", "voxels", cli.quiet);
    cfg.map.ghosts.progress = ghost_bar.fn();
    // Only a position the file gives (one PCD's VIEWPOINT) is checked: a given one stands.
    const bool check_viewpoint = cfg.map.viewpoint_check.enabled;
    cfg.map.viewpoint_check.enabled = check_viewpoint && run.scanner_source == "file";
    auto maps = layout::make_storey_maps(std::move(loaded.cloud), cfg.map, cfg.storeys, cli.storey);
    cfg.map.viewpoint_check.enabled = check_viewpoint;
    cfg.map.ghosts.progress = nullptr;
    ghost_bar.finish();
    run.storeys = maps.storeys;
    run.mapped = maps.mapped;
    if (maps.maps.empty()) throw InputError(names, "no storey holds points");
    for (const auto& m : maps.maps)
      run.mapped_surfaces_m.emplace_back(m.layers.floor_z_m, m.layers.ceiling_z_m);
    run.map = std::move(maps.maps.front());
    run.more_maps.assign(std::make_move_iterator(maps.maps.begin() + 1),
                         std::make_move_iterator(maps.maps.end()));
  } catch (const InputError& e) {
    if (!e.file().empty()) throw;
    std::string hint = unit;
    if (hint.empty() && e.problem().starts_with("all points lie at one height"))
      hint = height_hint(extent, cfg.map.voxel.bounds_gap_m);
    throw InputError(names, e.problem() + (hint.empty() ? "" : "; " + hint), e.line());
  } catch (const BudgetError& e) {  // a grid too large: most likely the unit, say so first
    if (unit.empty()) throw;
    throw InputError(names, unit + " (" + e.what() + ")");
  }
  if (run.storeys.size() > 1) {
    char msg[96];
    std::snprintf(msg, sizeof msg, "%zu storeys found; mapped:", run.storeys.size());
    std::string w = msg;
    for (int k : run.mapped) w += " " + std::to_string(k);
    input_warnings.push_back(w);
  }
  run.map.warnings.insert(run.map.warnings.begin(), input_warnings.begin(), input_warnings.end());
  if (const auto w = up_axis_warning(run.map.voxels, names); !w.empty())
    run.map.warnings.push_back(w);
  // A map without a single wall, furniture or free cell is not a result: the points are too few
  // or too far apart for the cells (1e308 or kilometres apart gave an empty map with exit 0).
  const auto& lc = run.map.layout;
  if (lc.cells_wall + lc.cells_furniture + lc.cells_free == 0) {
    std::uint64_t dropped = 0;
    for (const auto& in : run.inputs) dropped += in.points_dropped;
    char span[160], cell[32];
    const auto& g = run.map.geometry;
    std::snprintf(span, sizeof span, "%.3g x %.3g m", g.width() * g.cell_m(),
                  g.height() * g.cell_m());
    std::snprintf(cell, sizeof cell, "%g", g.cell_m());
    throw InputError(names, "no map: the layout has no wall, furniture or free cell (" +
                                std::to_string(run.kept) + " points kept over " + span +
                                (dropped ? ", " + std::to_string(dropped) +
                                               " non-finite or beyond float range dropped"
                                         : std::string()) +
                                "): too few points, or too far apart for cells of " + cell +
                                " m (check --unit)" + (unit.empty() ? "" : "; " + unit));
  }
  return run;
}

std::vector<std::string> write_map_outputs(const fs::path& out, const PipelineRun& run,
                                           const PipelineConfig& cfg) {
  const auto& m = run.map;
  std::vector<Eigen::Vector2d> markers;
  for (const auto& s : m.cloud_map.scanners) markers.emplace_back(s.x(), s.y());
  if (m.layout.seeds_estimated)
    for (const auto& s : m.layout.seeds) markers.push_back(m.geometry.center_of(s));
  std::vector<std::string> comments = source_frame_comments(run, cfg);
  for (auto& c : frame_comments(m.level)) comments.push_back(std::move(c));
  formats::write_ros_map(out, "map", m.nav.map, m.geometry,  // the robot's map, not M_r
                         comments);
  formats::write_layout_pgm(out / "layout.pgm", m.layout.layout);
  draw::RenderOptions ro;
  ro.title = "room layout M_r  (" + std::to_string(m.geometry.width()) + " x " +
             std::to_string(m.geometry.height()) + " cells of " +
             std::to_string(static_cast<int>(std::lround(m.geometry.cell_m() * 100))) + " cm)";
  ro.markers_map = markers;
  ro.marker_label = m.layout.seeds_estimated ? "scanner (estimated)" : "scanner";
  draw::write_layout_png(out / "layout.png", m.layout.layout, m.geometry, ro);
  ro.title = "navigation map (map.pgm): body band " + fmt_m(m.nav.body_lo_m - m.layers.floor_z_m) +
             "-" + fmt_m(m.nav.body_hi_m - m.layers.floor_z_m) + " m above the floor";
  ro.marker_label = "scanner position";
  ro.markers_map.clear();
  for (const auto& s : m.cloud_map.scanners) ro.markers_map.emplace_back(s.x(), s.y());
  draw::write_layout_png(out / "map.png", m.nav.map, m.geometry, ro);
  return {"map.pgm", "map.yaml", "map.png", "layout.pgm", "layout.png"};
}

json summary_json(const std::string& program, const PipelineRun& run, const PipelineConfig& cfg) {
  const auto& m = run.map;
  std::uint64_t read = 0, dropped = 0;
  json inputs = json::array();
  for (const auto& in : run.inputs) {
    read += in.points_read;
    dropped += in.points_dropped;
    inputs.push_back(
        {{"path", in.path},
         {"format", in.format},
         {"points_read", in.points_read},
         {"points_dropped", in.points_dropped},
         {"scans", in.scans},
         {"scanner_known", in.scanner_known},
         {"source_offset", in.source_offset ? vec(*in.source_offset) : json(nullptr)}});
  }
  json layers = json::array();
  for (std::size_t z = 0; z < m.layers.occupied_per_layer.size(); ++z)
    layers.push_back({{"layer", z},
                      {"z_m", m.voxels.layer_center_m(static_cast<std::int64_t>(z))},
                      {"occupied_cells", m.layers.occupied_per_layer[z]}});
  const json rot = matrix_json(m.level.map_from_input);
  const auto& al = m.level.align;
  json scanners = json::array();
  for (const auto& s : m.cloud_map.scanners) scanners.push_back(vec(s));
  json seeds = json::array();
  for (const auto& s : m.layout.seeds) {
    const auto c = m.geometry.center_of(s);
    seeds.push_back({c.x(), c.y()});
  }
  json hanging = json::array();
  for (const auto& hg : m.layout.hanging) {
    const Eigen::Vector2d lo =
        m.geometry.origin_m() + Eigen::Vector2d(hg.min_col, hg.min_row) * m.geometry.cell_m();
    const Eigen::Vector2d hi =
        m.geometry.origin_m() +
        Eigen::Vector2d(hg.max_col + 1, hg.max_row + 1) * m.geometry.cell_m();
    hanging.push_back(
        {{"bbox_m", {{"min", {lo.x(), lo.y()}}, {"max", {hi.x(), hi.y()}}}}, {"cells", hg.cells}});
  }
  json timings = {{"load", run.load_ms}};
  for (const auto& t : m.timings) timings[t.stage] = t.ms;
  std::vector<std::string> input_paths;
  for (const auto& in : run.inputs) input_paths.push_back(in.path);
  return {
      {"program", program},
      {"version", kVersion},
      {"provenance", provenance_json(input_paths)},
      {"inputs", inputs},
      {"points",
       {{"read", read},
        {"dropped_nonfinite", dropped},
        {"kept", run.kept},
        {"outside_bounds", m.voxels.points_outside},
        {"in_grid", m.voxels.points_inside}}},
      {"levelling",
       {{"levelled", m.level.levelled},
        {"tilt_deg", m.level.tilt_deg},
        {"up_input", vec(m.level.up_input)},
        {"map_from_input", rot},
        {"floor_plane_input", plane_json(m.level.floor)},
        {"ceiling_plane_input", plane_json(m.level.ceiling)},
        {"note", m.level.note}}},
      {"align_walls",
       {{"enabled", cfg.map.align_walls.enabled},
        {"applied", al.applied},
        {"yaw_deg", al.yaw_deg},
        {"wall_direction_levelled_deg", al.direction_deg},
        {"confidence", al.confidence},
        {"wall_points", al.wall_points},
        {"note", al.note},
        {"map_from_input", rot},
        {"input_from_map", matrix_json(m.level.map_from_input.transpose())}}},
      {"source_frame", source_frame_json(run, cfg)},
      {"grid",
       {{"resolution_m", m.voxels.cell_m},
        {"origin_m", vec(m.voxels.origin_m)},
        {"size_cells", {m.voxels.nx, m.voxels.ny, m.voxels.nz}},
        {"bounds_m", {{"lo", vec(m.bounds.lo_m)}, {"hi", vec(m.bounds.hi_m)}}}}},
      {"floor_z_m", m.layers.floor_z_m},
      {"floor_fill", m.floor_fill},
      {"free_from_evidence", m.free_from_evidence},
      {"veil_cells_dropped", m.veil_cells_dropped},
      {"ceiling_z_m", m.layers.ceiling_z_m},
      {"ceiling_found", m.layers.ceiling_found},
      {"ceiling_sloped", m.layers.ceiling_sloped},
      {"room_height_m", m.layers.ceiling_z_m - m.layers.floor_z_m},
      {"wall_band", band_json(m.layers.wall_band)},
      {"low_wall_band", band_json(m.layers.low_wall_band)},
      {"furniture_band", band_json(m.layers.furniture_band)},
      {"layers", layers},
      {"scanners_map_m", scanners},
      {"scanner_source", run.scanner_source},
      {"flood_seeds_map_m", seeds},
      {"hanging_objects", hanging},
      {"viewpoint_check",
       {{"occluded_share",
         m.viewpoint_occluded_share ? json(*m.viewpoint_occluded_share) : json(nullptr)},
        {"position_dropped", m.viewpoint_dropped}}},
      {"ghosts",
       {{"applied", m.ghosts.applied},
        {"rays", m.ghosts.rays},
        {"voxels_removed", m.ghosts.voxels_removed},
        {"points_removed", m.ghosts.points_removed}}},
      {"layout_cells",
       {{"wall", m.layout.cells_wall},
        {"furniture", m.layout.cells_furniture},
        {"free", m.layout.cells_free},
        {"unknown", m.layout.cells_unknown}}},
      {"nav_map",
       {{"body_band_m", {m.nav.body_lo_m, m.nav.body_hi_m}},
        {"positions", m.nav.positions},
        {"rays", m.nav.rays},
        {"cells",
         {{"occupied", m.nav.cells_occupied},
          {"free", m.nav.cells_free},
          {"free_floor_seen", m.nav.cells_floor_seen},
          {"free_rays_only", m.nav.cells_ray_free},
          {"free_shadows", m.nav.cells_shadow_filled},
          {"free_over_low", m.nav.cells_over_low},
          {"free_floor_holes", m.nav.cells_hole_filled},
          {"unknown", m.nav.cells_unknown}}},
        {"specks_dropped", m.nav.specks_dropped}}},
      {"timings_ms", timings},
      {"parameters", to_json(cfg)},
      {"warnings", m.warnings},
  };
}

json storeys_json(const PipelineRun& run) {
  json out = json::array();
  for (std::size_t k = 0; k < run.storeys.size(); ++k) {
    const auto& s = run.storeys[k];
    const auto at = std::find(run.mapped.begin(), run.mapped.end(), static_cast<int>(k));
    const bool mapped = at != run.mapped.end();
    // A mapped storey's heights are those its map was made with (its own levelling and layer
    // analysis); the surface histogram of the whole cloud that found it can be a cell or two off.
    const auto i = static_cast<std::size_t>(at - run.mapped.begin());
    const bool own = mapped && i < run.mapped_surfaces_m.size();
    out.push_back({{"index", k},
                   {"floor_z_m", own ? run.mapped_surfaces_m[i].first : s.floor_z_m},
                   {"ceiling_z_m", own ? run.mapped_surfaces_m[i].second : s.ceiling_z_m},
                   {"histogram_floor_z_m", s.floor_z_m},
                   {"histogram_ceiling_z_m", s.ceiling_z_m},
                   {"z_range_m", {s.lo_z_m, s.hi_z_m}},
                   {"mapped", mapped},
                   {"dir", run.storeys.size() > 1 ? "storey_" + std::to_string(k) : "."}});
  }
  return out;
}

namespace {

constexpr const char* kToSource =
    "source = source_frame.offset + S(transpose(map_from_input) * p_map) / unit_m, S undoing "
    "the up-axis swap (up_axis z: S = identity; up_axis y: S(x, y, z) = (x, z, -y))";

std::string fmt_offset(const Eigen::Vector3d& o) {
  char b[128];
  std::snprintf(b, sizeof b, "[%.3f, %.3f, %.3f]", o.x(), o.y(), o.z());
  return b;
}

}  // namespace

json source_frame_json(const PipelineRun& run, const PipelineConfig& cfg) {
  if (!run.source_offset) return nullptr;
  json rot = json::array();
  const auto& r = run.map.level.map_from_input;
  for (int i = 0; i < 3; ++i) rot.push_back({r(i, 0), r(i, 1), r(i, 2)});
  return {{"offset", vec(*run.source_offset)},
          {"unit_m", cfg.load.unit_m},
          {"up_axis", cfg.load.up_axis == cloud_io::UpAxis::kY ? "y" : "z"},
          {"map_from_input", rot},
          {"to_source", kToSource},
          {"note",
           "LAS coordinates were moved to a local frame on reading (source minus offset, in "
           "double precision, before the conversion to float); the map frame is that local "
           "frame, scaled by unit_m, up-axis mapped and levelled (levelling.map_from_input)"}};
}

std::vector<std::string> source_frame_comments(const PipelineRun& run, const PipelineConfig& cfg) {
  if (!run.source_offset) return {};
  const auto& r = run.map.level.map_from_input;
  char rot[256];
  std::snprintf(rot, sizeof rot, "[[%.9f, %.9f, %.9f], [%.9f, %.9f, %.9f], [%.9f, %.9f, %.9f]]",
                r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2));
  char unit[64];
  std::snprintf(unit, sizeof unit, "%g", cfg.load.unit_m);
  return {
      "map frame = map_from_input * ((source frame - source_offset) * unit_m), up-axis "
      "mapped (the LAS input was moved to a local frame on reading)",
      "source_offset: " + fmt_offset(*run.source_offset) +
          "  (source units; summary.json source_frame.offset)",
      std::string("unit_m: ") + unit +
          "  up_axis: " + (cfg.load.up_axis == cloud_io::UpAxis::kY ? "y" : "z"),
      std::string("map_from_input: ") + rot + "  (summary.json levelling.map_from_input)",
      std::string("back: ") + kToSource};
}

void report(const std::string& program, const PipelineRun& run, bool quiet) {
  const auto& m = run.map;
  std::uint64_t dropped = 0;
  for (const auto& in : run.inputs) dropped += in.points_dropped;
  for (const auto& w : m.warnings) std::cerr << program << ": warning: " << w << "\n";
  if (quiet) return;
  std::cerr << program << ": " << run.kept << " points (" << dropped
            << " non-finite dropped), tilt " << m.level.tilt_deg << " deg, floor "
            << m.layers.floor_z_m << " m, ceiling " << m.layers.ceiling_z_m << " m"
            << (m.layers.ceiling_found ? "" : " (not detected)") << ", grid " << m.geometry.width()
            << " x " << m.geometry.height() << "\n";
}

}  // namespace indoormap::app
