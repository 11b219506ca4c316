// grid-areas: splits a 2D grid map (ROS map.yaml, or a PNG / PGM with --resolution) into rooms,
// corridors and crossings: polygons (areas.geojson), a graph (areas.json), a label image, a
// picture and Nav2 costmap-filter masks; --score GT.png scores the rooms against a ground truth
// (Bormann et al.). Usage, options and figures: docs/grid-areas.md.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "areas_config.hpp"
#include "areas_outputs.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/version.hpp"
#include "main_guard.hpp"
#include "map_yaml.hpp"
#include "output_set.hpp"
#include "provenance.hpp"
#include "report.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using nlohmann::json;

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

struct Args {
  std::string map_path, out_dir, config_file, truth_path;
  double resolution_m = 0.0;
  bool print_config = false, quiet = false;
  std::optional<int> exit_code;
};

Args parse_args(int argc, char** argv) {
  CLI::App cli{
      "grid-areas: split a 2D grid map into rooms, corridors and crossings for a robot of a "
      "given\nfootprint. Writes areas.geojson, areas.json, areas_labels.png, areas.png, the Nav2 "
      "speed and\nkeepout masks (speed_mask.*, keepout_mask.*, *_filter_info.yaml) and "
      "summary.json.\n"};
  cli.footer(
      "Examples:\n"
      "  grid-areas ../shared/data/room-segmentation-maps/office_a_furnitures.png --resolution "
      "0.05 -o out/office_a\n"
      "  grid-areas ../shared/data/room-segmentation-maps/lab_a_scan_furnitures.png --resolution "
      "0.05 \\\n"
      "      --score ../shared/data/room-segmentation-maps/lab_a_scan_gt_segmentation.png -o "
      "out/lab_a\n"
      "  grid-areas out/map.yaml -o out/areas   # a ROS map: pcd-to-map clouds/office/cloud.pcd -o "
      "out\n"
      "  grid-areas --print-config > areas.yaml\n"
      "Exit codes: 0 done, 2 bad usage or bad input (the message names the file; nothing is "
      "written),\n"
      "3 no result (the footprint fits nowhere in the free space), 1 other failure.");
  Args a;
  cli.add_option("map", a.map_path, "ROS map YAML, or a PNG / PGM image (then --resolution)");
  cli.add_option("-o,--out", a.out_dir, "Output directory (created if missing)");
  cli.add_option("-c,--config", a.config_file,
                 "YAML parameters (defaults: config/grid-areas.yaml)");
  cli.add_option("--resolution", a.resolution_m, "Metres per pixel of a PNG / PGM map");
  cli.add_option("--score", a.truth_path,
                 "Ground-truth segmentation image (*_gt_segmentation.png): writes score.json");
  cli.add_flag("-q,--quiet", a.quiet, "No progress or figures on stderr (errors only)");
  cli.add_flag("--print-config", a.print_config, "Print the effective parameters as YAML and exit");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    a.exit_code = cli.exit(e) == 0 ? 0 : static_cast<int>(ExitCode::kBadInput);
  }
  return a;
}

/// The true rooms of a ground-truth image of the map's size.
Grid<int> read_truth(const std::string& path, const app::GridAreasRun& run) {
  if (!fs::exists(path)) throw InputError(path, "no such file");
  const formats::RosMap gt =
      formats::read_plain_map(path, run.map.geometry.cell_m(), run.config.free_min);
  if (gt.cells.width != run.map.cells.width || gt.cells.height != run.map.cells.height)
    throw InputError(path, "ground truth is " + std::to_string(gt.cells.width) + " x " +
                               std::to_string(gt.cells.height) + " pixels, the map " +
                               std::to_string(run.map.cells.width) + " x " +
                               std::to_string(run.map.cells.height));
  Grid<std::uint8_t> grey(gt.cells.width, gt.cells.height, 0);
  for (std::size_t i = 0; i < grey.size(); ++i)
    grey.data[i] = gt.cells.data[i] == Cell::kFree ? 255 : 0;
  return areas::truth_rooms(grey);
}

int run(int argc, char** argv) {
  const Args a = parse_args(argc, argv);
  if (a.exit_code) return *a.exit_code;
  const auto t_start = Clock::now();
  app::GridAreasRun run;
  if (!a.config_file.empty()) app::merge_grid_areas_config_file(run.config, a.config_file);
  app::validate(run.config);
  if (a.print_config) {
    std::cout << app::to_yaml(run.config);
    return 0;
  }
  if (a.map_path.empty()) throw UsageError("no map given: grid-areas MAP -o DIR (see --help)");
  if (a.out_dir.empty()) throw UsageError("no output directory given: use -o DIR");
  if (!fs::exists(a.map_path)) throw InputError(a.map_path, "no such file");
  run.map_path = a.map_path;
  run.map = app::load_map_argument(a.map_path, a.resolution_m, run.config.free_min);
  const fs::path out = a.out_dir;
  ensure_writable_dir(out);
  if (!a.quiet)
    std::cerr << "grid-areas: " << a.map_path << ": " << run.map.cells.width << " x "
              << run.map.cells.height << " cells of " << run.map.geometry.cell_m()
              << " m; splitting\n";

  auto t0 = Clock::now();
  run.result = areas::split_areas(run.map.cells, run.map.geometry, run.config.areas);
  run.split_ms = ms_since(t0);
  if (run.result.free_cells == 0)
    throw InputError(a.map_path, "the map has no free cell (free: grey level >= " +
                                     std::to_string(run.config.free_min) +
                                     " in a plain image, below free_thresh in a ROS map)");
  if (run.result.reachable_cells == 0) {
    const auto& fp = run.config.areas.footprint;
    std::cerr << "grid-areas: " << a.map_path << ": the footprint (" << fp.robot_width_m << " x "
              << fp.robot_length_m << " m) fits nowhere: no free space is wide enough; nothing "
              << "written\n";
    return static_cast<int>(ExitCode::kNoResult);
  }
  if (!a.truth_path.empty()) {
    t0 = Clock::now();
    run.truth_path = a.truth_path;
    Grid<int> found(run.result.labels.width, run.result.labels.height, 0);
    for (std::size_t i = 0; i < found.size(); ++i) found.data[i] = run.result.labels.data[i];
    run.score = areas::score_segmentation(read_truth(a.truth_path, run), found);
    run.score_ms = ms_since(t0);
  }

  const auto t_write = Clock::now();
  app::OutputSet set(out, "grid-areas");  // all or nothing: docs/grid-areas.md, "Outputs"
  auto files = app::write_grid_areas_outputs(set.dir(), run);
  files.push_back(app::kReportFile);
  files.push_back("summary.json");
  std::vector<std::string> inputs = app::map_argument_files(a.map_path);
  if (!a.truth_path.empty()) inputs.push_back(a.truth_path);
  const json summary = {
      {"program", "grid-areas"},
      {"version", kVersion},
      {"provenance", app::provenance_json(inputs)},
      {"map", a.map_path},
      {"parameters", app::to_json(run.config)},
      {"result", app::areas_summary_json(run)},
      {"timings_ms",
       {{"split", run.split_ms},
        {"score", run.score_ms},
        {"write", ms_since(t_write)},
        {"total", ms_since(t_start)}}},
      {"outputs", files},
  };
  formats::write_json(set.dir() / "summary.json", summary);
  app::write_report(set.dir(), summary, files);
  set.commit();
  if (!a.quiet) {
    const json s = app::areas_summary_json(run);
    char line[256];
    std::snprintf(line, sizeof line, "%d rooms, %d corridors, %d crossings, %zu doors in %.0f ms",
                  s["rooms"].get<int>(), s["corridors"].get<int>(), s["crossings"].get<int>(),
                  run.result.doors.size(), run.split_ms);
    std::cerr << "grid-areas: " << line << "\n";
    if (run.score)
      std::cerr << "grid-areas: score against " << a.truth_path << ": recall "
                << 100.0 * run.score->recall << " %, precision " << 100.0 * run.score->precision
                << " %\n";
    std::cout << "outputs written to " << out.string() << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("grid-areas", argc, argv, [&] { return run(argc, argv); });
}
