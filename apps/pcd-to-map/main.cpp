// pcd-to-map: indoor lidar scans -> levelled room layout and ROS navigation map.
// Usage and outputs: docs/pcd-to-map.md.
#include <chrono>
#include <filesystem>
#include <iostream>

#include "cli.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/io/map_io.hpp"
#include "indoormap/io/render.hpp"
#include "indoormap/version.hpp"
#include "route_outputs.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using nlohmann::json;

namespace {

json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

json plane_json(const cloud::PlaneFit& p) {
  if (!p.found) return nullptr;
  return {{"normal", vec(p.normal)}, {"offset_m", p.offset_m}, {"inliers", p.inliers}, {"rms_m", p.rms_m}};
}

json band_json(const cloud::HeightBand& b) {
  return {{"lo_m", b.lo_m}, {"hi_m", b.hi_m}, {"layers", {b.lo_layer, b.hi_layer}}};
}

int run(int argc, char** argv) {
  CLI::App cli_app{
      "pcd-to-map: turn indoor lidar scans into a levelled room layout and a ROS navigation map.\n"
      "Outputs map.pgm + map.yaml, layout.pgm, layout.png and summary.json in the output directory.\n"};
  cli_app.footer(
      "Examples:\n"
      "  pcd-to-map clouds/office/cloud.pcd -o out\n"
      "  pcd-to-map ../shared/data/jacobs-thermocolorlab --scans 0-8 -o out/jacobs\n"
      "  pcd-to-map scan.xyz --unit mm --up-axis y --scanner 0,0,1.5 -o out/scan\n"
      "  pcd-to-map --print-config > my.yaml; pcd-to-map -c my.yaml room.ply -o out\n"
      "Exit codes: 0 done, 2 bad usage or bad input, 1 other failure.");
  app::PipelineCli cli;
  app::add_pipeline_options(cli_app, cli);
  try {
    cli_app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cli_app.exit(e) == 0 ? 0 : static_cast<int>(ExitCode::kBadInput);
  }
  const auto t_start = std::chrono::steady_clock::now();
  app::PipelineConfig cfg = app::resolve_config(cli);
  if (cli.print_config) {
    std::cout << app::to_yaml(cfg);
    return 0;
  }
  if (cli.inputs.empty()) throw UsageError("no input given (see --help)");
  if (cli.out_dir.empty()) throw UsageError("no output directory given: use -o DIR");
  const fs::path out = cli.out_dir;
  ensure_writable_dir(out);

  auto t0 = std::chrono::steady_clock::now();
  cfg.load.progress = app::terminal_progress();
  cloud::LoadResult loaded = cloud::load_clouds(cli.inputs, cfg.load);
  const double load_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!cfg.scanners.empty()) loaded.cloud.scanners = cfg.scanners;
  const std::size_t kept = loaded.cloud.points.size();
  const bool scanners_given = !loaded.cloud.scanners.empty();

  layout::MapResult m = [&] {
    try {
      return layout::make_map(std::move(loaded.cloud), cfg.map);
    } catch (const InputError& e) {
      if (!e.file().empty()) throw;
      std::string names;  // the data as a whole is unusable: name every input
      for (const auto& in : cli.inputs) names += (names.empty() ? "" : ", ") + in;
      throw InputError(names, e.problem(), e.line());
    }
  }();

  // Outputs.
  t0 = std::chrono::steady_clock::now();
  std::vector<Eigen::Vector2d> markers;
  for (const auto& s : m.cloud_map.scanners) markers.emplace_back(s.x(), s.y());
  if (m.layout.seeds_estimated)
    for (const auto& s : m.layout.seeds) markers.push_back(m.geometry.center_of(s));
  io::write_ros_map(out, "map", m.layout.layout, m.geometry);
  io::write_layout_pgm(out / "layout.pgm", m.layout.layout);
  io::RenderOptions ro;
  ro.title = "room layout M_r  (" + std::to_string(m.geometry.width()) + " x " +
             std::to_string(m.geometry.height()) + " cells of " +
             std::to_string(static_cast<int>(std::lround(m.geometry.cell_m() * 100))) + " cm)";
  ro.markers_map = markers;
  ro.marker_label = m.layout.seeds_estimated ? "scanner (estimated)" : "scanner";
  io::write_layout_png(out / "layout.png", m.layout.layout, m.geometry, ro);
  const double write_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const auto route = app::write_route_outputs(out, cli, cfg, m.layout.layout, m.geometry);  // --start/--goal

  std::uint64_t read = 0, dropped = 0;
  json inputs = json::array();
  for (const auto& in : loaded.inputs) {
    read += in.points_read;
    dropped += in.points_dropped;
    inputs.push_back({{"path", in.path}, {"format", in.format}, {"points_read", in.points_read},
                      {"points_dropped", in.points_dropped}, {"scans", in.scans},
                      {"scanner_known", in.scanner_known}});
  }
  json layers = json::array();
  for (std::size_t z = 0; z < m.layers.occupied_per_layer.size(); ++z)
    layers.push_back({{"layer", z}, {"z_m", m.voxels.layer_center_m(static_cast<std::int64_t>(z))},
                      {"occupied_cells", m.layers.occupied_per_layer[z]}});
  json rot = json::array();
  for (int r = 0; r < 3; ++r)
    rot.push_back({m.level.map_from_input(r, 0), m.level.map_from_input(r, 1), m.level.map_from_input(r, 2)});
  json scanners = json::array();
  for (const auto& s : m.cloud_map.scanners) scanners.push_back(vec(s));
  json seeds = json::array();
  for (const auto& s : m.layout.seeds) {
    const auto c = m.geometry.center_of(s);
    seeds.push_back({c.x(), c.y()});
  }
  json timings = {{"load", load_ms}};
  for (const auto& t : m.timings) timings[t.stage] = t.ms;
  timings["write"] = write_ms;
  timings["total"] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_start).count();

  json summary = {
      {"program", "pcd-to-map"},
      {"version", kVersion},
      {"inputs", inputs},
      {"points", {{"read", read}, {"dropped_nonfinite", dropped}, {"kept", kept},
                  {"outside_bounds", m.voxels.points_outside}, {"in_grid", m.voxels.points_inside}}},
      {"levelling", {{"levelled", m.level.levelled}, {"tilt_deg", m.level.tilt_deg},
                     {"up_input", vec(m.level.up_input)}, {"map_from_input", rot},
                     {"floor_plane_input", plane_json(m.level.floor)},
                     {"ceiling_plane_input", plane_json(m.level.ceiling)}, {"note", m.level.note}}},
      {"grid", {{"resolution_m", m.voxels.cell_m}, {"origin_m", vec(m.voxels.origin_m)},
                {"size_cells", {m.voxels.nx, m.voxels.ny, m.voxels.nz}},
                {"bounds_m", {{"lo", vec(m.bounds.lo_m)}, {"hi", vec(m.bounds.hi_m)}}}}},
      {"floor_z_m", m.layers.floor_z_m},
      {"ceiling_z_m", m.layers.ceiling_z_m},
      {"ceiling_found", m.layers.ceiling_found},
      {"room_height_m", m.layers.ceiling_z_m - m.layers.floor_z_m},
      {"wall_band", band_json(m.layers.wall_band)},
      {"furniture_band", band_json(m.layers.furniture_band)},
      {"layers", layers},
      {"scanners_map_m", scanners},
      {"scanner_source", scanners_given ? (cfg.scanners.empty() ? "file" : "config") : "estimated"},
      {"flood_seeds_map_m", seeds},
      {"layout_cells", {{"wall", m.layout.cells_wall}, {"furniture", m.layout.cells_furniture},
                        {"free", m.layout.cells_free}, {"unknown", m.layout.cells_unknown}}},
      {"timings_ms", timings},
      {"parameters", app::to_json(cfg)},
      {"warnings", m.warnings},
      {"outputs", {"map.pgm", "map.yaml", "layout.pgm", "layout.png", "summary.json"}},
      {"route", route ? route->summary : json(nullptr)},
  };
  io::write_json(out / "summary.json", summary);

  for (const auto& w : m.warnings) std::cerr << "pcd-to-map: warning: " << w << "\n";
  std::cerr << "pcd-to-map: " << kept << " points (" << dropped << " non-finite dropped), tilt "
            << m.level.tilt_deg << " deg, floor " << m.layers.floor_z_m << " m, ceiling "
            << m.layers.ceiling_z_m << " m" << (m.layers.ceiling_found ? "" : " (not detected)")
            << ", grid " << m.geometry.width() << " x " << m.geometry.height() << "\n";
  std::cout << "outputs written to " << out.string() << "\n";
  if (route && !route->found) std::cerr << "pcd-to-map: " << route->message << "\n";
  return route && !route->found ? static_cast<int>(ExitCode::kNoResult) : 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("pcd-to-map", [&] { return run(argc, argv); });
}
