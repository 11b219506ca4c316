// Objects as a user gets them (issue 17): default random scenes (`scene-sim --random --seed N`,
// default scanner, tilt and corridor), `furniture-extract` with its defaults, `map-eval` with its
// defaults (recall over truth items of at least 0.1 m2, precision over every object written), as
// scripts/objects_eval.sh runs them. App-level, over 1 s: labelled slow. Figures in
// docs/evaluation-history.md ("Figures as a user gets them").
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "test_support.hpp"

using indoormap::test::run_app;
using nlohmann::json;

namespace {

namespace fs = std::filesystem;

struct UserFigures {
  int truth = 0, result = 0, matched = 0, matched_all = 0;
  double recall = 0.0, precision = 0.0, median_abs_dz_m = 1e9;
};

// Runs the three apps on seeds first..last and sums map-eval's object blocks.
UserFigures user_figures(int first, int last) {
  const fs::path dir = fs::temp_directory_path() / "indoormap-tests" /
                       ("objects_user_" + std::to_string(::getpid()));
  UserFigures f;
  std::vector<double> dz;
  for (int seed = first; seed <= last; ++seed) {
    const fs::path sim = dir / ("sim_" + std::to_string(seed));
    const fs::path res = dir / ("res_" + std::to_string(seed));
    const fs::path ev = dir / ("eval_" + std::to_string(seed));
    auto r =
        run_app("scene-sim", "--random --seed " + std::to_string(seed) + " -q -o " + sim.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    r = run_app("furniture-extract", (sim / "cloud.pcd").string() + " -q -o " + res.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    r = run_app("map-eval", "--truth " + (sim / "ground_truth.json").string() + " --result " +
                                res.string() + " -o " + ev.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(ev / "eval.json");
    const json o = json::parse(in).at("objects");
    f.truth += o.at("truth_count").get<int>();
    f.result += o.at("result_count").get<int>();
    f.matched += o.at("matched").get<int>();
    f.matched_all += o.at("matched_all").get<int>();
    for (const auto& m : o.at("matches"))
      if (m.contains("z_max_error_m") && !m.at("z_max_error_m").is_null())
        dz.push_back(std::abs(m.at("z_max_error_m").get<double>()));
  }
  fs::remove_all(dir);
  f.recall = f.truth ? static_cast<double>(f.matched) / f.truth : 0.0;
  f.precision = f.result ? static_cast<double>(f.matched_all) / f.result : 0.0;
  if (!dz.empty()) {
    std::sort(dz.begin(), dz.end());
    // The middle element for an odd count, the mean of the two middle ones for an even count
    // (Python's statistics.median, as scripts/objects_eval.sh).
    const std::size_t n = dz.size();
    f.median_abs_dz_m = n % 2 ? dz[n / 2] : 0.5 * (dz[n / 2 - 1] + dz[n / 2]);
  }
  std::printf(
      "seeds %d-%d: truth %d result %d matched %d (all %d) recall %.3f precision %.3f "
      "median |dz| %.3f m\n",
      first, last, f.truth, f.result, f.matched, f.matched_all, f.recall, f.precision,
      f.median_abs_dz_m);
  return f;
}

}  // namespace

// The tuning seeds: issue 17's targets hold there (2026-12-02: recall 0.955, precision 0.938,
// median 0.018 m; 2026-12-06: 0.970, 0.950; docs/evaluation.md).
TEST(ObjectsAsUserGetsThem, TuningSeeds1To20) {
  const UserFigures f = user_figures(1, 20);
  EXPECT_GE(f.recall, 0.95);
  EXPECT_GE(f.precision, 0.93);
  EXPECT_LE(f.median_abs_dz_m, 0.05);
}

// The held-out seeds 21-40, run after the rules were chosen on seeds 1-20 and 41-80: issue 17's
// target, recall and precision >= 0.9 (2026-12-02: recall 0.889, 64 of 72, precision 0.865;
// 2026-12-06, after the stray-return and wall-face rules: recall 0.903, 65 of 72, precision
// 0.908, 79 of 87 written, median 0.018 m; docs/evaluation.md).
TEST(ObjectsAsUserGetsThem, HeldOutSeeds21To40) {
  const UserFigures f = user_figures(21, 40);
  EXPECT_GE(f.recall, 0.9);
  EXPECT_GE(f.precision, 0.9);
  EXPECT_LE(f.median_abs_dz_m, 0.05);
}
