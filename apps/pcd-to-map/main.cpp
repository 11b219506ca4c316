// pcd-to-map: indoor lidar scans -> levelled room layout and ROS navigation map.
// Usage and outputs: docs/pcd-to-map.md.
#include <chrono>
#include <filesystem>
#include <iostream>

#include "border_outputs.hpp"
#include "cli.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "objects_outputs.hpp"
#include "output_set.hpp"
#include "pipeline_run.hpp"
#include "route_outputs.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using nlohmann::json;

namespace {

int run(int argc, char** argv) {
  CLI::App cli_app{
      "pcd-to-map: turn indoor lidar scans into a levelled room layout and a ROS navigation map.\n"
      "Outputs map.pgm + map.yaml, layout.pgm, layout.png, objects.json and summary.json.\n"};
  cli_app.footer(
      "Examples:\n"
      "  pcd-to-map clouds/office/cloud.pcd -o out\n"
      "  pcd-to-map ../shared/data/jacobs-thermocolorlab --scans 0-8 -o out/jacobs\n"
      "  pcd-to-map scan.xyz --unit mm --up-axis y --scanner 0,0,1.5 -o out/scan\n"
      "  pcd-to-map --print-config > my.yaml; pcd-to-map -c my.yaml room.ply -o out\n"
      "  pcd-to-map clouds/office/cloud.pcd --start 1,1,0 --goal 4,3 -o out   # adds a route\n"
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
  const auto& m = run.map;
  double objects_ms = 0.0;
  objects::ObjectsResult objs = app::timed_objects(m, cfg.objects, &objects_ms);
  double border_ms = 0.0;
  const border::BorderResult border_result = app::timed_border(m, cfg.border, &border_ms);
  const std::size_t furniture_count = objs.objects.size();
  app::add_border_objects(objs, border_result);

  const auto t_write = std::chrono::steady_clock::now();
  app::OutputSet set(out, "pcd-to-map");  // all or nothing: docs/pcd-to-map.md, "Outputs"
  const fs::path& dir = set.dir();
  std::vector<std::string> outputs = app::write_map_outputs(dir, run);
  app::ObjectOutputs what;
  what.csv = what.picture = false;
  for (auto& f : app::write_object_outputs(dir, m, objs, what)) outputs.push_back(f);
  json border_block = app::write_border_outputs(dir, m, border_result, border_ms);
  for (const auto& f : border_block["outputs"]) outputs.push_back(f.get<std::string>());
  const auto route = app::write_route_outputs(dir, setup->cli, cfg, m.layout.layout,
                                              m.geometry);  // --start/--goal
  if (route)
    for (const auto& f : route->summary.value("outputs", json::array()))
      outputs.push_back(f.get<std::string>());

  json summary = app::summary_json("pcd-to-map", run, cfg);
  summary["border"] = border_block;
  summary["route"] = route ? route->summary : json(nullptr);
  summary["objects"] = {{"count", objs.objects.size()},
                        {"from_border", objs.objects.size() - furniture_count},
                        {"file", "objects.json"}};
  summary["timings_ms"]["objects"] = objects_ms;
  app::finish_summary(summary, dir, outputs, t_write, setup->start);
  set.commit();

  app::report("pcd-to-map", run, setup->cli.quiet);
  std::cout << "outputs written to " << out.string() << "\n";
  if (route && !route->found) std::cerr << "pcd-to-map: " << route->message << "\n";
  return route && !route->found ? static_cast<int>(ExitCode::kNoResult) : 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("pcd-to-map", [&] { return run(argc, argv); });
}
