// Issue 17, "Sparse scans": default random scenes simulated at a 1 degree step (seeds 21-40,
// never looked at while tuning), at a 2 degree step and with the 16-beam lidar of
// config/scene-sim-16beam.yaml, run through pcd-to-map with its defaults and scored by map-eval
// with its defaults (objects: pcd-to-map's objects.json, the same objects furniture-extract
// writes). docs/evaluation-history.md, "Sparse scans", has the figures; scripts/sparse_eval.sh
// prints them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using indoormap::test::run_app;
using nlohmann::json;

/// scene-sim --random --seed N SIM_ARGS, pcd-to-map, map-eval: eval.json (null on a failure,
/// which the test reports).
json eval_of(int seed, const std::string& sim_args, const fs::path& dir) {
  const fs::path sim = dir / ("sim_" + std::to_string(seed)),
                 res = dir / ("res_" + std::to_string(seed));
  auto r = run_app("scene-sim", "--random --seed " + std::to_string(seed) + " " + sim_args +
                                    " -q -o " + sim.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_app("pcd-to-map", (sim / "cloud.pcd").string() + " -q -o " + res.string());
  EXPECT_EQ(r.exit_code, 0) << "seed " << seed << ": " << r.err;
  if (r.exit_code != 0) return nullptr;
  r = run_app("map-eval", "-q --truth " + (sim / "ground_truth.json").string() + " --result " +
                              res.string() + " -o " + (res / "eval").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return json::parse(indoormap::test::read_text(res / "eval" / "eval.json"));
}

/// The room polygon of the truth room (not the corridor) within 0.15 m Hausdorff and 3 % area.
bool border_within(const json& e) {
  const json* best = nullptr;
  for (const auto& r : e["room"]["rooms"]) {
    if (r["truth_room"].is_null() || r["truth_room"].get<std::string>().starts_with("corridor"))
      continue;
    if (!best || r["iou"].get<double>() > (*best)["iou"].get<double>()) best = &r;
  }
  return best && (*best)["hausdorff_m"].get<double>() <= 0.15 &&
         std::abs((*best)["area_error_rel"].get<double>()) <= 0.03;
}

// Objects at 1 degree: issue 17's target, 0.8 (met since 2026-12-06: recall 58 of 72, 0.806,
// precision 68 of 83 written, 0.819; docs/evaluation-history.md, "Sparse scans"). The 16-beam far
// share: a regression guard (the figure of 2026-12-02 rounded up; that target is not met).
constexpr double kRecallFloor = 0.8, kPrecisionFloor = 0.8, kSixteenBeamFarCeil = 0.35;

double far_share(const json& e, const char* grid) {
  return e["floor"][grid]["far_free"]["share"].get<double>();
}

}  // namespace

// The 1 degree figures on all of seeds 21-40 (10-25 s on the 2-core machine).
TEST(Sparse, OneDegreeStepOnTwentyHeldOutScenes) {
  const fs::path dir = indoormap::test::scratch_dir();
  int truth = 0, matched = 0, written = 0, matched_all = 0, border = 0, runs = 0;
  double seen_iou = 0;
  for (int seed = 21; seed <= 40; ++seed) {
    const json e = eval_of(seed, "--step-deg 1", dir);
    if (e.is_null()) continue;
    ++runs;
    const json& o = e["objects"];
    truth += o["truth_count"].get<int>();
    matched += o["matched"].get<int>();
    written += o["result_count"].get<int>();
    matched_all += o["matched_all"].get<int>();
    border += border_within(e);
    const double iou = e["floor"]["map"]["seen_free_iou"]["iou"].get<double>();
    seen_iou += iou;
    EXPECT_GE(iou, 0.8) << "seed " << seed;
    EXPECT_LE(far_share(e, "map"), 0.005) << "seed " << seed;
    EXPECT_LE(far_share(e, "layout"), 0.005) << "seed " << seed;
  }
  EXPECT_EQ(runs, 20);  // every scene gives a map (before: seeds with no map at all)
  // Issue 17: at least 0.8 x 20 rooms within 0.15 m and 3 %; free IoU over seen cells >= 0.8.
  EXPECT_GE(border, 16);
  EXPECT_GE(seen_iou / 20, 0.8);
  // Objects: issue 17's 0.8 over everything written (docs/evaluation-history.md, "Sparse scans").
  const double recall = static_cast<double>(matched) / truth;
  const double precision = static_cast<double>(matched_all) / written;
  EXPECT_GE(recall, kRecallFloor) << matched << " of " << truth;
  EXPECT_GE(precision, kPrecisionFloor) << matched_all << " of " << written;
}

// No free cell far from any observation (0.5 m from every seen cell of the truth) on 2 degree
// scans, seeds 21-25: the paper's flood bridged gaps between isolated hits into unseen space.
TEST(Sparse, TwoDegreeStepHasNoFreeCellsFarFromTheRays) {
  const fs::path dir = indoormap::test::scratch_dir();
  for (int seed = 21; seed <= 25; ++seed) {
    const json e = eval_of(seed, "--step-deg 2", dir);
    if (e.is_null()) continue;
    EXPECT_LE(far_share(e, "map"), 0.005) << "seed " << seed;
    EXPECT_LE(far_share(e, "layout"), 0.005) << "seed " << seed;
  }
}

// The 16-beam lidar (config/scene-sim-16beam.yaml), seeds 21-25: every scene gives a map. Free
// far from the rays: NOT met. Around the scanner, within about 1.3 m, no ray comes down into
// the truth's seen band (below 1 m: the lowest beam is 15 degrees down), but the 2D rays of the
// navigation map call those cells free (docs/evaluation-history.md, "Sparse scans"). The bound is a
// guard against regressions only (seeds 1-20: 9 % of the free area; 21-25: up to 33 % per scene).
TEST(Sparse, SixteenBeamLidarGivesAMapWithFreeSpaceNearTheRays) {
  const fs::path dir = indoormap::test::scratch_dir();
  const std::string cfg =
      "-c " + (fs::path(INDOORMAP_SOURCE_DIR) / "config/scene-sim-16beam.yaml").string();
  for (int seed = 21; seed <= 25; ++seed) {
    const json e = eval_of(seed, cfg, dir);
    if (e.is_null()) continue;
    EXPECT_LE(far_share(e, "map"), kSixteenBeamFarCeil) << "seed " << seed;
    EXPECT_LE(far_share(e, "layout"), kSixteenBeamFarCeil) << "seed " << seed;
    // No return lies on the floor: no plane through the walls levels the cloud, and the run
    // says the floor is unseen (docs/evaluation-history.md, "16-beam lidar: planes through walls").
    const json s = json::parse(
        indoormap::test::read_text(dir / ("res_" + std::to_string(seed)) / "summary.json"));
    EXPECT_FALSE(s["levelling"]["levelled"].get<bool>()) << "seed " << seed;
    int unseen = 0;
    for (const auto& w : s["warnings"])
      unseen += w.get<std::string>().find("floor is nearly all unseen") != std::string::npos;
    EXPECT_EQ(unseen, 1) << "seed " << seed;
  }
}
