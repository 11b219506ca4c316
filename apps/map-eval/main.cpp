// map-eval: compares pcd-to-map / furniture-extract outputs with a scene-sim ground truth.
// See docs/map-eval.md and docs/evaluation.md.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "config_reader.hpp"
#include "eval_pair.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/formats/ground_truth_json.hpp"
#include "indoormap/sim/eval.hpp"
#include "indoormap/version.hpp"
#include "main_guard.hpp"
#include "output_set.hpp"
#include "progress.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using nlohmann::ordered_json;

namespace {

/// Every key of the config file (-c, config/map-eval.yaml), top-level keys.
ordered_json opt(const std::optional<double>& v) {
  return v ? ordered_json(*v) : ordered_json(nullptr);
}

template <class F>
void visit(sim::EvalParams& p, F&& f) {
  f("", "min_object_iou", app::finite(p.min_object_iou));
  f("", "objects_include_hanging", p.include_hanging);
  f("", "min_object_area_m2", app::finite(p.min_truth_area_m2));
}

/// Floor heights of the result's storeys from RESULT/summary.json ("storeys": [{"floor_z_m"}]),
/// by storey_<k> directory; missing keys leave the list short (storeys then match by index).
std::vector<std::optional<double>> result_floors(const fs::path& dir, int n) {
  std::vector<std::optional<double>> out(n);
  try {
    std::ifstream in(dir / "summary.json");
    if (!in) return out;
    const auto j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.contains("storeys") || !j["storeys"].is_array()) return out;
    for (std::size_t i = 0; i < j["storeys"].size() && static_cast<int>(i) < n; ++i) {
      const auto& s = j["storeys"][i];
      for (const char* key : {"floor_z_m", "floor_m", "floor"})
        if (s.is_object() && s.contains(key) && s[key].is_number()) {
          out[i] = s[key].get<double>();
          break;
        }
    }
  } catch (const std::exception&) {
  }
  return out;
}

/// Per-storey evaluation: truth storey k against the result's storey_<m> whose floor is nearest
/// (within 1 m); without result floors, storey_<k> against truth storey k.
ordered_json storeys_json(const formats::TruthFile& truth, const fs::path& dir,
                          const map_eval::PairParams& p, int& evaluated,
                          const app::ProgressReporter& bar) {
  int n_result = 0;
  while (fs::is_directory(dir / ("storey_" + std::to_string(n_result)))) ++n_result;
  const auto floors = result_floors(dir, n_result);
  ordered_json list = ordered_json::array();
  for (const auto& ts : truth.storeys) {
    int match = -1;
    double best = 1.0;
    for (int m = 0; m < n_result; ++m)
      if (floors[m] && std::abs(*floors[m] - ts.floor_z_m) <= best)
        best = std::abs(*floors[m] - ts.floor_z_m), match = m;
    const bool by_index = match < 0 && ts.k < n_result && !floors[ts.k];
    if (by_index) match = ts.k;
    ordered_json j = {
        {"k", ts.k}, {"truth_floor_z_m", ts.floor_z_m}, {"truth_ceiling_z_m", ts.ceiling_z_m}};
    if (match < 0) {
      j["result"] = nullptr;
      j["note"] = "no result storey with a floor within 1 m";
      list.push_back(j);
      bar.update(static_cast<std::int64_t>(list.size()) + 1,
                 static_cast<std::int64_t>(truth.storeys.size()) + 1);
      continue;
    }
    j["result"] = "storey_" + std::to_string(match);
    j["result_floor_z_m"] = opt(floors[match]);
    j["floor_error_m"] =
        floors[match] ? ordered_json(*floors[match] - ts.floor_z_m) : ordered_json(nullptr);
    if (by_index) j["note"] = "matched by index: the result's summary.json gives no floor heights";
    const formats::TruthFile st = formats::read_truth_json(ts.ground_truth);
    auto r = map_eval::evaluate_pair(st, dir / ("storey_" + std::to_string(match)), p);
    evaluated += r.evaluated;
    j.update(r.json);
    list.push_back(j);
    bar.update(static_cast<std::int64_t>(list.size()) + 1,
               static_cast<std::int64_t>(truth.storeys.size()) + 1);
  }
  return list;
}

int run(int argc, char** argv) {
  CLI::App app{
      "map-eval: compares pcd-to-map / furniture-extract results with a scene-sim ground truth and "
      "writes "
      "eval.json (layout IoU per class, object recall / precision, room Hausdorff / area error)."};
  app.footer(
      "Examples:\n"
      "  map-eval --truth clouds/office/ground_truth.json --result out\n"
      "  map-eval --truth /tmp/scene7/ground_truth.json --result /tmp/scene7-out -o /tmp/eval7 "
      "--min-iou 0.4\n"
      "Reads from RESULT: layout.pgm (+ layout.yaml or map.yaml), objects.json, room.geojson, "
      "map.pgm / map.yaml,\n"
      "and storey_<k>/ for a multi-storey truth; each missing file is reported as \"missing\" "
      "in eval.json. Exit codes: 0 done, 2 bad usage or input, 3 "
      "nothing to evaluate, 1 other.");
  std::string truth_file, result_dir, out_dir, config_file;
  sim::EvalParams p;
  bool print_config = false, quiet = false;
  double min_iou = -1;
  bool include_hanging = false;
  double min_area = -1, robot_width = 0.4;
  app.add_flag("-q,--quiet", quiet, "No progress or messages on stderr (errors stay)");
  app.add_option("--truth", truth_file, "ground_truth.json written by scene-sim");
  app.add_option("--result", result_dir, "Directory with the results to evaluate");
  app.add_option("-o,--out", out_dir, "Where to write eval.json (default: the result directory)");
  app.add_option("-c,--config", config_file,
                 "Config file (YAML; keys min_object_iou, objects_include_hanging)");
  app.add_option("--min-iou", min_iou, "Footprint IoU needed to match an object (default 0.5)")
      ->check(CLI::Range(0.01, 1.0));
  app.add_option("--min-area", min_area,
                 "Recall counts truth objects of at least this area, m^2 (default 0.1)")
      ->check(CLI::Range(0.0, 100.0));
  app.add_option("--robot-width-m", robot_width,
                 "Robot diameter for the door and reachability metrics (default 0.4)")
      ->check(CLI::Range(0.01, 5.0));
  app.add_flag("--include-hanging", include_hanging, "Also count ceiling lamps as objects to find");
  app.add_flag("--print-config", print_config, "Print the effective parameters as YAML and exit");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : static_cast<int>(ExitCode::kBadInput);
  }
  if (!config_file.empty()) app::read_config_file(config_file, [&](auto&& f) { visit(p, f); });
  if (min_iou > 0) p.min_object_iou = min_iou;
  if (include_hanging) p.include_hanging = true;
  if (min_area >= 0) p.min_truth_area_m2 = min_area;
  sim::validate(p);
  if (print_config) {
    std::cout << app::config_to_yaml([&](auto&& f) { visit(p, f); });
    return 0;
  }
  if (truth_file.empty() || result_dir.empty())
    throw UsageError("--truth FILE and --result DIR are required (see --help)");
  if (!fs::is_directory(result_dir)) throw InputError(result_dir, "result directory not found");
  if (out_dir.empty()) out_dir = result_dir;
  ensure_writable_dir(out_dir);

  const formats::TruthFile truth = formats::read_truth_json(truth_file);
  const fs::path dir(result_dir);
  ordered_json report;
  report["app"] = "map-eval";
  report["version"] = kVersion;
  report["truth"] = truth_file;
  report["result"] = result_dir;
  report["parameters"] = {{"min_object_iou", p.min_object_iou},
                          {"objects_include_hanging", p.include_hanging}};
  report["parameters"]["min_object_area_m2"] = p.min_truth_area_m2;
  report["parameters"]["robot_width_m"] = robot_width;
  const map_eval::PairParams pp{p, robot_width};
  // Progress over the parts evaluated: the whole result, then each storey of a storeyed truth.
  const app::ProgressReporter bar("map-eval: evaluating", "parts", quiet);
  auto pair = map_eval::evaluate_pair(truth, dir, pp);
  bar.update(1, static_cast<std::int64_t>(truth.storeys.size()) + 1);
  int evaluated = pair.evaluated;
  const std::vector<std::string> missing = pair.missing;
  report.update(pair.json);
  if (!truth.storeys.empty()) report["storeys"] = storeys_json(truth, dir, pp, evaluated, bar);
  report["missing"] = missing;
  {
    app::OutputSet set(out_dir, "map-eval");  // all or nothing: docs/map-eval.md, "Outputs"
    write_file_atomic(set.dir() / "eval.json", report.dump(2) + "\n");
    set.commit();
  }
  if (evaluated == 0) {
    std::fprintf(
        stderr,
        "map-eval: nothing to evaluate in %s (no layout.pgm, objects.json or room.geojson)\n",
        result_dir.c_str());
    return static_cast<int>(ExitCode::kNoResult);
  }
  if (!quiet)
    std::fprintf(stderr, "map-eval: wrote %s\n", (fs::path(out_dir) / "eval.json").c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("map-eval", [&] { return run(argc, argv); });
}
