// map-eval: compares pcd-to-map / furniture-extract outputs with a scene-sim ground truth.
// See docs/map-eval.md and docs/evaluation.md.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "config_reader.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/formats/ground_truth_json.hpp"
#include "indoormap/formats/objects_json.hpp"
#include "indoormap/formats/pgm.hpp"
#include "indoormap/formats/room_geojson.hpp"
#include "indoormap/formats/ros_map.hpp"
#include "indoormap/sim/eval.hpp"
#include "indoormap/version.hpp"
#include "main_guard.hpp"
#include "map_yaml.hpp"
#include "output_set.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using nlohmann::ordered_json;

namespace {

/// Every key of the config file (-c, config/map-eval.yaml), top-level keys.
template <class F>
void visit(sim::EvalParams& p, F&& f) {
  f("", "min_object_iou", app::finite(p.min_object_iou));
  f("", "objects_include_hanging", p.include_hanging);
}

/// Grid geometry of a result layout: layout.yaml if present, else map.yaml (same grid), read by
/// the one map.yaml reader (app::read_map_yaml; the image it names is not opened).
GridGeometry result_geometry(const fs::path& dir, const Grid<std::uint8_t>& image,
                             std::string& source) {
  fs::path yaml = dir / "layout.yaml";
  if (!fs::exists(yaml)) yaml = dir / "map.yaml";
  if (!fs::exists(yaml))
    throw InputError(
        (dir / "map.yaml").string(),
        "missing: layout.pgm needs map.yaml (or layout.yaml) for its resolution and origin");
  source = yaml.filename().string();
  const formats::RosMapMeta meta = app::read_map_yaml(yaml);
  if (meta.origin.z() != 0.0)
    throw InputError(yaml.string(), "key 'origin': a rotated map (yaw != 0) is not supported");
  return GridGeometry({meta.origin.x(), meta.origin.y()}, meta.resolution_m, image.width,
                      image.height);
}

ordered_json opt(const std::optional<double>& v) {
  return v ? ordered_json(*v) : ordered_json(nullptr);
}

ordered_json layout_json(const sim::LayoutScores& s) {
  ordered_json j;
  ordered_json classes;
  for (int k = 0; k < 4; ++k) {
    const auto& c = s.classes[k];
    classes[std::string(to_string(static_cast<Cell>(k)))] = {{"iou", opt(c.iou)},
                                                             {"intersection_m2", c.intersection_m2},
                                                             {"union_m2", c.union_m2},
                                                             {"truth_m2", c.truth_m2},
                                                             {"result_m2", c.result_m2}};
  }
  j["classes"] = classes;
  j["mean_iou"] = opt(s.mean_iou);
  j["mean_iou_over"] = {"wall", "furniture", "free"};
  j["accuracy"] = s.accuracy;
  ordered_json conf;
  for (int t = 0; t < 4; ++t) {
    ordered_json row;
    for (int r = 0; r < 4; ++r)
      row[std::string(to_string(static_cast<Cell>(r)))] = s.confusion_m2[t][r];
    conf[std::string(to_string(static_cast<Cell>(t)))] = row;
  }
  j["confusion_m2"] = conf;
  j["confusion_rows"] = "truth class";
  j["confusion_columns"] = "result class";
  return j;
}

ordered_json objects_json(const sim::ObjectScores& s) {
  ordered_json j;
  j["truth_count"] = s.truth_count;
  j["result_count"] = s.result_count;
  j["matched"] = s.matched;
  j["recall"] = s.recall;
  j["precision"] = s.precision;
  j["mean_abs_z_max_error_m"] = opt(s.mean_abs_z_max_error_m);
  j["mean_abs_z_min_error_m"] = opt(s.mean_abs_z_min_error_m);
  j["max_abs_height_error_m"] = opt(s.max_abs_height_error_m);
  ordered_json m = ordered_json::array();
  for (const auto& x : s.matches)
    m.push_back({{"truth_id", x.truth_id},
                 {"result_id", x.result_id},
                 {"iou", x.iou},
                 {"z_min_error_m", opt(x.z_min_error_m)},
                 {"z_max_error_m", opt(x.z_max_error_m)}});
  j["matches"] = m;
  j["missed"] = s.missed;
  j["spurious"] = s.spurious;
  return j;
}

ordered_json rooms_json(const std::vector<sim::RoomMatch>& rooms) {
  ordered_json a = ordered_json::array();
  for (const auto& r : rooms) {
    ordered_json j;
    j["result_index"] = r.result_index;
    if (r.truth_index < 0) {
      j["truth_room"] = nullptr;
      j["note"] = "overlaps no truth room";
    } else {
      j["truth_room"] = r.truth_name;
      j["iou"] = r.iou;
      j["hausdorff_m"] = r.hausdorff_m;
      j["truth_area_m2"] = r.truth_area_m2;
      j["result_area_m2"] = r.result_area_m2;
      j["area_error_m2"] = r.area_error_m2;
      j["area_error_rel"] = r.area_error_rel;
    }
    a.push_back(j);
  }
  return a;
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
      "Reads from RESULT: layout.pgm (+ layout.yaml or map.yaml), objects.json, room.geojson; each "
      "missing file\n"
      "is reported as \"missing\" in eval.json. Exit codes: 0 done, 2 bad usage or input, 3 "
      "nothing to evaluate, 1 other.");
  std::string truth_file, result_dir, out_dir, config_file;
  sim::EvalParams p;
  bool print_config = false;
  double min_iou = -1;
  bool include_hanging = false;
  app.add_option("--truth", truth_file, "ground_truth.json written by scene-sim");
  app.add_option("--result", result_dir, "Directory with the results to evaluate");
  app.add_option("-o,--out", out_dir, "Where to write eval.json (default: the result directory)");
  app.add_option("-c,--config", config_file,
                 "Config file (YAML; keys min_object_iou, objects_include_hanging)");
  app.add_option("--min-iou", min_iou, "Footprint IoU needed to match an object (default 0.5)")
      ->check(CLI::Range(0.01, 1.0));
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
  std::vector<std::string> missing;
  int evaluated = 0;

  // Layout.
  if (fs::exists(dir / "layout.pgm")) {
    const Grid<std::uint8_t> raw = formats::read_pgm(dir / "layout.pgm");
    std::string source;
    const GridGeometry rg = result_geometry(dir, raw, source);
    const Grid<Cell> result = formats::read_layout_pgm(dir / "layout.pgm", rg);
    const Grid<Cell> truth_cells =
        formats::read_layout_pgm(truth.layout_image, truth.layout_geometry);
    ordered_json j = {{"status", "ok"}, {"file", "layout.pgm"}, {"geometry_from", source}};
    j.update(layout_json(sim::evaluate_layout(truth.layout_geometry, truth_cells, rg, result)));
    report["layout"] = j;
    ++evaluated;
  } else {
    report["layout"] = {{"status", "missing"}, {"file", "layout.pgm"}};
    missing.push_back("layout.pgm");
  }
  // Objects.
  if (fs::exists(dir / "objects.json")) {
    // Without --include-hanging both sides are what stands on the floor (sim::evaluate_objects).
    const auto objects = formats::read_objects_json(dir / "objects.json");
    ordered_json j = {{"status", "ok"}, {"file", "objects.json"}};
    j.update(objects_json(sim::evaluate_objects(truth.furniture, objects, p)));
    report["objects"] = j;
    ++evaluated;
  } else {
    report["objects"] = {{"status", "missing"}, {"file", "objects.json"}};
    missing.push_back("objects.json");
  }
  // Room polygons.
  if (fs::exists(dir / "room.geojson")) {
    const auto rooms = formats::read_room_geojson(dir / "room.geojson");
    ordered_json j = {{"status", rooms.empty() ? "empty" : "ok"}, {"file", "room.geojson"}};
    j["rooms"] = rooms_json(sim::evaluate_rooms(truth.rooms, rooms));
    report["room"] = j;
    ++evaluated;
  } else {
    report["room"] = {{"status", "missing"}, {"file", "room.geojson"}};
    missing.push_back("room.geojson");
  }
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
  std::fprintf(stderr, "map-eval: wrote %s\n", (fs::path(out_dir) / "eval.json").c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return app::run_guarded("map-eval", [&] { return run(argc, argv); });
}
