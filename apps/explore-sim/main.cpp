// explore-sim: a simulated differential-drive robot with a simulated laser explores a known map
// (any ROS map, or a plain PNG/PGM map) until no reachable frontier is left, and writes the map it
// built, its path and how the exploration went. Usage and outputs: docs/explore-sim.md.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>

#include "cli.hpp"
#include "explore_config.hpp"
#include "explore_outputs.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/exploration/coverage.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/version.hpp"
#include "map_yaml.hpp"
#include "output_set.hpp"
#include "progress.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using nlohmann::json;

namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::string format(const char* fmt, double a, double b = 0.0, double c = 0.0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}

/// The command line; exit_code is set when parsing ends the run (--help, a usage error).
struct Args {
  std::string map_path, start_s, out_dir, config_file;
  double resolution = 0.0;
  int free_min = 250;
  std::optional<std::uint32_t> seed;
  bool print_config = false, quiet = false;
  std::optional<int> exit_code;
};

Args parse_args(int argc, char** argv) {
  CLI::App cli_app{
      "explore-sim: a simulated robot with a simulated laser explores a known map until no\n"
      "reachable frontier is left. Writes map.pgm + map.yaml (the map it built), path.geojson,\n"
      "explore.json, explore.png, explore_strip.png and summary.json in the output directory.\n"};
  cli_app.footer(
      "Examples (from the repository's root, with the shared data next to it):\n"
      "  explore-sim ../shared/data/room-segmentation-maps/lab_a_scan_furnitures.png "
      "--resolution 0.05 -o out/explore\n"
      "  explore-sim out/explore/map.yaml --start 4.1,16.1,90 --seed 7 -o out/explore2\n"
      "  explore-sim --print-config > explore.yaml; explore-sim -c explore.yaml "
      "out/explore/map.yaml -q -o out/explore3\n"
      "Without --start the robot starts at the middle cell (in row-major order) of the largest\n"
      "connected region where it fits, facing +x. Headings: degrees counter-clockwise from +x.\n"
      "Exit codes: 0 done, 2 bad usage or bad input, 3 no result (the start is not in free space\n"
      "where the robot fits, so nothing is reachable), 1 other failure.");
  Args a;
  cli_app.add_option("map", a.map_path,
                     "ROS map YAML (map_server format), or a plain PNG/PGM map with --resolution");
  cli_app.add_option("--resolution", a.resolution, "Metres per pixel of a plain PNG/PGM map");
  cli_app
      .add_option("--free-min", a.free_min,
                  "Plain maps: grey levels >= this are free (default 250)")
      ->check(CLI::Range(0, 255));
  cli_app.add_option("--start", a.start_s, "Start X,Y[,DEG] in map metres (default: see below)");
  cli_app.add_option("--seed", a.seed, "Seed of the laser noise (overrides run.seed)")
      ->check(CLI::NonNegativeNumber);  // "-1" would wrap to 2^32-1
  cli_app.add_option("-o,--out", a.out_dir, "Output directory (created if missing)");
  cli_app.add_option("-c,--config", a.config_file,
                     "YAML robot, laser and exploration parameters (config/explore-sim.yaml)");
  cli_app.add_flag("--print-config", a.print_config,
                   "Print the effective parameters as YAML and exit");
  cli_app.add_flag("-q,--quiet", a.quiet, "No progress messages on stderr");
  try {
    cli_app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    a.exit_code = cli_app.exit(e) == 0 ? 0 : static_cast<int>(ExitCode::kBadInput);
  }
  return a;
}

/// --start, or the documented default; start_rule says which.
laser::Pose2d choose_start(const Args& a, const formats::RosMap& map,
                           const exploration::ExploreParams& p, std::string& start_rule) {
  const double clearance = p.robot.radius_m + p.navigator.inflation_margin_m;
  if (a.start_s.empty()) {
    const auto pts = exploration::start_points(map.cells, map.geometry, clearance, {0.5});
    if (pts.empty())
      throw Error(a.map_path + format(": no free cell is farther than %.2f m from every "
                                      "obstacle: the robot fits nowhere",
                                      clearance),
                  ExitCode::kNoResult);
    start_rule = "middle of the largest region where the robot fits";
    return {pts[0].x(), pts[0].y(), 0.0};
  }
  const planning::Pose2 s = app::parse_pose(a.start_s, "--start");
  if (!std::isfinite(s.position_map.x()) || !std::isfinite(s.position_map.y()) ||
      !map.geometry.contains(map.geometry.cell_of(s.position_map)))
    throw UsageError("--start " + a.start_s + " is outside the map");
  start_rule = "given";
  return {s.position_map.x(), s.position_map.y(),
          s.heading_deg.value_or(0.0) * std::numbers::pi / 180.0};
}

/// Progress on stderr: the explored share of the free space (a bar, or a line every few s).
std::function<void(const exploration::CoverageSample&)> progress_printer() {
  const app::ProgressReporter bar("explore-sim: explored (per mille)", "", false);
  return [bar](const exploration::CoverageSample& c) {
    bar.update(static_cast<std::int64_t>(1000.0 * c.explored_share), 1000);
  };
}

int run(int argc, char** argv) {
  const Args a = parse_args(argc, argv);
  if (a.exit_code) return *a.exit_code;
  const auto t_start = std::chrono::steady_clock::now();
  app::ExploreSimConfig cfg;
  if (!a.config_file.empty()) app::merge_explore_config_file(cfg, a.config_file);
  if (a.seed) cfg.explore.seed = *a.seed;
  app::resolve(cfg);
  if (a.print_config) {
    std::cout << app::to_yaml(cfg);
    return 0;
  }
  if (a.map_path.empty()) throw UsageError("no map given: explore-sim MAP -o DIR (see --help)");
  if (a.out_dir.empty()) throw UsageError("no output directory given: use -o DIR");
  auto t0 = std::chrono::steady_clock::now();
  formats::RosMap map = app::load_map_argument(a.map_path, a.resolution, a.free_min);
  if (cfg.unknown_is_obstacle)
    for (Cell& c : map.cells.data)
      if (c == Cell::kUnknown) c = Cell::kWall;
  const double load_ms = ms_since(t0);
  app::ExploreRunInfo info;
  info.start = choose_start(a, map, cfg.explore, info.start_rule);
  const double clearance = cfg.explore.robot.radius_m + cfg.explore.navigator.inflation_margin_m;
  if (!exploration::reachable_free_space(map.cells, map.geometry,
                                         map.geometry.cell_of(info.start.position_m()), clearance)
           .start_free)
    throw Error(format("start (%.2f, %.2f) is not in free space where the robot fits (in an "
                       "obstacle or within %.2f m of one): nothing is reachable; choose "
                       "another --start",
                       info.start.x_m, info.start.y_m, clearance),
                ExitCode::kNoResult);
  const fs::path out = a.out_dir;
  ensure_writable_dir(out);
  if (!a.quiet) {
    std::fprintf(stderr, "explore-sim: %s, %d x %d cells of %.3f m, start (%.2f, %.2f), %s rule\n",
                 a.map_path.c_str(), map.geometry.width(), map.geometry.height(),
                 map.geometry.cell_m(), info.start.x_m, info.start.y_m,
                 std::string(exploration::to_string(cfg.explore.goal.rule)).c_str());
    cfg.explore.progress = progress_printer();
  }
  t0 = std::chrono::steady_clock::now();
  const exploration::ExploreResult r =
      exploration::explore(map.cells, map.geometry, info.start, cfg.explore);
  cfg.explore.progress = nullptr;  // ends the progress bar's line
  const double explore_ms = ms_since(t0);
  if (r.status == exploration::ExploreStatus::kStartBlocked)
    throw Error("the start is blocked: nothing is reachable", ExitCode::kNoResult);

  info.map_name = fs::path(a.map_path).filename().string();
  info.rule = cfg.explore.goal.rule;
  info.seed = cfg.explore.seed;
  info.truth_cell_m = map.geometry.cell_m();
  info.control_period_s = cfg.explore.control_period_s;
  info.path_sample_every = cfg.explore.path_sample_every;
  info.strip_panels = cfg.strip_panels;
  t0 = std::chrono::steady_clock::now();
  app::OutputSet staged(out, "explore-sim");  // all or nothing: docs/explore-sim.md
  auto files = app::write_explore_files(staged.dir(), r, info);
  const double write_ms = ms_since(t0);
  const json summary = {
      {"program", "explore-sim"},
      {"version", kVersion},
      {"map", a.map_path},
      {"grid",
       {{"width", map.geometry.width()},
        {"height", map.geometry.height()},
        {"resolution_m", map.geometry.cell_m()},
        {"origin_m", {map.geometry.origin_m().x(), map.geometry.origin_m().y()}}}},
      {"start", {{"x_m", info.start.x_m}, {"y_m", info.start.y_m}, {"rule", info.start_rule}}},
      {"status", std::string(exploration::to_string(r.status))},
      {"explored_share", r.explored_share},
      {"distance_m", r.distance_m},
      {"simulated_s", r.time_s},
      {"realtime_x", r.time_s / std::max(explore_ms / 1000.0, 1e-9)},
      {"parameters", app::to_json(cfg)},
      {"timings_ms",
       {{"load", load_ms},
        {"explore", explore_ms},
        {"write", write_ms},
        {"total", ms_since(t_start)}}},
      {"outputs",
       [&] {
         auto all = files;
         all.push_back("summary.json");
         return all;
       }()},
  };
  formats::write_json(staged.dir() / "summary.json", summary);
  files.push_back("summary.json");
  staged.commit();
  if (!a.quiet) {
    const auto d95 = r.distance_to_share(0.95);
    std::fprintf(stderr,
                 "explore-sim: %s: explored %.1f %% in %.1f m, %.0f s simulated (%.0f x real "
                 "time), %zu goals, %zu frontiers blacklisted\n",
                 std::string(exploration::to_string(r.status)).c_str(), 100.0 * r.explored_share,
                 r.distance_m, r.time_s, r.time_s / std::max(explore_ms / 1000.0, 1e-9), r.goals,
                 r.blacklisted_frontiers);
    if (d95)
      std::fprintf(stderr, "explore-sim: 95 %% of the reachable free space after %.1f m\n", *d95);
    else
      std::fprintf(stderr, "explore-sim: 95 %% of the reachable free space not reached\n");
    std::cout << "outputs written to " << out.string() << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("explore-sim", [&] { return run(argc, argv); });
}
