// scene-sim: synthetic terrestrial laser scans of furnished rooms, with ground truth.
// See docs/scene-sim.md.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/sim/building.hpp"
#include "indoormap/sim/mobile.hpp"
#include "indoormap/sim/random_scene.hpp"
#include "indoormap/sim/simulate.hpp"
#include "indoormap/sim/world.hpp"
#include "indoormap/version.hpp"
#include "main_guard.hpp"
#include "output_set.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "report.hpp"
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
  int rooms = 0, storeys = 0;
  bool mobile = false;
  double sector_deg = -1, step_deg = 0, truth_cell = 0, mobile_step = 0, mobile_share = 0;
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
      "  scene-sim --random --seed 7 --rooms 3 --step-deg 0.5 -o out/scene7 --3dtk --sector-deg "
      "40\n"
      "  scene-sim --random --seed 3 --rooms 4 --storeys 2 --step-deg 0.5 -o out/tower --3dtk\n"
      "  scene-sim --random --seed 4 --rooms 2 --mobile -o out/walk\n"
      "  scene-sim scenes/office.yaml --print-config\n"
      "Outputs in DIR: cloud.pcd, ground_truth.json, ground_truth_layout.{pgm,png,yaml}, "
      "ground_truth_seen.{pgm,yaml},\n"
      "summary.json, with --3dtk a 3dtk/ scan directory, with --mobile trajectory.txt (TUM); with "
      "--storeys S > 1\n"
      "the truth of storey k in storey_<k>/. Exit codes: 0 done, 2 bad usage or input, 1 other.");
  Args a;
  app.add_option("scene", a.scene_file, "Scene description (YAML, see docs/scene-sim.md)");
  app.add_flag("--random", a.random, "Generate a plausible random scene instead of reading one");
  auto* seed_opt = app.add_option("--seed", a.seed,
                                  "Seed of the random scene and of the noise (default 1; for a "
                                  "scene file it overrides the file's seed)")
                       ->check(CLI::NonNegativeNumber);  // "-1" would wrap to 2^64-1
  app.add_option("--rooms", a.rooms, "Random scene: number of furnished rooms (default 1)")
      ->check(CLI::Range(1, 200));
  app.add_option("--storeys", a.storeys,
                 "Storeys stacked on slabs (random: each its own rooms; scene file: copies)")
      ->check(CLI::Range(1, 20));
  app.add_flag("--mobile", a.mobile,
               "Mobile scanner: a path through every room, sparse rays every --mobile-step-m");
  app.add_option("--mobile-step-m", a.mobile_step, "Mobile: metres between positions (0.5)")
      ->check(CLI::Range(0.05, 10.0));
  app.add_option("--mobile-ray-share", a.mobile_share,
                 "Mobile: rays per position as a share of the terrestrial pattern (0.06)")
      ->check(CLI::Range(1e-6, 1.0));
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
                                    const sim::Building& building, const sim::SimResult& result,
                                    const std::vector<scene_sim::StoreyTruth>& truths,
                                    const std::vector<std::string>& files, double sim_s,
                                    double write_s) {
  const sim::Scene& scene = building.storeys.front().scene;
  nlohmann::ordered_json summary;
  summary["app"] = "scene-sim";
  summary["version"] = kVersion;
  summary["provenance"] =
      app::provenance_json(a.random ? std::vector<std::string>{} : std::vector{a.scene_file});
  summary["scene"] = a.random ? "random" : a.scene_file;
  summary["seed"] = scene.seed;
  if (a.random) summary["rooms"] = config.random.rooms;
  summary["points"] = result.points.size();
  summary["rays"] = result.rays;
  summary["mixed_pixels"] = result.mixed_pixels;
  summary["scans"] = result.scans.size();
  summary["storeys"] = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < building.storeys.size(); ++k) {
    const auto& st = building.storeys[k];
    summary["storeys"].push_back({{"k", k},
                                  {"floor_z_m", st.floor_z_m},
                                  {"ceiling_z_m", st.ceiling_z_m},
                                  {"scanner_positions", st.scene.scanners.size()},
                                  {"seen_cells", sim::seen_count(truths[k].seen)}});
  }
  summary["mobile"] = config.mobile;
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
      {"mixed_pixel_min_jump_m", config.scanner.mixed_pixel_min_jump_m},
      {"coordinate_step_m", config.scanner.coordinate_step_m}};
  summary["parameters"]["output"] = {{"truth_cell_m", config.output.truth_cell_m},
                                     {"3dtk", config.output.write_3dtk},
                                     {"sector_deg", config.sector_deg}};
  summary["parameters"]["building"] = {{"storeys", config.storeys},
                                       {"slab_thickness_m", config.slab_thickness_m},
                                       {"same_footprint", config.same_footprint}};
  summary["parameters"]["seen"] = {{"min_height_m", config.seen.min_height_m},
                                   {"max_height_m", config.seen.max_height_m}};
  if (config.mobile) {
    const auto& m = config.mobile_params;
    summary["parameters"]["mobile"] = {{"step_m", m.step_m},
                                       {"ray_share", m.ray_share},
                                       {"beams", m.beams},
                                       {"elevation_min_deg", m.elevation_min_deg},
                                       {"elevation_max_deg", m.elevation_max_deg},
                                       {"sensor_height_m", m.sensor_height_m},
                                       {"clearance_m", m.clearance_m},
                                       {"speed_m_s", m.speed_m_s}};
  }
  summary["outputs"] = files;
  summary["timings_s"] = {{"simulate", sim_s}, {"write", write_s}};
  summary["points_per_second"] = sim_s > 0 ? result.points.size() / sim_s : 0.0;
  return summary;
}

/// The building to simulate: a random one, or the scene file stacked config.storeys times.
sim::Building make_building(const Args& a, scene_sim::Config& config) {
  if (a.random) {
    sim::BuildingParams bp;
    bp.random = config.random;
    bp.storeys = config.storeys;
    bp.slab_thickness_m = config.slab_thickness_m;
    bp.same_footprint = config.same_footprint;
    sim::Building b = sim::random_building(a.seed, bp);
    for (auto& st : b.storeys) st.scene.scanner = config.scanner;
    return b;
  }
  auto parsed = scene_sim::parse_scene_file(a.scene_file, config.scanner);
  sim::Scene scene = std::move(parsed.scene);
  if (a.seed_given) scene.seed = a.seed;
  if (a.step_deg > 0)
    scene.scanner.azimuth_step_deg = scene.scanner.elevation_step_deg = a.step_deg;
  check_scene_or_throw(scene, parsed.key_lines, a.scene_file);
  std::vector<sim::Scene> copies;
  for (int k = 0; k < config.storeys; ++k) {
    copies.push_back(scene);
    copies.back().seed = scene.seed + 7919ULL * static_cast<std::uint64_t>(k);
  }
  return sim::stack_storeys(std::move(copies), config.slab_thickness_m);
}

/// Mobile mode: every storey's scanners become the planned path's poses.
void plan_paths(sim::Building& b, const scene_sim::Config& config, bool quiet) {
  const auto paths = sim::plan_mobile_paths(b, config.mobile_params, config.output.truth_cell_m);
  for (std::size_t k = 0; k < paths.size(); ++k) {
    if (paths[k].unreached > 0)
      std::fprintf(stderr,
                   "scene-sim: warning: storey %zu: the mobile path finds no way into %d room(s)\n",
                   k, paths[k].unreached);
    if (!quiet)
      std::fprintf(stderr, "scene-sim: storey %zu: mobile path %.1f m, %zu positions, %d room(s)\n",
                   k, paths[k].length_m, paths[k].poses.size(), paths[k].rooms_visited);
  }
}

int run(int argc, char** argv) {
  const Args a = parse_args(argc, argv);
  if (a.exit_code) return *a.exit_code;
  scene_sim::Config config;
  if (!a.config_file.empty()) scene_sim::apply_config_file(a.config_file, config);
  if (a.rooms > 0) config.random.rooms = a.rooms;
  if (a.storeys > 0) config.storeys = a.storeys;
  if (a.mobile) config.mobile = true;
  if (a.mobile_step > 0) config.mobile_params.step_m = a.mobile_step;
  if (a.mobile_share > 0) config.mobile_params.ray_share = a.mobile_share;
  if (a.tdtk) config.output.write_3dtk = true;
  if (a.sector_deg >= 0) config.sector_deg = a.sector_deg;
  if (a.truth_cell > 0) config.output.truth_cell_m = a.truth_cell;
  sim::validate(config.mobile_params);
  sim::validate(config.seen);
  if (config.storeys < 1 || config.storeys > 20)
    throw UsageError("building.storeys must be in [1, 20]");

  if (a.random == !a.scene_file.empty())
    throw UsageError("give either a scene file or --random (see --help)");
  if (!a.random && a.rooms > 0) throw UsageError("--rooms applies to --random only");
  if (a.random) {
    sim::validate(config.random);
    if (a.step_deg > 0)
      config.scanner.azimuth_step_deg = config.scanner.elevation_step_deg = a.step_deg;
  }
  if (a.print_config) {
    if (!a.random) {
      config.scanner = scene_sim::parse_scene_file(a.scene_file, config.scanner).scene.scanner;
      if (a.step_deg > 0)
        config.scanner.azimuth_step_deg = config.scanner.elevation_step_deg = a.step_deg;
    }
    std::cout << scene_sim::config_to_yaml(config);
    return 0;
  }
  if (a.out_dir.empty()) throw UsageError("--out DIR is required (see --help)");
  sim::Building building = make_building(a, config);
  config.scanner = building.storeys.front().scene.scanner;
  if (a.random)
    check_scene_or_throw(building.storeys.front().scene, {},
                         "<random scene, seed " + std::to_string(a.seed) + ">");

  ensure_writable_dir(a.out_dir);
  const auto t0 = std::chrono::steady_clock::now();
  if (config.mobile) plan_paths(building, config, a.quiet);
  sim::SimOptions sim_options;
  sim_options.sector_deg = config.sector_deg;
  std::int64_t all_rays = 0;
  for (const auto& st : building.storeys) {
    const sim::Scene& scene = st.scene;
    const std::uint64_t rays =
        config.mobile ? sim::mobile_ray_count(scene, config.mobile_params) : sim::ray_count(scene);
    all_rays += static_cast<std::int64_t>(rays);
    if (!a.quiet)
      std::fprintf(
          stderr,
          "scene-sim: %s: %zu room(s), %zu furniture item(s), %zu scanner position(s), %llu rays\n",
          scene.name.c_str(), scene.rooms.size(), scene.furniture.size(), scene.scanners.size(),
          static_cast<unsigned long long>(rays));
  }
  const app::ProgressReporter bar("scene-sim: casting rays", "rays", a.quiet);
  if (bar.active()) {  // one bar over all storeys: each storey's count starts at 0 again
    auto base = std::make_shared<std::int64_t>(0);
    sim_options.progress = [bar, base, all_rays](std::int64_t done, std::int64_t total) {
      bar.update(*base + done, all_rays);
      if (total > 0 && done >= total) *base += total;
    };
  }
  const sim::BuildingSim bsim =
      sim::simulate_storeys(building, sim_options, config.mobile ? &config.mobile_params : nullptr);
  const sim::SimResult& result = bsim.sim;
  const auto t1 = std::chrono::steady_clock::now();
  if (result.points.empty()) {
    std::fprintf(stderr,
                 "scene-sim: no point was returned (every ray missed or was out of range)\n");
    return static_cast<int>(ExitCode::kNoResult);
  }
  const auto truths = sim::storey_truths(building, bsim, config.output.truth_cell_m, config.seen);
  sim::OutputOptions out_options = config.output;
  app::OutputSet set(a.out_dir, "scene-sim");  // all or nothing: docs/scene-sim.md, "Outputs"
  const auto written = scene_sim::write_building_outputs(
      set.dir(), building, bsim, truths, out_options,
      config.mobile ? std::optional(config.mobile_params) : std::nullopt);
  const auto t2 = std::chrono::steady_clock::now();

  const double sim_s = std::chrono::duration<double>(t1 - t0).count();
  const double write_s = std::chrono::duration<double>(t2 - t1).count();
  std::vector<std::string> files = written.files;
  files.push_back(app::kReportFile);
  files.push_back("summary.json");
  const nlohmann::ordered_json summary =
      summary_json(a, config, building, result, truths, files, sim_s, write_s);
  write_file_atomic(set.dir() / "summary.json", summary.dump(2) + "\n");
  app::write_report(set.dir(), nlohmann::json(summary), files);
  set.commit();
  if (!a.quiet)
    std::fprintf(stderr, "scene-sim: %zu points (%.1f M points/s), outputs in %s\n",
                 result.points.size(), sim_s > 0 ? result.points.size() / sim_s / 1e6 : 0.0,
                 a.out_dir.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("scene-sim", argc, argv, [&] { return run(argc, argv); });
}
