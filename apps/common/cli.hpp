#pragma once
// Command-line plumbing shared by the pipeline apps (pcd-to-map, furniture-extract, ...).
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "config.hpp"
#include "indoormap/planning/planner.hpp"
#include "main_guard.hpp"
#include "progress.hpp"

namespace indoormap::app {

/// Options every pipeline app takes: inputs, output dir, config, and overrides of config keys.
struct PipelineCli {
  std::vector<std::string> inputs;
  std::string out_dir;
  std::string config_file;
  bool print_config = false;
  std::string scans;                  ///< "A-B" or "N"
  std::string up_axis;                ///< "z" / "y"
  std::string unit;                   ///< "m", "cm", "mm" or metres per unit
  std::vector<std::string> scanners;  ///< "X,Y,Z"
  std::string trajectory;             ///< TUM or x y z file of scanner positions
  int storey = -1;                    ///< --storey K: only that storey (-1: every storey)
  double cell_m = 0.0;                ///< 0: from config
  bool no_level = false;
  bool align_walls = false;  ///< --align-walls: align_walls.enabled
  std::string start;         ///< "X,Y[,DEG]" map frame: plan a route (with goal)
  std::string goal;          ///< "X,Y[,DEG]"
  bool quiet = false;        ///< -q: no progress or run report on stderr (warnings still shown)
};

/// Parses "X,Y" or "X,Y,DEG" (metres, degrees counter-clockwise from +x). Throws UsageError
/// naming the option.
planning::Pose2 parse_pose(const std::string& text, const std::string& option);

void add_pipeline_options(CLI::App& app, PipelineCli& cli);

/// Defaults, then the config file, then the command-line overrides; validated.
PipelineConfig resolve_config(const PipelineCli& cli);

/// The progress of long loads (text files, per file) for cloud_io::LoadOptions::progress, through
/// ProgressReporter (a bar on a terminal, a line every few seconds otherwise); empty when quiet.
std::function<void(const std::string&, double)> load_progress(bool quiet);

}  // namespace indoormap::app
