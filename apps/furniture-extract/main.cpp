// furniture-extract: the furniture objects of a scanned room, with their size, place and height,
// and each object's own points for a recogniser. Usage and outputs: docs/furniture-extract.md.
#include <chrono>
#include <filesystem>
#include <iostream>

#include "cli.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/io/map_io.hpp"
#include "objects_outputs.hpp"
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
      "Outputs: objects.json, objects.csv, objects.png, objects/object_<id>.pcd (input frame),\n"
      "layout.pgm, map.yaml, summary.json.\n"
      "Exit codes: 0 done (also with no object: an empty list), 2 bad usage or bad input, 1 other failure.");
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

  app::PipelineRun run = app::run_pipeline(cli, cfg, /*keep_input_points=*/true);
  const auto& m = run.map;
  const auto t_objects = std::chrono::steady_clock::now();
  const objects::ObjectsResult objs =
      objects::extract_objects(m.layout.layout, m.geometry, m.voxels, m.layers, cfg.objects);
  const double objects_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_objects).count();

  const auto t_write = std::chrono::steady_clock::now();
  std::vector<std::string> outputs = app::write_map_outputs(out, run);
  app::ObjectOutputs what;
  what.input_points = &run.input_points;
  what.crop_margin_m = cfg.objects.crop_margin_m;
  for (auto& f : app::write_object_outputs(out, m, objs, what)) outputs.push_back(f);

  json summary = app::summary_json("furniture-extract", run, cfg);
  summary["objects"] = {{"count", objs.objects.size()}, {"file", "objects.json"}};
  summary["timings_ms"]["objects"] = objects_ms;
  summary["timings_ms"]["write"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_write).count();
  summary["timings_ms"]["total"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_start).count();
  outputs.push_back("summary.json");
  summary["outputs"] = outputs;
  io::write_json(out / "summary.json", summary);

  app::report("furniture-extract", run);
  std::cerr << "furniture-extract: " << objs.objects.size() << " objects\n";
  std::cout << "outputs written to " << out.string() << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("furniture-extract", [&] { return run(argc, argv); });
}
