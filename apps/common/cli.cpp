#include "cli.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <new>

#include "indoormap/core/errors.hpp"

namespace indoormap::app {

namespace {
// Scan numbers above this are refused (they index files scanNNN.3d; an int holds them).
constexpr int kMaxScanNumber = 1'000'000;
}  // namespace

void add_pipeline_options(CLI::App& app, PipelineCli& cli) {
  app.add_option(
      "inputs", cli.inputs,
      "Point clouds: .pcd, .ply, .xyz/.txt/.csv, .las (LAS 1.2-1.4), or a 3DTK scan directory "
      "(several are merged)");
  app.add_option("-o,--out", cli.out_dir, "Output directory (created if missing)");
  app.add_option("-c,--config", cli.config_file, "YAML parameters (see config/default.yaml)");
  app.add_flag("--print-config", cli.print_config,
               "Print the effective parameters as YAML and exit");
  app.add_flag("-q,--quiet", cli.quiet,
               "No progress or run report on stderr (warnings still shown)");
  app.add_option("--scans", cli.scans, "3DTK: scan numbers to read, e.g. 0-8 or 3");
  app.add_option("--up-axis", cli.up_axis, "Up axis of PCD/PLY/XYZ input: z (default) or y")
      ->check(CLI::IsMember({"z", "y"}));
  app.add_option("--unit", cli.unit,
                 "Unit of PCD/PLY/XYZ input: m (default), cm, mm, or metres per unit");
  app.add_option(
      "--scanner", cli.scanners,
      "Scanner position X,Y,Z in metres (input frame); repeat for several. Overrides file poses");
  app.add_option("--trajectory", cli.trajectory,
                 "Scanner positions from a file: TUM 't x y z qx qy qz qw' or 'x y z' lines "
                 "(metres, input frame); added to the others");
  app.add_option("--storey", cli.storey,
                 "Map only storey K (0: the lowest; see summary.json 'storeys')")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--cell-m", cli.cell_m, "Voxel / map cell size in metres (voxel.cell_m)");
  app.add_flag("--no-level", cli.no_level, "Do not level the cloud (level.enabled: false)");
  app.add_flag("--align-walls", cli.align_walls,
               "Turn the map frame about the vertical so the walls run along x and y "
               "(align_walls.enabled: true); summary.json and map.yaml say how to go back");
  app.add_option("--start", cli.start,
                 "Route start X,Y[,DEG] in the map frame (with --goal: route outputs)");
  app.add_option("--goal", cli.goal, "Route goal X,Y[,DEG] in the map frame (with --start)");
}

namespace {

double parse_number(const std::string& s, const std::string& what) {
  try {
    std::size_t used = 0;
    const double v = std::stod(s, &used);
    if (used != s.size() || !std::isfinite(v)) throw std::invalid_argument(s);
    return v;
  } catch (const std::exception&) {
    throw UsageError(what + ": '" + s + "' is not a number");
  }
}

}  // namespace

planning::Pose2 parse_pose(const std::string& text, const std::string& option) {
  std::vector<double> v;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto comma = text.find(',', start);
    v.push_back(parse_number(text.substr(start, comma - start), option));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (v.size() != 2 && v.size() != 3)
    throw UsageError(option + ": expected X,Y or X,Y,DEG, got '" + text + "'");
  planning::Pose2 p;
  p.position_map = {v[0], v[1]};
  if (v.size() == 3) p.heading_deg = v[2];
  return p;
}

PipelineConfig resolve_config(const PipelineCli& cli) {
  PipelineConfig c;
  if (!cli.config_file.empty()) merge_config_file(c, cli.config_file);
  if (!cli.up_axis.empty())
    c.load.up_axis = cli.up_axis == "y" ? cloud_io::UpAxis::kY : cloud_io::UpAxis::kZ;
  if (!cli.unit.empty()) {
    if (cli.unit == "m")
      c.load.unit_m = 1.0;
    else if (cli.unit == "cm")
      c.load.unit_m = 0.01;
    else if (cli.unit == "mm")
      c.load.unit_m = 0.001;
    else
      c.load.unit_m = parse_number(cli.unit, "--unit");
  }
  if (!cli.scans.empty()) {
    const auto dash = cli.scans.find('-');
    const std::string a = cli.scans.substr(0, dash);
    const std::string b = dash == std::string::npos ? a : cli.scans.substr(dash + 1);
    const double first = parse_number(a, "--scans"), last = parse_number(b, "--scans");
    if (first < 0 || last < first || first != std::floor(first) || last != std::floor(last))
      throw UsageError("--scans: expected A-B with 0 <= A <= B, got '" + cli.scans + "'");
    if (last > kMaxScanNumber)
      throw UsageError("--scans: scan numbers are at most " + std::to_string(kMaxScanNumber) +
                       ", got '" + cli.scans + "'");
    c.load.scan_first = static_cast<int>(first);
    c.load.scan_last = static_cast<int>(last);
  }
  if (!cli.scanners.empty()) {
    c.scanners.clear();
    for (const auto& s : cli.scanners) {
      std::vector<double> v;
      std::size_t start = 0;
      while (start <= s.size()) {
        const auto comma = s.find(',', start);
        v.push_back(parse_number(s.substr(start, comma - start), "--scanner"));
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
      if (v.size() != 3) throw UsageError("--scanner: expected X,Y,Z, got '" + s + "'");
      c.scanners.emplace_back(v[0], v[1], v[2]);
    }
  }
  if (cli.cell_m != 0.0) c.map.voxel.cell_m = cli.cell_m;
  if (cli.no_level) c.map.level.enabled = false;
  if (cli.align_walls) c.map.align_walls.enabled = true;
  if (cli.start.empty() != cli.goal.empty()) throw UsageError("--start and --goal go together");
  validate(c);
  return c;
}

std::function<void(const std::string&, double)> load_progress(bool quiet) {
  if (progress_mode(quiet) == ProgressMode::kOff) return {};
  // One reporter per file (a 3DTK directory is many files), in per mille of the file's bytes.
  auto current = std::make_shared<std::pair<std::string, ProgressReporter>>(
      "", ProgressReporter("", "", true));
  return [current](const std::string& file, double fraction) {
    if (current->first != file)
      *current = {file, ProgressReporter("loading " + file + " (per mille)", "", false)};
    current->second.update(static_cast<std::int64_t>(fraction * 1000.0), 1000);
  };
}

}  // namespace indoormap::app
