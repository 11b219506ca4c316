#pragma once
// map-eval's evaluation of one result directory against one ground truth (one storey): layout,
// objects, room polygons (eval.json's "layout", "objects", "room") and the whole-floor metrics
// ("floor": seen-free IoU, wall faces, doors, reachability). docs/map-eval.md lists the keys.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "indoormap/formats/ground_truth_json.hpp"
#include "indoormap/sim/eval.hpp"

namespace indoormap::map_eval {

struct PairParams {
  sim::EvalParams eval;
  double robot_width_m = 0.4;
  double far_free_m = 0.5;  ///< "far free": result free cells farther than this from any seen cell
};

struct PairReport {
  nlohmann::ordered_json json;       ///< layout, objects, room, floor, missing
  std::vector<std::string> missing;  ///< result files not found
  int evaluated = 0;                 ///< of layout.pgm, objects.json, room.geojson, map.pgm
};

/// Never throws for a missing optional file: its metric is null with a note. Throws InputError
/// for a malformed file (named).
PairReport evaluate_pair(const formats::TruthFile& truth, const std::filesystem::path& result_dir,
                         const PairParams& params);

}  // namespace indoormap::map_eval
