#pragma once
// The part of every pipeline app between argument parsing and its own outputs: load the inputs,
// run make_map, write the map outputs, and assemble summary.json.
#include <Eigen/Core>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "indoormap/border/border.hpp"
#include "indoormap/cloud_io/load.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "indoormap/layout/storeys.hpp"
#include "indoormap/objects/objects.hpp"

namespace indoormap::app {

struct PipelineRun {
  std::vector<cloud_io::InputReport> inputs;
  std::vector<Eigen::Vector3f> input_points;  ///< input frame; kept only when asked for
  layout::MapResult map;                      ///< the (first) storey mapped
  std::vector<layout::Storey> storeys;        ///< every storey found, bottom up
  std::vector<int> mapped;                    ///< the storeys mapped: map, then more_maps
  std::vector<layout::MapResult> more_maps;
  /// Floor and ceiling heights (map frame) of each mapped storey's own map, in run.mapped's order:
  /// kept here because the apps move the maps on while writing.
  std::vector<std::pair<double, double>> mapped_surfaces_m;
  std::size_t kept = 0;
  std::string scanner_source;  ///< "file", "config", "trajectory" or "estimated"
  double load_ms = 0.0;
  /// LAS inputs: the local-frame offset subtracted on reading (cloud_io::LoadResult).
  std::optional<Eigen::Vector3d> source_offset;
};

/// What every pipeline app does before its own work.
struct AppSetup {
  PipelineCli cli;
  PipelineConfig config;
  std::filesystem::path out;
  std::chrono::steady_clock::time_point start;
};

/// Parses the arguments (options of add_pipeline_options, already added to `app`), resolves the
/// config, answers --help and --print-config, requires inputs and -o, and checks that the output
/// directory is writable. nullopt: the app is done, with *exit_code set.
std::optional<AppSetup> setup_pipeline_app(CLI::App& app, PipelineCli& cli, int argc, char** argv,
                                           int* exit_code);

/// True when no ray evidence removed the map's stray returns (mixed pixels): no scanner position,
/// so no ghost filter. (Along a moving scanner's path the ghost filter removes most of them, and
/// leaving out the cells of one or two returns then costs more of the objects' own thin faces,
/// bins and table edges, than it removes: second tuning set, recall 0.809 -> 0.791.)
bool strays_unfiltered(const layout::MapResult& map);

/// The objects of the map, and the time they took (added to *ms). With strays_out, the pieces
/// made of stray returns are dropped (objects::drop_stray_pieces) and, where strays_unfiltered,
/// the stray cells are left out of the objects (objects::ScanTraits::peel_strays); without it
/// every piece is whole, for the steps that need every piece (the rooms of a floor).
objects::ObjectsResult timed_objects(const layout::MapResult& map,
                                     const objects::ObjectParams& params, double* ms,
                                     bool strays_out = true);

/// The room border of the map (border closure), and the time it took.
border::BorderResult timed_border(const layout::MapResult& map, const border::BorderParams& params,
                                  double* ms);

/// Adds the write and total timings and the output list (report.html and summary.json last) to
/// the summary, writes it and then report.html from it (report.hpp).
void finish_summary(nlohmann::json& summary, const std::filesystem::path& out,
                    std::vector<std::string> outputs,
                    std::chrono::steady_clock::time_point write_start,
                    std::chrono::steady_clock::time_point start);

/// Loads every input and makes the map. An error about the data as a whole (no file named) is
/// re-thrown naming all inputs.
PipelineRun run_pipeline(const PipelineCli& cli, PipelineConfig& config, bool keep_input_points);

/// run_pipeline's second half: the map of clouds already loaded (in load_ms), e.g. the Python
/// bindings' numpy points; cli.inputs name the data in errors. config's progress hooks are set
/// for the run (cli.quiet) and cleared after it.
PipelineRun map_loaded(cloud_io::LoadResult loaded, const PipelineCli& cli, PipelineConfig& config,
                       bool keep_input_points, double load_ms);

/// map.pgm + map.yaml (the navigation map; with LAS inputs, comments on the way back to the source
/// frame) and its picture map.png, layout.pgm, layout.png. Returns the file names.
std::vector<std::string> write_map_outputs(const std::filesystem::path& out, const PipelineRun& run,
                                           const PipelineConfig& config);

/// summary.json contents common to the pipeline apps; apps add their own keys.
nlohmann::json summary_json(const std::string& program, const PipelineRun& run,
                            const PipelineConfig& config);

/// The storeys found (index; floor and ceiling heights in the map frame, a mapped storey's as its
/// map has them, and as the storey histogram found them; the points' z range; whether mapped; the
/// directory of its outputs).
nlohmann::json storeys_json(const PipelineRun& run);

/// How to go from the map frame back to the source frame of LAS inputs (the local-frame offset,
/// unit and up axis, the levelling rotation), for summary.json; null when no LAS input was moved.
nlohmann::json source_frame_json(const PipelineRun& run, const PipelineConfig& config);

/// The same as map.yaml comment lines (empty when no LAS input was moved).
std::vector<std::string> source_frame_comments(const PipelineRun& run,
                                               const PipelineConfig& config);

/// Prints the warnings and a one-line report on stderr.
void report(const std::string& program, const PipelineRun& run, bool quiet = false);

}  // namespace indoormap::app
