// laser-to-map: a CARMEN laser log with known poses to an occupancy map (ROS map.pgm + map.yaml,
// map.png) by HIMM or log-odds mapping, and the map's self-consistency against the scans it was
// built from (laser_map.json, stderr). Usage, options and figures: docs/laser-to-map.md.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/core/input_file.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/version.hpp"
#include "laser_config.hpp"
#include "laser_outputs.hpp"
#include "laser_run.hpp"
#include "main_guard.hpp"
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

/// The command line; exit_code is set when parsing ends the run (--help, a usage error).
struct Args {
  std::string log_path, out_dir, config_file, method;
  std::optional<double> cell_m, max_range_m;
  bool print_config = false, quiet = false;
  std::optional<int> exit_code;
};

Args parse_args(int argc, char** argv) {
  CLI::App cli{
      "laser-to-map: build an occupancy map from a CARMEN laser log with known poses (HIMM or "
      "log-odds)\nand check it against its own scans. Writes map.pgm + map.yaml (ROS map_server), "
      "map.png,\nlaser_map.json and summary.json in the output directory.\n"
      "By default each scan's pose is first refined against the map of the log (pose_refine.passes "
      "2;\nset it to 0 for the log's poses as given), and the log-odds sum is not clamped (every "
      "beam of\nthe log weighs alike: log_odds.clamp). docs/laser-to-map.md.\n"};
  cli.footer(
      "Examples:\n"
      "  laser-to-map ../shared/data/carmen-logs/intel-corrected.log.gz -o out/intel\n"
      "  laser-to-map ../shared/data/carmen-logs/csail-corrected.log.gz --method himm -o "
      "out/csail\n"
      "  laser-to-map --print-config > laser.yaml\n"
      "  laser-to-map -c laser.yaml ../shared/data/carmen-logs/freiburg-079-corrected.log.gz -o "
      "out/fr\n"
      "Logs: plain text or gzip. Exit codes: 0 done, 2 bad usage or bad log (the message names "
      "the\n"
      "file and line; nothing is written), 3 no usable scan in the log, 1 other failure.");
  Args a;
  cli.add_option("log", a.log_path, "CARMEN log (FLASER messages with poses), plain or .gz");
  cli.add_option("-o,--out", a.out_dir, "Output directory (created if missing)");
  cli.add_option("-c,--config", a.config_file,
                 "YAML parameters (defaults: config/laser-to-map.yaml)");
  cli.add_option("--method", a.method, "Mapping method: himm or logodds (default logodds)");
  cli.add_option("--cell-m", a.cell_m, "Cell size in metres (mapping.cell_m, default 0.05)");
  cli.add_option("--max-range-m", a.max_range_m,
                 "Longer readings are not obstacles nor checked (mapping.max_range_m, default 44)");
  cli.add_flag("-q,--quiet", a.quiet, "No progress or figures on stderr (errors only)");
  cli.add_flag("--print-config", a.print_config, "Print the effective parameters as YAML and exit");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    a.exit_code = cli.exit(e) == 0 ? 0 : static_cast<int>(ExitCode::kBadInput);
  }
  return a;
}

app::LaserMapConfig effective_config(const Args& a) {
  app::LaserMapConfig cfg;
  if (!a.config_file.empty()) app::merge_laser_map_config_file(cfg, a.config_file);
  if (!a.method.empty()) cfg.method = app::parse_method(a.method);
  if (a.cell_m) cfg.grid.cell_m = *a.cell_m;
  if (a.max_range_m) cfg.grid.max_range_m = *a.max_range_m;
  app::validate(cfg);
  return cfg;
}

int run(int argc, char** argv) {
  const Args a = parse_args(argc, argv);
  if (a.exit_code) return *a.exit_code;
  const auto t_start = Clock::now();
  const app::LaserMapConfig cfg = effective_config(a);
  if (a.print_config) {
    std::cout << app::to_yaml(cfg);
    return 0;
  }
  if (a.log_path.empty()) throw UsageError("no log given: laser-to-map LOG -o DIR (see --help)");
  if (a.out_dir.empty()) throw UsageError("no output directory given: use -o DIR");
  check_input_file(a.log_path, kNoSizeLimit);  // missing, a directory, a FIFO: exit 2
  const fs::path out = a.out_dir;
  ensure_writable_dir(out);

  // Everything is computed (and every log line read) before the first file is written.
  const app::LaserMapRun r = app::map_log(a.log_path, cfg, a.quiet);
  if (r.scans_mapped == 0) {
    std::cerr << "laser-to-map: " << a.log_path << ": no usable FLASER scan (" << r.stats.scans
              << " read, " << r.scans_skipped << " with an unusable pose); nothing written\n";
    return static_cast<int>(ExitCode::kNoResult);
  }
  const auto t_write = Clock::now();
  app::OutputSet set(out, "laser-to-map");  // all or nothing: docs/laser-to-map.md, "Outputs"
  auto files = app::write_laser_map_outputs(set.dir(), r);
  files.push_back(app::kReportFile);
  files.push_back("summary.json");
  const json summary = {
      {"program", "laser-to-map"},
      {"version", kVersion},
      {"provenance", app::provenance_json({a.log_path})},
      {"log", a.log_path},
      {"parameters", app::to_json(cfg)},
      {"result", app::laser_map_json(r)},
      {"timings_ms",
       {{"map", r.map_ms},
        {"check", r.check_ms},
        {"write", ms_since(t_write)},
        {"total", ms_since(t_start)}}},
      {"outputs", files},
  };
  formats::write_json(set.dir() / "summary.json", summary);
  app::write_report(set.dir(), summary, files);
  set.commit();
  if (!a.quiet) {
    const auto& c = r.check;
    char line[256];
    std::snprintf(line, sizeof line,
                  "%zu scans mapped (%s, %zu skipped); consistency: %zu beams, %.1f %% within "
                  "%g m, median |error| %.4f m",
                  r.scans_mapped, cfg.method == laser::MapperKind::kHimm ? "himm" : "logodds",
                  r.scans_skipped, c.beams_checked, c.within_share * 100.0, c.within_m,
                  c.median_abs_error_m);
    std::cerr << "laser-to-map: " << line << "\n";
    std::cout << "outputs written to " << out.string() << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("laser-to-map", argc, argv, [&] { return run(argc, argv); });
}
