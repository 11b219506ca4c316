// scene-sim: synthetic terrestrial laser scans of furnished rooms, with ground truth.
// See docs/scene-sim.md.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/sim/random_scene.hpp"
#include "indoormap/sim/simulate.hpp"
#include "indoormap/version.hpp"
#include "main_guard.hpp"
#include "output_set.hpp"
#include "scene_outputs.hpp"
#include "scene_yaml.hpp"

namespace fs = std::filesystem;
using namespace indoormap;

namespace {

/// The command line; exit_code is set when parsing ends the run (--help, a usage error).
struct Args {
  std::string scene_file, out_dir, config_file;
  bool random = false, print_config = false, tdtk = false, quiet = false;
  std::uint64_t seed = 1;
  bool seed_given = false;
  int rooms = 0;
  double sector_deg = -1, step_deg = 0, truth_cell = 0;
  std::optional<int> exit_code;
};

Args parse_args(int argc, char** argv) {
  CLI::App app{
      "scene-sim: simulates a terrestrial laser scanner (Riegl VZ-400 like) in a furnished indoor "
      "scene "
      "and writes the cloud with its ground truth."};
  app.footer(
      "Examples:\n"
      "  scene-sim scenes/office.yaml -o clouds/office\n"
      "  scene-sim --random --seed 7 --rooms 3 -o /tmp/scene7 --3dtk --sector-deg 40\n"
      "  scene-sim scenes/office.yaml --print-config\n"
      "Outputs in DIR: cloud.pcd, ground_truth.json, ground_truth_layout.{pgm,png,yaml}, "
      "summary.json,\n"
      "and with --3dtk a 3dtk/ scan directory. Exit codes: 0 done, 2 bad usage or input, 1 other.");
  Args a;
  app.add_option("scene", a.scene_file, "Scene description (YAML, see docs/scene-sim.md)");
  app.add_flag("--random", a.random, "Generate a plausible random scene instead of reading one");
  auto* seed_opt = app.add_option("--seed", a.seed,
                                  "Seed of the random scene and of the noise (default 1; for a "
                                  "scene file it overrides the file's seed)")
                       ->check(CLI::NonNegativeNumber);  // "-1" would wrap to 2^64-1
  app.add_option("--rooms", a.rooms, "Random scene: number of furnished rooms (default 1)")
      ->check(CLI::Range(1, 200));
  app.add_option("-o,--out", a.out_dir, "Output directory (created if needed)");
  app.add_option("-c,--config", a.config_file,
                 "Config file (YAML; keys scanner, output, random; see config/scene-sim.yaml)");
  app.add_flag("--3dtk", a.tdtk, "Also write a 3DTK scan directory DIR/3dtk (scanNNN.3d + .pose)");
  app.add_option("--sector-deg", a.sector_deg,
                 "Split every position into scans of this many degrees (3DTK; 0: whole turn)")
      ->check(CLI::Range(0.0, 360.0));
  app.add_option("--step-deg", a.step_deg, "Angular step, azimuth and elevation (degrees)")
      ->check(CLI::Range(0.005, 10.0));
  app.add_option("--truth-cell", a.truth_cell,
                 "Cell of the ground-truth layout (metres, default 0.05)")
      ->check(CLI::Range(0.001, 10.0));
  app.add_flag("--print-config", a.print_config, "Print the effective parameters as YAML and exit");
  app.add_flag("-q,--quiet", a.quiet, "No progress messages");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    a.exit_code = app.exit(e) == 0 ? 0 : static_cast<int>(ExitCode::kBadInput);
  }
  a.seed_given = seed_opt->count() > 0;
  return a;
}

/// Semantic checks of the scene: the first problem as InputError(file, key, YAML line of the
/// offending key or its closest parent in key_lines).
void check_scene_or_throw(const sim::Scene& scene,
                          const std::map<std::string, std::size_t>& key_lines,
                          const std::string& file) {
  const auto problems = sim::check_scene(scene);
  if (problems.empty()) return;
  const auto& p = problems.front();
  std::string key = p.key;
  std::size_t line = 0;
  while (!key.empty()) {
    if (auto it = key_lines.find(key); it != key_lines.end()) {
      line = it->second;
      break;
    }
    const auto cut = key.find_last_of(".[");
    key = cut == std::string::npos ? "" : key.substr(0, cut);
  }
  throw InputError(file, "key '" + p.key + "': " + p.problem, line);
}

/// summary.json: what was simulated, with which parameters, and how long it took.
nlohmann::ordered_json summary_json(const Args& a, const scene_sim::Config& config,
                                    const sim::Scene& scene, const sim::SimResult& result,
                                    const std::vector<std::string>& files, double sim_s,
                                    double write_s) {
  nlohmann::ordered_json summary;
  summary["app"] = "scene-sim";
  summary["version"] = kVersion;
  summary["scene"] = a.random ? "random" : a.scene_file;
  summary["seed"] = scene.seed;
  if (a.random) summary["rooms"] = config.random.rooms;
  summary["points"] = result.points.size();
  summary["rays"] = result.rays;
  summary["mixed_pixels"] = result.mixed_pixels;
  summary["scans"] = result.scans.size();
  summary["parameters"] = nlohmann::ordered_json::object();
  summary["parameters"]["scanner"] = {
      {"azimuth_step_deg", config.scanner.azimuth_step_deg},
      {"elevation_step_deg", config.scanner.elevation_step_deg},
      {"elevation_min_deg", config.scanner.elevation_min_deg},
      {"elevation_max_deg", config.scanner.elevation_max_deg},
      {"range_min_m", config.scanner.range_min_m},
      {"range_max_m", config.scanner.range_max_m},
      {"range_sigma_m", config.scanner.range_sigma_m},
      {"mixed_pixel_probability", config.scanner.mixed_pixel_probability},
      {"mixed_pixel_min_jump_m", config.scanner.mixed_pixel_min_jump_m}};
  summary["parameters"]["output"] = {{"truth_cell_m", config.output.truth_cell_m},
                                     {"3dtk", config.output.write_3dtk},
                                     {"sector_deg", config.sector_deg}};
  summary["outputs"] = files;
  summary["timings_s"] = {{"simulate", sim_s}, {"write", write_s}};
  summary["points_per_second"] = sim_s > 0 ? result.points.size() / sim_s : 0.0;
  return summary;
}

int run(int argc, char** argv) {
  const Args a = parse_args(argc, argv);
  if (a.exit_code) return *a.exit_code;
  scene_sim::Config config;
  if (!a.config_file.empty()) scene_sim::apply_config_file(a.config_file, config);
  if (a.rooms > 0) config.random.rooms = a.rooms;
  if (a.tdtk) config.output.write_3dtk = true;
  if (a.sector_deg >= 0) config.sector_deg = a.sector_deg;
  if (a.truth_cell > 0) config.output.truth_cell_m = a.truth_cell;

  if (a.random == !a.scene_file.empty())
    throw UsageError("give either a scene file or --random (see --help)");
  if (!a.random && a.rooms > 0) throw UsageError("--rooms applies to --random only");

  sim::Scene scene;
  std::map<std::string, std::size_t> key_lines;
  if (a.random) {
    scene = sim::random_scene(a.seed, config.random);
    scene.scanner = config.scanner;
  } else {
    auto parsed = scene_sim::parse_scene_file(a.scene_file, config.scanner);
    scene = std::move(parsed.scene);
    key_lines = std::move(parsed.key_lines);
    if (a.seed_given) scene.seed = a.seed;
  }
  if (a.step_deg > 0)
    scene.scanner.azimuth_step_deg = scene.scanner.elevation_step_deg = a.step_deg;
  config.scanner = scene.scanner;

  if (a.print_config) {
    std::cout << scene_sim::config_to_yaml(config);
    return 0;
  }
  if (a.out_dir.empty()) throw UsageError("--out DIR is required (see --help)");

  check_scene_or_throw(
      scene, key_lines,
      a.random ? "<random scene, seed " + std::to_string(a.seed) + ">" : a.scene_file);

  ensure_writable_dir(a.out_dir);
  const auto t0 = std::chrono::steady_clock::now();
  sim::SimOptions sim_options;
  sim_options.sector_deg = config.sector_deg;
  if (!a.quiet)
    std::fprintf(
        stderr,
        "scene-sim: %s: %zu room(s), %zu furniture item(s), %zu scanner position(s), %llu rays\n",
        scene.name.c_str(), scene.rooms.size(), scene.furniture.size(), scene.scanners.size(),
        static_cast<unsigned long long>(sim::ray_count(scene)));
  const sim::SimResult result = sim::simulate(scene, sim_options);
  const auto t1 = std::chrono::steady_clock::now();
  if (result.points.empty()) {
    std::fprintf(stderr,
                 "scene-sim: no point was returned (every ray missed or was out of range)\n");
    return static_cast<int>(ExitCode::kNoResult);
  }
  sim::OutputOptions out_options = config.output;
  app::OutputSet set(a.out_dir, "scene-sim");  // all or nothing: docs/scene-sim.md, "Outputs"
  const auto written = scene_sim::write_scene_outputs(set.dir(), scene, result, out_options);
  const auto t2 = std::chrono::steady_clock::now();

  const double sim_s = std::chrono::duration<double>(t1 - t0).count();
  const double write_s = std::chrono::duration<double>(t2 - t1).count();
  const nlohmann::ordered_json summary =
      summary_json(a, config, scene, result, written.files, sim_s, write_s);
  write_file_atomic(set.dir() / "summary.json", summary.dump(2) + "\n");
  set.commit();
  if (!a.quiet)
    std::fprintf(stderr, "scene-sim: %zu points (%.1f M points/s), outputs in %s\n",
                 result.points.size(), sim_s > 0 ? result.points.size() / sim_s / 1e6 : 0.0,
                 a.out_dir.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("scene-sim", [&] { return run(argc, argv); });
}
