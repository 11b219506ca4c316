// pcd-to-map: indoor lidar scans -> levelled room layout and ROS navigation map.
// Usage and outputs: docs/pcd-to-map.md.
#include <chrono>
#include <filesystem>
#include <future>
#include <iostream>
#include <optional>
#include <vector>

#include "border_outputs.hpp"
#include "cli.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/version.hpp"
#include "objects_outputs.hpp"
#include "output_set.hpp"
#include "pipeline_run.hpp"
#include "provenance.hpp"
#include "report.hpp"
#include "rooms_outputs.hpp"
#include "route_outputs.hpp"
#include "storey_work.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using nlohmann::json;

namespace {

int run(int argc, char** argv) {
  CLI::App cli_app{
      "pcd-to-map: turn indoor lidar scans into a levelled room layout and a ROS navigation map.\n"
      "Inputs: .pcd, .ply, .xyz / .txt / .csv (x y z first), .las (LAS 1.2-1.4; not .laz), or "
      "3DTK\n"
      "(a scan directory or a .3d file).\n"
      "Outputs in DIR: map.pgm + map.yaml + map.png (the navigation map), layout.pgm + "
      "layout.png,\n"
      "objects.json, room.geojson + room.json + border.png (the room's border), rooms.geojson +\n"
      "rooms.json + rooms.png (the rooms), summary.json, report.html (one page of the run);\n"
      "with --start/--goal route.json + route.png + safe.pgm + safe.yaml;\n"
      "several storeys: each storey's files in storey_<k>/.\n"};
  cli_app.footer(
      "Examples:\n"
      "  pcd-to-map clouds/office/cloud.pcd -o out\n"
      "  pcd-to-map ../shared/data/jacobs-thermocolorlab --scans 0-8 -o out/jacobs\n"
      "  pcd-to-map --print-config > my.yaml; pcd-to-map -c my.yaml clouds/office/cloud.pcd -o "
      "out/my\n"
      "  pcd-to-map clouds/office/cloud.pcd --start 1,1,0 --goal 4,3 -o out/with-route   # adds a "
      "route\n"
      "  pcd-to-map out/walk/cloud.pcd --trajectory out/walk/trajectory.txt -o out/walk-map   # "
      "mobile scan\n"
      "  pcd-to-map out/tower/cloud.pcd --storey 1 -o out/first   # the second storey only\n"
      "  pcd-to-map ../shared/data/jacobs-thermocolorlab --align-walls -o out/aligned   # walls "
      "along x / y\n"
      "(out/walk and out/tower: scene-sim --help's examples.) Other units and up axes, e.g. a "
      "text\n"
      "cloud in mm with y up: --unit mm --up-axis y --scanner 0,0,1.5 (the scanner in the "
      "converted\n"
      "frame: metres, z up).\n"
      "Frames: --scanner and --trajectory in the loaded frame (metres, z up: after --unit and\n"
      "--up-axis; LAS less its local offset, summary.json 'source_frame'), before levelling;\n"
      "--start/--goal in the map frame (metres; levelled, and turned with --align-walls: the "
      "frame\n"
      "of map.yaml).\n"
      "Exit codes: 0 done, 2 bad usage or bad input, 3 no route (with --start/--goal), 1 other "
      "failure.");
  app::PipelineCli cli;
  app::add_pipeline_options(cli_app, cli);
  int code = 0;
  auto setup = app::setup_pipeline_app(cli_app, cli, argc, argv, &code);
  if (!setup) return code;
  const auto& cfg = setup->config;
  const fs::path& out = setup->out;

  app::PipelineRun run = app::run_pipeline(setup->cli, setup->config, /*keep_input_points=*/false);
  const bool storeyed = run.storeys.size() > 1;  // outputs in storey_<k>/, else in OUTDIR itself
  if (storeyed && (!setup->cli.start.empty() || !setup->cli.goal.empty()) && run.mapped.size() > 1)
    throw UsageError("--start / --goal on a cloud of " + std::to_string(run.storeys.size()) +
                     " storeys: pick one with --storey K");
  // Compute every storey first, then write everything (all or nothing).
  std::vector<app::StoreyWork> work;
  for (std::size_t i = 0; i < run.mapped.size(); ++i)
    work.push_back(app::compute_storey(
        run.mapped[i], i == 0 ? std::move(run.map) : std::move(run.more_maps[i - 1]), cfg));

  const auto t_write = std::chrono::steady_clock::now();
  app::OutputSet set(out, "pcd-to-map");  // all or nothing: docs/pcd-to-map.md, "Outputs"
  std::vector<std::string> top_outputs;
  std::optional<app::RouteOutputs> route;
  json storeys = json::array();
  for (auto& w : work) {
    const std::string sub = storeyed ? "storey_" + std::to_string(w.index) : "";
    const fs::path dir = sub.empty() ? set.dir() : set.dir() / sub;
    if (!sub.empty()) fs::create_directories(dir);
    run.map = std::move(w.map);
    const auto& m = run.map;
    // The maps' pictures are drawn and encoded beside the other outputs (all read-only on run).
    auto map_files =
        std::async(std::launch::async, [&] { return app::write_map_outputs(dir, run, cfg); });
    std::vector<std::string> outputs;
    app::ObjectOutputs what;
    what.csv = what.picture = false;
    what.room_ids = &w.rooms.object_rooms;
    for (auto& f : app::write_object_outputs(dir, m, w.objs, what)) outputs.push_back(f);
    json border_block = app::write_border_outputs(dir, m, w.border, w.border_ms);
    for (const auto& f : border_block["outputs"]) outputs.push_back(f.get<std::string>());
    json rooms_block = app::write_rooms_outputs(dir, m, w.objs, w.rooms);
    for (const auto& f : rooms_block["outputs"]) outputs.push_back(f.get<std::string>());
    route = app::write_route_outputs(dir, setup->cli, cfg, m.layout.layout,
                                     m.geometry);  // --start/--goal
    if (route)
      for (const auto& f : route->summary.value("outputs", json::array()))
        outputs.push_back(f.get<std::string>());
    std::vector<std::string> map_outputs = map_files.get();  // rethrows a failed write
    outputs.insert(outputs.begin(), map_outputs.begin(), map_outputs.end());
    json summary = app::summary_json("pcd-to-map", run, cfg);
    summary["border"] = border_block;
    summary["rooms"] = rooms_block;
    summary["route"] = route ? route->summary : json(nullptr);
    summary["objects"] = {{"count", w.objs.objects.size()},
                          {"from_border", w.objs.objects.size() - w.furniture_count},
                          {"left_over_cells", w.objs.left_over_cells},
                          {"left_over_area_m2", w.objs.left_over_area_m2},
                          {"file", "objects.json"}};
    summary["timings_ms"]["objects"] = w.objects_ms;
    summary["storeys"] = app::storeys_json(run);
    if (sub.empty()) {
      app::finish_summary(summary, dir, outputs, t_write, setup->start);
    } else {
      summary["storey"] = w.index;
      app::finish_summary(summary, dir, outputs, t_write, setup->start);
      for (const auto& f : outputs) top_outputs.push_back(sub + "/" + f);
      top_outputs.push_back(sub + "/" + app::kReportFile);
      top_outputs.push_back(sub + "/summary.json");
    }
    app::report("pcd-to-map", run, setup->cli.quiet);
  }
  if (storeyed) {  // OUTDIR/summary.json: the storeys and where their outputs are
    json summary = {{"program", "pcd-to-map"},
                    {"version", kVersion},
                    {"provenance", app::provenance_json(setup->cli.inputs)},
                    {"storeys", app::storeys_json(run)},
                    {"source_frame", app::source_frame_json(run, cfg)},
                    {"parameters", app::to_json(cfg)}};
    app::finish_summary(summary, set.dir(), top_outputs, t_write, setup->start);
  }
  set.commit();

  std::cout << "outputs written to " << out.string() << "\n";
  if (route && !route->found) std::cerr << "pcd-to-map: " << route->message << "\n";
  return route && !route->found ? static_cast<int>(ExitCode::kNoResult) : 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("pcd-to-map", argc, argv, [&] { return run(argc, argv); });
}
