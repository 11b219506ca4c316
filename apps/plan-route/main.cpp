// plan-route: a route of "turn, then go straight" commands on any ROS map (or plain map image),
// through the safe zone of a robot of the configured size. Usage and outputs: docs/plan-route.md.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "cli.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/version.hpp"
#include "map_yaml.hpp"
#include "output_set.hpp"
#include "plan_config.hpp"
#include "progress.hpp"
#include "route_files.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using nlohmann::json;

namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

/// The command line; exit_code is set when parsing ends the run (--help, a usage error).
struct Args {
  std::string map_path, start_s, goal_s, out_dir, config_file;
  double resolution = 0.0;
  int free_min = 250;
  bool print_config = false;
  bool quiet = false;
  std::optional<int> exit_code;
};

Args parse_args(int argc, char** argv) {
  CLI::App cli_app{
      "plan-route: plan a route of 'turn, then go straight' commands through the safe zone of a "
      "robot.\n"
      "Writes route.json, route.png, safe.pgm + safe.yaml and summary.json in the output "
      "directory.\n"};
  cli_app.footer(
      "Examples:\n"
      "  plan-route --map out/jacobs/map.yaml --start 1.0,2.0,90 --goal 4.5,3.0 -o out/route\n"
      "  plan-route --map building.png --resolution 0.05 --start 10,5 --goal 30,12,180 -o out/r\n"
      "  plan-route --print-config > robot.yaml; plan-route -c robot.yaml --map map.yaml ...\n"
      "Headings: degrees counter-clockwise from the map's +x axis. Without one, the robot is taken "
      "to\n"
      "face its first move.\n"
      "Exit codes: 0 route found, 2 bad usage or bad input (e.g. start in the unsafe zone), 3 no "
      "route,\n"
      "1 other failure.");
  Args a;
  cli_app.add_option("--map", a.map_path,
                     "ROS map YAML (map_server format), or a plain PNG/PGM map with --resolution");
  cli_app.add_option("--resolution", a.resolution, "Metres per pixel of a plain PNG/PGM map");
  cli_app
      .add_option("--free-min", a.free_min,
                  "Plain maps: grey levels >= this are free (default 250)")
      ->check(CLI::Range(0, 255));
  cli_app.add_option("--start", a.start_s,
                     "Start X,Y[,DEG] in map metres (DEG: the robot's heading)");
  cli_app.add_option("--goal", a.goal_s, "Goal X,Y[,DEG] in map metres (DEG: final heading)");
  cli_app.add_option("-o,--out", a.out_dir, "Output directory (created if missing)");
  cli_app.add_option("-c,--config", a.config_file,
                     "YAML robot and planner parameters (config/plan-route.yaml)");
  cli_app.add_flag("--print-config", a.print_config,
                   "Print the effective parameters as YAML and exit");
  cli_app.add_flag("-q,--quiet", a.quiet, "No progress or run report on stderr (errors stay)");
  try {
    cli_app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    a.exit_code = cli_app.exit(e) == 0 ? 0 : static_cast<int>(ExitCode::kBadInput);
  }
  return a;
}

int run(int argc, char** argv) {
  const Args a = parse_args(argc, argv);
  if (a.exit_code) return *a.exit_code;
  const auto t_start = std::chrono::steady_clock::now();
  app::PlanConfig cfg;
  if (!a.config_file.empty()) app::merge_plan_config_file(cfg, a.config_file);
  app::validate(cfg);
  if (a.print_config) {
    std::cout << app::to_yaml(cfg);
    return 0;
  }
  if (a.map_path.empty()) throw UsageError("no map given: use --map map.yaml (see --help)");
  if (a.start_s.empty() || a.goal_s.empty())
    throw UsageError("both --start X,Y[,DEG] and --goal X,Y[,DEG] are needed");
  if (a.out_dir.empty()) throw UsageError("no output directory given: use -o DIR");
  const planning::Pose2 start = app::parse_pose(a.start_s, "--start");
  const planning::Pose2 goal = app::parse_pose(a.goal_s, "--goal");
  const fs::path out = a.out_dir;
  ensure_writable_dir(out);

  auto t0 = std::chrono::steady_clock::now();
  const formats::RosMap map = app::load_map_argument(a.map_path, a.resolution, a.free_min);
  const double load_ms = ms_since(t0);

  t0 = std::chrono::steady_clock::now();
  const planning::Templates templates = [&] {
    try {
      return planning::make_templates(cfg.robot, cfg.planner, map.geometry.cell_m());
    } catch (const BudgetError& e) {  // the resolution is the map file's: name it
      throw InputError(a.map_path, e.what());
    }
  }();
  const double templates_ms = ms_since(t0);
  t0 = std::chrono::steady_clock::now();
  const auto safe = planning::safe_zone(map.cells, templates.disk, cfg.safe_zone);
  const double safe_ms = ms_since(t0);
  if (!a.quiet) {
    std::fprintf(
        stderr, "plan-route: %s: %d x %d cells of %.3f m; searching (budget %lld nodes, %g s)\n",
        a.map_path.c_str(), map.geometry.width(), map.geometry.height(), map.geometry.cell_m(),
        static_cast<long long>(cfg.planner.max_nodes), cfg.planner.max_seconds);
    // One reporter per search (the planner calls about once a second; the total is unknown).
    auto current = std::make_shared<std::pair<std::string, app::ProgressReporter>>(
        "", app::ProgressReporter("", "", true));
    cfg.planner.progress = [current](const char* search, std::int64_t nodes, double) {
      if (current->first != search) {
        current->second.finish();
        *current = {search, app::ProgressReporter(std::string("plan-route: ") + search + " search",
                                                  "nodes", false)};
      }
      current->second.update(nodes, 0);
    };
  }
  t0 = std::chrono::steady_clock::now();
  const planning::PlanResult result =
      planning::plan_routes(safe, map.geometry, start, goal, templates, cfg.planner);
  cfg.planner.progress = nullptr;  // ends the progress bar's line
  const double plan_ms = ms_since(t0);

  t0 = std::chrono::steady_clock::now();
  formats::RouteReport rep{&safe, map.geometry, start, goal, cfg.robot, cfg.planner, &result};
  app::OutputSet set(out, "plan-route");  // all or nothing: docs/plan-route.md, "Outputs"
  auto files = app::write_route_files(set.dir(), rep);
  const double write_ms = ms_since(t0);
  files.push_back("summary.json");
  json summary = {
      {"program", "plan-route"},
      {"version", kVersion},
      {"map", a.map_path},
      {"grid",
       {{"width", map.geometry.width()},
        {"height", map.geometry.height()},
        {"resolution_m", map.geometry.cell_m()},
        {"origin_m", {map.geometry.origin_m().x(), map.geometry.origin_m().y()}}}},
      {"found", !result.routes.empty()},
      {"message", result.message},
      {"routes", result.routes.size()},
      {"budget_reached",
       result.budget_reached.empty() ? json(nullptr) : json(result.budget_reached)},
      {"best", result.routes.empty() ? json(nullptr)
                                     : json{{"moves", result.routes[0].moves},
                                            {"turns", result.routes[0].turns},
                                            {"length_m", result.routes[0].length_m}}},
      {"parameters", app::to_json(cfg)},
      {"d_save_m", planning::d_save_m(cfg.robot)},
      {"timings_ms",
       {{"load", load_ms},
        {"templates", templates_ms},
        {"safe_zone", safe_ms},
        {"plan", plan_ms},
        {"write", write_ms},
        {"total", ms_since(t_start)}}},
      {"outputs", files},
  };
  formats::write_json(set.dir() / "summary.json", summary);
  set.commit();
  if (result.routes.empty()) {
    std::cerr << "plan-route: " << result.message << "\n";
    return static_cast<int>(ExitCode::kNoResult);
  }
  const auto& b = result.routes.front();
  if (a.quiet) return 0;
  std::cerr << "plan-route: " << result.routes.size() << " route(s); best: " << b.moves
            << " moves, " << b.turns << " turns, " << b.length_m << " m\n";
  std::cout << "outputs written to " << out.string() << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("plan-route", [&] { return run(argc, argv); });
}
