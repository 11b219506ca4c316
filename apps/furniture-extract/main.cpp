// furniture-extract: the furniture objects of a scanned room, with their size, place and height,
// and each object's own points for a recogniser. Usage and outputs: docs/furniture-extract.md.
#include <chrono>
#include <filesystem>
#include <iostream>

#include "cli.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "objects_outputs.hpp"
#include "output_set.hpp"
#include "pipeline_run.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using nlohmann::json;

namespace {

int run(int argc, char** argv) {
  CLI::App cli_app{
      "furniture-extract: list the furniture objects of a scanned room (id, size, oriented box,\n"
      "height range, wall contact) and write each object's own points for recognition.\n"
      "Takes the same inputs and options as pcd-to-map.\n"};
  cli_app.footer(
      "Examples:\n"
      "  furniture-extract clouds/office/cloud.pcd -o out/objects\n"
      "  furniture-extract ../shared/data/jacobs-thermocolorlab -o out/jacobs-objects\n"
      "  furniture-extract room.ply -c my.yaml -o out   # objects.min_area_m2, crop_margin_m, ...\n"
      "  furniture-extract clouds/office/cloud.pcd --align-walls -o out/aligned   # crops too\n"
      "Outputs: objects.json, objects.csv, objects.png, objects/object_<id>.pcd (input frame;\n"
      "map frame with --align-walls), "
      "layout.pgm, map.yaml, summary.json.\n"
      "Exit codes: 0 done (also with no object: an empty list), 2 bad usage or bad input, 1 other "
      "failure.");
  app::PipelineCli cli;
  app::add_pipeline_options(cli_app, cli);
  int code = 0;
  auto setup = app::setup_pipeline_app(cli_app, cli, argc, argv, &code);
  if (!setup) return code;
  const auto& cfg = setup->config;
  const fs::path& out = setup->out;

  app::PipelineRun run = app::run_pipeline(setup->cli, setup->config, /*keep_input_points=*/true);
  const auto& m = run.map;
  double objects_ms = 0.0;
  objects::ObjectsResult objs = app::timed_objects(m, cfg.objects, &objects_ms);
  // The room border's own small objects (columns, installations) are listed too.
  double border_ms = 0.0;
  const border::BorderResult border_result = app::timed_border(m, cfg.border, &border_ms);
  const std::size_t furniture_count = objs.objects.size();
  app::add_border_objects(objs, border_result, cfg.objects.min_area_m2);

  const auto t_write = std::chrono::steady_clock::now();
  app::OutputSet set(out, "furniture-extract");  // all or nothing: docs/furniture-extract.md
  const fs::path& dir = set.dir();
  std::vector<std::string> outputs = app::write_map_outputs(dir, run, cfg);
  app::ObjectOutputs what;
  what.input_points = &run.input_points;
  what.crop_margin_m = cfg.objects.crop_margin_m;
  if (m.level.align.applied) what.crop_map_from_input = &m.level.map_from_input;
  for (auto& f : app::write_object_outputs(dir, m, objs, what)) outputs.push_back(f);

  json summary = app::summary_json("furniture-extract", run, cfg);
  summary["objects"] = {{"count", objs.objects.size()},
                        {"from_border", objs.objects.size() - furniture_count},
                        {"left_over_cells", objs.left_over_cells},
                        {"left_over_area_m2", objs.left_over_area_m2},
                        {"left_over_pieces", objs.left_over_pieces},
                        {"file", "objects.json"}};
  summary["border"] = {{"closed", border_result.closed}, {"reason", border_result.reason}};
  summary["timings_ms"]["objects"] = objects_ms;
  summary["timings_ms"]["border"] = border_ms;
  app::finish_summary(summary, dir, outputs, t_write, setup->start);
  set.commit();

  app::report("furniture-extract", run, setup->cli.quiet);
  if (!setup->cli.quiet) std::cerr << "furniture-extract: " << objs.objects.size() << " objects\n";
  std::cout << "outputs written to " << out.string() << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("furniture-extract", [&] { return run(argc, argv); });
}
