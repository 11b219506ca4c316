// Furniture objects: accuracy on simulated scenes (issue 4 acceptance).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <opencv2/imgproc.hpp>
#include <random>
#include <set>

#include "indoormap/cloud/level.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "indoormap/objects/objects.hpp"
#include "indoormap/sim/eval.hpp"
#include "indoormap/sim/ground_truth.hpp"
#include "indoormap/sim/random_scene.hpp"
#include "indoormap/sim/simulate.hpp"
#include "objects_fixtures.hpp"

using namespace indoormap;
using namespace indoormap::objects;
using namespace objects_fixtures;

// ---- Accuracy on simulated scenes (issue 4 acceptance) ------------------------------------------

namespace {

struct SceneScore {
  int truth = 0, result = 0, matched_truth = 0, matched_result = 0;
  int lamps = 0, lamps_found = 0, lamp_results = 0, lamp_results_right = 0;
  std::vector<double> height_errors_m;
};

// Objects of at least min_area_m2 on both sides: recall counts truth items matched by any result
// object, precision counts result objects matched by any truth item (footprint IoU >= 0.5).
SceneScore score_scene(std::uint64_t seed, double min_area_m2) {
  sim::RandomSceneParams rp;
  rp.rooms = 1;
  const sim::Scene scene = sim::normalised(sim::random_scene(seed, rp));
  const sim::SimResult s = sim::simulate(scene);
  PointCloud cloud{s.points, s.scanner_positions_m, {}};
  const layout::MapResult m = layout::make_map(std::move(cloud), {});
  const auto objs = objects::extract_objects(m.layout.layout, m.geometry, m.voxels, m.layers, {},
                                             m.cloud_map.scanners);
  // Recall: truth items of at least min_area_m2 against every result object. Precision: result
  // objects of at least min_area_m2 against every truth item on the floor (a result matching a
  // small truth item is right, not spurious).
  std::vector<sim::EvalObject> truth_big, truth_all, result_big, result_all;
  for (const auto& t : sim::furniture_truth(scene)) {
    if (!t.on_floor) continue;
    sim::EvalObject e{t.id, "", t.footprint, t.z_min_m, t.z_max_m, true};
    truth_all.push_back(e);
    if (std::abs(indoormap::signed_area(t.footprint)) >= min_area_m2) truth_big.push_back(e);
  }
  for (const auto& o : objs.objects) {
    if (o.kind == ObjectKind::kHanging || o.kind == ObjectKind::kLamp)
      continue;  // floor items only, as map-eval does
    sim::EvalObject e{std::to_string(o.id), "", o.footprint_m, std::nullopt, std::nullopt, true};
    if (o.has_height) {
      e.z_min_m = o.z_min_m;
      e.z_max_m = o.z_max_m;
    }
    result_all.push_back(e);
    if (o.area_m2 >= min_area_m2) result_big.push_back(e);
  }
  // Lamps: the truth items off the floor in the scanned room (the corridor's are not seen)
  // against the result objects of kind lamp or hanging.
  std::vector<sim::EvalObject> truth_lamps, result_lamps;
  int scanned_room = -1;
  for (std::size_t i = 0; i < scene.rooms.size(); ++i)
    if (scene.rooms[i].kind == sim::RoomKind::kRoom) scanned_room = static_cast<int>(i);
  for (const auto& t : sim::furniture_truth(scene))
    if (!t.on_floor && t.room == scanned_room)
      truth_lamps.push_back({t.id, "", t.footprint, t.z_min_m, t.z_max_m, false});
  for (const auto& o : objs.objects)
    if (o.kind == ObjectKind::kHanging || o.kind == ObjectKind::kLamp)
      result_lamps.push_back(
          {std::to_string(o.id), "", o.footprint_m, o.z_min_m, o.z_max_m, false});
  const sim::ObjectScores lamp_scores = sim::evaluate_objects(truth_lamps, result_lamps, 0.5);
  if (std::getenv("IM_DEBUG_LAMPS")) {
    for (const auto& t : truth_lamps) {
      double best = 0;
      std::string bid = "-";
      for (const auto& o : result_lamps) {
        const auto one = sim::evaluate_objects({t}, {o}, 0.0);
        if (!one.matches.empty() && one.matches[0].iou > best)
          best = one.matches[0].iou, bid = o.id;
      }
      std::printf("  seed %llu lamp %s z %.2f-%.2f best %s %.2f\n", (unsigned long long)seed,
                  t.id.c_str(), *t.z_min_m, *t.z_max_m, bid.c_str(), best);
    }
    for (const auto& o : objs.objects)
      if (o.kind == ObjectKind::kHanging || o.kind == ObjectKind::kLamp)
        std::printf("  seed %llu result %d %s at %.2f,%.2f %.2fx%.2f z %.2f-%.2f\n",
                    (unsigned long long)seed, o.id, std::string(to_string(o.kind)).c_str(),
                    o.box.center_m.x(), o.box.center_m.y(), o.box.length_m, o.box.width_m,
                    o.z_min_m, o.z_max_m);
  }
  const sim::ObjectScores for_recall = sim::evaluate_objects(truth_big, result_all, 0.5);
  const sim::ObjectScores for_precision = sim::evaluate_objects(truth_all, result_big, 0.5);
  SceneScore r;
  r.lamps = lamp_scores.truth_count;
  r.lamps_found = lamp_scores.matched;
  r.lamp_results = lamp_scores.result_count;
  r.lamp_results_right = lamp_scores.matched;
  r.truth = for_recall.truth_count;
  r.result = for_precision.result_count;
  r.matched_truth = for_recall.matched;
  r.matched_result = for_precision.matched;
  for (const auto& mt : for_recall.matches) {
    if (mt.z_max_error_m) r.height_errors_m.push_back(std::abs(*mt.z_max_error_m));
    if (std::getenv("IM_DEBUG"))
      std::printf("  %s iou %.2f dz %.2f\n", mt.truth_id.c_str(), mt.iou,
                  mt.z_max_error_m.value_or(99));
  }
  if (std::getenv("IM_DEBUG")) {
    for (const auto& id : for_recall.missed)
      for (const auto& t : truth_big)
        if (t.id == id) {
          std::string best = "-";
          double best_iou = 0.0;
          for (const auto& o : result_all) {
            const auto one = sim::evaluate_objects({t}, {o}, 0.0);
            if (!one.matches.empty() && one.matches[0].iou > best_iou) {
              best_iou = one.matches[0].iou;
              best = o.id;
            }
          }
          std::printf("  missed %s area %.2f best %s %.2f\n", id.c_str(),
                      std::abs(indoormap::signed_area(t.footprint)), best.c_str(), best_iou);
        }
    for (const auto& id : for_precision.spurious)
      for (const auto& o : objs.objects)
        if (std::to_string(o.id) == id) {
          std::string best = "-";
          double best_iou = 0.0;
          for (const auto& t : truth_all) {
            const auto one = sim::evaluate_objects(
                {t}, {{id, "", o.footprint_m, std::nullopt, std::nullopt, true}}, 0.0);
            if (!one.matches.empty() && one.matches[0].iou > best_iou) {
              best_iou = one.matches[0].iou;
              best = t.id;
            }
          }
          std::printf("  spurious %s area %.2f at %.2f,%.2f top %.2f best %s %.2f\n", id.c_str(),
                      o.area_m2, o.box.center_m.x(), o.box.center_m.y(), o.z_max_m, best.c_str(),
                      best_iou);
        }
  }
  return r;
}

}  // namespace

struct Totals {
  double recall = 0, precision = 0, median_height_error_m = 1e9;
  double lamp_recall = 0, lamp_precision = 0;
};

Totals score_scenes(std::uint64_t first_seed, std::uint64_t last_seed) {
  int truth = 0, result = 0, matched = 0, matched_result = 0;
  int lamps = 0, lamps_found = 0, lamp_results = 0;
  std::vector<double> errors;
  for (std::uint64_t seed = first_seed; seed <= last_seed; ++seed) {
    const SceneScore s = score_scene(seed, 0.1);
    lamps += s.lamps;
    lamps_found += s.lamps_found;
    lamp_results += s.lamp_results;
    truth += s.truth;
    result += s.result;
    matched += s.matched_truth;
    matched_result += s.matched_result;
    errors.insert(errors.end(), s.height_errors_m.begin(), s.height_errors_m.end());
    std::printf("scene %2llu: truth %2d result %2d matched %2d\n",
                static_cast<unsigned long long>(seed), s.truth, s.result, s.matched_truth);
  }
  EXPECT_GT(truth, 50);
  Totals t;
  t.recall = truth ? static_cast<double>(matched) / truth : 0.0;
  t.precision = result ? static_cast<double>(matched_result) / result : 0.0;
  std::sort(errors.begin(), errors.end());
  if (!errors.empty()) t.median_height_error_m = errors[errors.size() / 2];
  t.lamp_recall = lamps ? static_cast<double>(lamps_found) / lamps : 0.0;
  t.lamp_precision = lamp_results ? static_cast<double>(lamps_found) / lamp_results : 0.0;
  std::printf("lamps: truth %d, result %d, matched %d, recall %.3f, precision %.3f\n", lamps,
              lamp_results, lamps_found, t.lamp_recall, t.lamp_precision);
  std::printf(
      "objects >= 0.1 m2 in scenes %llu-%llu: truth %d, result %d, matched %d, recall %.3f, "
      "precision %.3f, median |z_max error| %.3f m\n",
      static_cast<unsigned long long>(first_seed), static_cast<unsigned long long>(last_seed),
      truth, result, matched, t.recall, t.precision, t.median_height_error_m);
  return t;
}

// Issue 4's acceptance: recall and precision >= 0.9, median height error <= 5 cm on 20 scenes.
TEST(ObjectsAccuracy, TwentySimulatedScenes) {
  const Totals t = score_scenes(1, 20);
  EXPECT_GE(t.recall, 0.9);
  EXPECT_GE(t.precision, 0.9);
  EXPECT_LE(t.median_height_error_m, 0.05);
  // Lamps (no target in the issue; docs/evaluation-history.md): guards against regressions.
  EXPECT_GE(t.lamp_recall, 0.75);
  EXPECT_GE(t.lamp_precision, 0.6);
}

// The parameters were chosen looking at scenes 1-20; scenes 21-40 were not looked at while doing
// so and show what to expect on new scenes (docs/evaluation-history.md).
TEST(ObjectsAccuracy, TwentyHeldOutScenes) {
  const Totals t = score_scenes(21, 40);
  EXPECT_GE(t.recall, 0.88);    // 2026-12-02: 0.889 (64 of 72)
  EXPECT_GE(t.precision, 0.9);  // 2026-12-02: 0.909
  EXPECT_LE(t.median_height_error_m, 0.05);
}
