// explore-sim, the app (apps/explore-sim): outputs on a hand-made room, determinism for a seed,
// bad inputs (message, exit code, no outputs), the config, and one shared room-segmentation map.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "test_support.hpp"

using namespace indoormap;
namespace fs = std::filesystem;

namespace {

const char* const kOutputs[] = {"map.pgm",     "map.yaml",          "path.geojson", "explore.json",
                                "explore.png", "explore_strip.png", "report.html",  "summary.json"};

/// A 6 x 4 m room at 0.05 m per pixel (binary PGM, north up): walls 2 px thick, a 1 x 0.6 m
/// table in the east half and a short wall stub from the north wall, so that the robot must move.
fs::path write_room_pgm(const fs::path& dir) {
  const int w = 120, h = 80;
  std::string px(static_cast<std::size_t>(w * h), static_cast<char>(255));
  auto set = [&](int c, int r) { px[static_cast<std::size_t>(r * w + c)] = 0; };
  for (int c = 0; c < w; ++c)
    for (int t = 0; t < 2; ++t) set(c, t), set(c, h - 1 - t);
  for (int r = 0; r < h; ++r)
    for (int t = 0; t < 2; ++t) set(t, r), set(w - 1 - t, r);
  for (int r = 30; r < 42; ++r)
    for (int c = 80; c < 100; ++c) set(c, r);           // the table
  for (int r = 2; r < 40; ++r) set(60, r), set(61, r);  // a wall stub from the north wall
  const fs::path p = dir / "room.pgm";
  test::write_text(p, "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n" + px);
  return p;
}

bool empty_or_absent(const fs::path& d) {
  return !fs::exists(d) || fs::is_empty(d);
}

}  // namespace

TEST(ExploreSim, SingleRoomOutputsAndDeterminism) {
  const auto dir = test::scratch_dir();
  const std::string map = write_room_pgm(dir).string() + " --resolution 0.05";
  auto r = test::run_app("explore-sim", map + " --seed 3 -o " + (dir / "a").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("% of the reachable free space after"), std::string::npos)
      << r.err;  // report (progress lines: test_progress_slow)
  for (const char* f : kOutputs) EXPECT_TRUE(fs::exists(dir / "a" / f)) << f;
  const auto j = nlohmann::json::parse(test::read_text(dir / "a" / "explore.json"));
  EXPECT_GE(j["explored_share"].get<double>(), 0.95);
  EXPECT_TRUE(j["reached_95"].get<bool>());
  EXPECT_GT(j["distance_to_95_m"].get<double>(), 0.0);
  EXPECT_GE(j["goals"].get<int>(), 1);
  EXPECT_GE(j["series"].size(), 2u);
  EXPECT_EQ(j["status"], "complete");
  EXPECT_EQ(j["start"]["rule"], "middle of the largest region where the robot fits");
  const auto s = nlohmann::json::parse(test::read_text(dir / "a" / "summary.json"));
  EXPECT_EQ(s["program"], "explore-sim");
  EXPECT_EQ(s["parameters"]["run"]["seed"], 3);
  EXPECT_EQ(s["outputs"].size(), std::size(kOutputs));
  const auto path = nlohmann::json::parse(test::read_text(dir / "a" / "path.geojson"));
  EXPECT_GE(path["features"][0]["geometry"]["coordinates"].size(), 2u);
  EXPECT_NE(test::read_text(dir / "a" / "map.yaml").find("image: map.pgm"), std::string::npos);
  // No staging directory left behind (beside or inside); the one hidden file is the manifest.
  for (const auto& e : fs::directory_iterator(dir / "a"))
    if (e.path().filename() != ".indoormap-outputs") {
      EXPECT_NE(e.path().filename().string().front(), '.') << e.path();
    }
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find("indoormap-staging"), std::string::npos);

  // The same seed: the same explore.json, path and map; -q: nothing on stderr.
  r = test::run_app("explore-sim", map + " --seed 3 -q -o " + (dir / "b").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  for (const char* f : {"explore.json", "path.geojson", "map.pgm"})
    EXPECT_EQ(test::read_text(dir / "a" / f), test::read_text(dir / "b" / f)) << f;

  // A given start and heading, the paper's rule from a config file.
  test::write_text(dir / "paper.yaml", "goal:\n  rule: nearest_frontier\n");
  r = test::run_app("explore-sim", map + " -q -c " + (dir / "paper.yaml").string() +
                                       " --start 1.0,1.0,90 -o " + (dir / "c").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto jc = nlohmann::json::parse(test::read_text(dir / "c" / "explore.json"));
  EXPECT_EQ(jc["goal_rule"], "nearest_frontier");
  EXPECT_EQ(jc["start"]["rule"], "given");
  EXPECT_DOUBLE_EQ(jc["start"]["heading_deg"].get<double>(), 90.0);
  EXPECT_GE(jc["explored_share"].get<double>(), 0.95);

  // A ROS map (map.yaml) as input: the map the first run built, its unknown cells walls.
  r = test::run_app("explore-sim",
                    (dir / "a" / "map.yaml").string() + " -q -o " + (dir / "d").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto jd = nlohmann::json::parse(test::read_text(dir / "d" / "explore.json"));
  EXPECT_GE(jd["explored_share"].get<double>(), 0.95);
  r = test::run_app("explore-sim", (dir / "a" / "map.yaml").string() + " --resolution 0.05 -o " +
                                       (dir / "e").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--resolution is for plain"), std::string::npos) << r.err;
}

TEST(ExploreSim, BadInputsGetAMessageAnExitCodeAndNoOutputs) {
  const auto dir = test::scratch_dir();
  const std::string map = write_room_pgm(dir).string() + " --resolution 0.05";
  const auto out = dir / "o";
  const std::string o = " -o " + out.string();
  // A missing map: exit 2, named.
  auto r = test::run_app("explore-sim", (dir / "nope.pgm").string() + " --resolution 0.05" + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("nope.pgm"), std::string::npos) << r.err;
  EXPECT_TRUE(empty_or_absent(out));
  // An image without --resolution, no map at all.
  r = test::run_app("explore-sim", write_room_pgm(dir).string() + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--resolution"), std::string::npos) << r.err;
  r = test::run_app("explore-sim", o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no map given"), std::string::npos) << r.err;
  // A malformed --start, one outside the map: exit 2.
  r = test::run_app("explore-sim", map + " --start 1,x" + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--start"), std::string::npos) << r.err;
  r = test::run_app("explore-sim", map + " --start 1,2,3,4" + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--start"), std::string::npos) << r.err;
  r = test::run_app("explore-sim", map + " --start 50,1" + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("outside the map"), std::string::npos) << r.err;
  // A start in a wall, and one too close to it for the robot: exit 3, no outputs.
  for (const char* start : {"0.03,2.0", "0.2,2.0", "4.5,2.2"}) {  // west wall; beside it; table
    r = test::run_app("explore-sim", map + " --start " + start + o);
    EXPECT_EQ(r.exit_code, 3) << start << ": " << r.err;
    EXPECT_NE(r.err.find("explore-sim: start"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("not in free space"), std::string::npos) << r.err;
  }
  EXPECT_TRUE(empty_or_absent(out));
  // Config errors name the key and the line.
  test::write_text(dir / "typo.yaml", "robot:\n  speed_mps: 0.4\n  raduis_m: 0.2\n");
  r = test::run_app("explore-sim", map + " -c " + (dir / "typo.yaml").string() + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("robot.raduis_m"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("typo.yaml:3"), std::string::npos) << r.err;
  test::write_text(dir / "rule.yaml", "goal:\n  rule: closest\n");
  r = test::run_app("explore-sim", map + " -c " + (dir / "rule.yaml").string() + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("nearest_frontier"), std::string::npos) << r.err;
  test::write_text(dir / "speed.yaml", "robot:\n  speed_mps: -1\n");
  r = test::run_app("explore-sim", map + " -c " + (dir / "speed.yaml").string() + o);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("speed"), std::string::npos) << r.err;
  EXPECT_TRUE(empty_or_absent(out));
}

TEST(ExploreSim, ConfigFileIsTheDefaultsAndHelpHasExamples) {
  // config/explore-sim.yaml documents exactly the built-in defaults.
  const std::string cfg = std::string(INDOORMAP_SOURCE_DIR) + "/config/explore-sim.yaml";
  const auto builtin = test::run_app("explore-sim", "--print-config");
  const auto documented = test::run_app("explore-sim", "-c " + cfg + " --print-config");
  ASSERT_EQ(builtin.exit_code, 0) << builtin.err;
  ASSERT_EQ(documented.exit_code, 0) << documented.err;
  EXPECT_EQ(builtin.out, documented.out);
  EXPECT_NE(builtin.out.find("rule: gain_per_cost"), std::string::npos) << builtin.out;
  // --print-config's output reads back.
  const auto dir = test::scratch_dir();
  test::write_text(dir / "printed.yaml", builtin.out);
  const auto again =
      test::run_app("explore-sim", "-c " + (dir / "printed.yaml").string() + " --print-config");
  EXPECT_EQ(again.out, builtin.out);
  const auto help = test::run_app("explore-sim", "--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("Examples"), std::string::npos);
  EXPECT_NE(help.out.find("Exit codes"), std::string::npos);
}

TEST(ExploreSim, SharedFurnishedMap) {
  INDOORMAP_REQUIRE_DATA(dir, "room-segmentation-maps/Freiburg52_scan_furnitures.png");
  const auto out = test::scratch_dir();
  const auto r = test::run_app("explore-sim",
                               dir.string() + " --resolution 0.05 -q -o " + (out / "f52").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : kOutputs) EXPECT_TRUE(fs::exists(out / "f52" / f)) << f;
  const auto j = nlohmann::json::parse(test::read_text(out / "f52" / "explore.json"));
  EXPECT_GE(j["explored_share"].get<double>(), 0.95);
  EXPECT_GT(j["reachable_free_m2"].get<double>(), 100.0);
  const auto s = nlohmann::json::parse(test::read_text(out / "f52" / "summary.json"));
  std::printf(
      "[ figures  ] Freiburg52 furnished: explored %.3f, %.1f m, to 95 %% %.1f m, "
      "%.0f s simulated, %.0f x real time\n",
      j["explored_share"].get<double>(), j["distance_m"].get<double>(),
      j["distance_to_95_m"].get<double>(), j["time_s"].get<double>(),
      s["realtime_x"].get<double>());
}
