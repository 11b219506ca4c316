// scan-features: walls, doors, corners and corridors in every scan of a CARMEN laser log
// (features.jsonl, a picture of one scan) and, with --align, the relative motion of consecutive
// scans by point-to-point and point-to-line ICP beside the log's poses (align.json). Usage,
// options and figures: docs/scan-features.md.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "main_guard.hpp"
#include "output_set.hpp"
#include "scan_config.hpp"
#include "scan_outputs.hpp"
#include "scan_run.hpp"

namespace fs = std::filesystem;
using namespace indoormap;

namespace {

using Clock = std::chrono::steady_clock;

struct Args {
  std::string log_path, out_dir, config_file;
  int scan = 0;
  bool align = false, print_config = false, quiet = false;
  std::optional<int> exit_code;
};

Args parse_args(int argc, char** argv) {
  CLI::App cli{
      "scan-features: walls, doors, corners (inner / outer / potential) and corridors in every\n"
      "scan of a CARMEN laser log, and with --align the motion between consecutive scans by\n"
      "point-to-point and point-to-line ICP beside the log's poses. Writes features.jsonl,\n"
      "scan_<N>.png, align.json (--align) and summary.json in the output directory.\n"};
  cli.footer(
      "Examples:\n"
      "  scan-features ../shared/data/carmen-logs/intel-corrected.log.gz -o out/intel\n"
      "  scan-features ../shared/data/carmen-logs/freiburg-079-corrected.log.gz --scan 120 "
      "--align -o out/fr\n"
      "  scan-features --print-config > scan.yaml\n"
      "  scan-features -c scan.yaml ../shared/data/carmen-logs/csail-corrected.log.gz -o "
      "out/csail\n"
      "Logs: plain text or gzip. Exit codes: 0 done, 2 bad usage or bad log (the message names "
      "the\nfile and line; nothing is written), 3 no usable scan in the log, 1 other failure.");
  Args a;
  cli.add_option("log", a.log_path, "CARMEN log (FLASER messages with poses), plain or .gz");
  cli.add_option("-o,--out", a.out_dir, "Output directory (created if missing)");
  cli.add_option("-c,--config", a.config_file,
                 "YAML parameters (defaults: config/scan-features.yaml)");
  cli.add_option("--scan", a.scan, "0-based index of the scan to draw (default 0)")
      ->check(CLI::NonNegativeNumber);
  cli.add_flag("--align", a.align, "Also align consecutive scans (both ICP variants): align.json");
  cli.add_flag("-q,--quiet", a.quiet, "No progress or figures on stderr (errors only)");
  cli.add_flag("--print-config", a.print_config, "Print the effective parameters as YAML and exit");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    a.exit_code = cli.exit(e) == 0 ? 0 : static_cast<int>(ExitCode::kBadInput);
  }
  return a;
}

void report(const app::ScanFeaturesRun& r) {
  const auto j = app::scan_features_result_json(r);
  std::cerr << "scan-features: " << r.records.size() << " scans (" << r.scans_skipped
            << " skipped): " << j["walls"] << " walls, " << j["doors"] << " doors, "
            << j["corridors"] << " corridors, corners " << j["corners"].dump() << "\n";
  if (!r.align) return;
  const auto& s = r.align_summary;
  for (int k = 0; k < 2; ++k) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "%s: median error %.4f m / %.3f deg over %d pairs, %.4f m / %.3f deg over %d "
                  "that moved",
                  k == 0 ? "point-to-point" : "point-to-line", s.median_translation_error_m[k][0],
                  s.median_rotation_error_deg[k][0], s.pairs, s.median_translation_error_m[k][1],
                  s.median_rotation_error_deg[k][1], s.moved_pairs);
    std::cerr << "scan-features: " << line << "\n";
  }
}

int run(int argc, char** argv) {
  const Args a = parse_args(argc, argv);
  if (a.exit_code) return *a.exit_code;
  const auto t_start = Clock::now();
  app::ScanFeaturesConfig cfg;
  if (!a.config_file.empty()) app::merge_scan_features_config_file(cfg, a.config_file);
  app::validate(cfg);
  if (a.print_config) {
    std::cout << app::to_yaml(cfg);
    return 0;
  }
  if (a.log_path.empty()) throw UsageError("no log given: scan-features LOG -o DIR (see --help)");
  if (a.out_dir.empty()) throw UsageError("no output directory given: use -o DIR");
  if (!fs::exists(a.log_path)) throw InputError(a.log_path, "no such file");
  if (fs::is_directory(a.log_path)) throw InputError(a.log_path, "is a directory, not a log");
  const fs::path out = a.out_dir;
  ensure_writable_dir(out);

  // Everything is computed (and every log line read) before the first file is written.
  const app::ScanFeaturesRun r = app::run_scan_features(a.log_path, cfg, a.scan, a.align, a.quiet);
  if (r.records.empty()) {
    std::cerr << "scan-features: " << a.log_path << ": no usable FLASER scan (" << r.stats.scans
              << " read, " << r.scans_skipped << " with an unusable pose); nothing written\n";
    return static_cast<int>(ExitCode::kNoResult);
  }
  if (!r.picture)
    throw UsageError("--scan " + std::to_string(a.scan) + ": " + a.log_path + " has " +
                     std::to_string(r.stats.scans) + " scans (0-based; unusable ones have no " +
                     "picture); nothing written");
  const nlohmann::json timings = {
      {"read", r.read_ms},
      {"features", r.features_ms},
      {"align", r.align_ms},
      {"total_before_write",
       std::chrono::duration<double, std::milli>(Clock::now() - t_start).count()}};
  app::OutputSet set(out, "scan-features");  // all or nothing: docs/scan-features.md
  app::write_scan_features_outputs(set.dir(), r, timings);
  set.commit();
  if (!a.quiet) {
    report(r);
    std::cout << "outputs written to " << out.string() << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("scan-features", argc, argv, [&] { return run(argc, argv); });
}
