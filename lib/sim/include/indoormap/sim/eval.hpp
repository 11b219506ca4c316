#pragma once
// Evaluation of pcd-to-map / furniture-extract results against a scene's ground truth
// (docs/evaluation.md): per-class IoU of the layout, object recall / precision with height
// errors, room-polygon Hausdorff distance and area error. Values in, values out: the files are
// read by lib/formats (ground_truth_json.hpp, objects_json.hpp, room_geojson.hpp, pgm.hpp).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/core/polygon.hpp"

namespace indoormap::sim {

// ---- Layout ------------------------------------------------------------------------------------

struct ClassScore {
  double intersection_m2 = 0.0;
  double union_m2 = 0.0;
  double truth_m2 = 0.0;
  double result_m2 = 0.0;
  /// intersection / union; empty when the class appears in neither grid.
  std::optional<double> iou;
};

struct LayoutScores {
  std::array<ClassScore, 4> classes;  ///< indexed by the Cell value
  std::optional<double> mean_iou;     ///< mean over wall, furniture, free (classes with a union)
  double accuracy = 0.0;              ///< share of the area (truth or result known) that agrees
  std::array<std::array<double, 4>, 4> confusion_m2{};  ///< [truth][result] area
};

/// Compares by metric position: every result cell takes the truth class at its centre (truth
/// grid by its own geometry; outside = unknown). Truth cells whose centre lies outside the result
/// grid count as result = unknown, so a cropped result misses what it does not cover. Areas are
/// in m^2, so grids of different resolution compare fairly. result values must be 0..3.
LayoutScores evaluate_layout(const GridGeometry& truth_geometry, const Grid<Cell>& truth,
                             const GridGeometry& result_geometry, const Grid<Cell>& result);

// ---- Objects -----------------------------------------------------------------------------------

struct EvalObject {
  std::string id;
  std::string type;  ///< truth: furniture type; result: optional label
  Polygon footprint;
  std::optional<double> z_min_m, z_max_m;
  bool on_floor = true;
};

struct ObjectMatch {
  std::string truth_id, result_id;
  double iou = 0.0;
  std::optional<double> z_min_error_m, z_max_error_m;  ///< result - truth
};

struct ObjectScores {
  int truth_count = 0, result_count = 0, matched = 0;
  double recall = 0.0, precision = 0.0;
  std::vector<ObjectMatch> matches;
  std::vector<std::string> missed;    ///< truth ids without a match
  std::vector<std::string> spurious;  ///< result ids without a match
  int truth_below_min_area = 0;       ///< truth items left out of truth_count (EvalParams)
  int matched_all = 0;                ///< matches including those of items below the minimum area
  std::optional<double> mean_abs_z_max_error_m, mean_abs_z_min_error_m, max_abs_height_error_m;
};

/// One-to-one greedy matching by footprint IoU (highest first) with IoU >= min_iou; footprint
/// IoU is computed by rasterising both polygons at 1 cm. Recall = matched / truth, precision =
/// matched / result (0 when the denominator is 0).
ObjectScores evaluate_objects(const std::vector<EvalObject>& truth,
                              const std::vector<EvalObject>& result, double min_iou = 0.5);

/// map-eval's parameters (config/map-eval.yaml).
struct EvalParams {
  double min_object_iou = 0.5;  ///< footprint IoU needed to match a result object with a truth item
  bool include_hanging = false;  ///< also expect lamps (not standing on the floor) as objects
  /// Recall counts truth items of at least this footprint area (m^2); smaller items may still
  /// be matched (a result object matching one is no false positive) but are not expected.
  /// Precision counts every result object. 0: every item counts.
  double min_truth_area_m2 = 0.1;
};

/// Throws UsageError unless min_object_iou is in (0, 1]. Called by evaluate_objects(..., params).
void validate(const EvalParams& params);

/// The object scores map-eval reports: without include_hanging both sides are what stands on the
/// floor (truth items with on_floor, result objects not of kind hanging / lamp); matched with
/// params.min_object_iou; recall over the truth items of at least min_truth_area_m2 (matched
/// = their matches), precision = matched_all / result_count. Throws UsageError for invalid params
/// (validate).
ObjectScores evaluate_objects(const std::vector<EvalObject>& truth, std::vector<EvalObject> result,
                              const EvalParams& params);

// ---- Rooms -------------------------------------------------------------------------------------

struct TruthRoom {
  std::string name;
  std::string kind;  ///< "room" or "corridor"
  Polygon polygon;
};

struct RoomMatch {
  int result_index = 0;
  int truth_index = -1;  ///< -1: overlaps no truth room
  std::string truth_name;
  double iou = 0.0;
  double hausdorff_m = 0.0;
  double truth_area_m2 = 0.0, result_area_m2 = 0.0;
  double area_error_m2 = 0.0;   ///< result - truth
  double area_error_rel = 0.0;  ///< (result - truth) / truth
};

/// Each result polygon is matched with the truth room it overlaps most (IoU, 2 cm raster); the
/// Hausdorff distance is between the boundaries sampled every 1 cm.
std::vector<RoomMatch> evaluate_rooms(const std::vector<TruthRoom>& truth,
                                      const std::vector<Polygon>& result);

}  // namespace indoormap::sim
