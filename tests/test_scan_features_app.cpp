// scan-features end to end: a small generated CARMEN log (simulated scans of a room with a door)
// to every output, --align against the log's poses, the options and config, bad input (exit 2,
// the file and line named, no output at all) and a log without scans (exit 3).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <string>

#include "indoormap/sim/scan_scenes.hpp"
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using namespace indoormap;
using indoormap::test::run_app;
using nlohmann::json;

bool empty_or_missing(const fs::path& dir) {
  return !fs::exists(dir) || fs::is_empty(dir);
}

/// A FLASER log of `scans` scans (361 beams over 180 degrees) of one simulated room, the robot
/// driving 5 cm and turning 1 degree per scan.
std::string room_log(int scans) {
  const sim::ScanScene scene = sim::random_scan_scene(3);
  std::mt19937_64 rng(3);
  laser::Pose2d pose = sim::random_pose(scene, 1.5, rng);
  sim::LaserModel m;
  m.beams = 361;
  m.fov_rad = std::numbers::pi;
  std::string log = "# generated\nPARAM robot_front_laser_max 30.0 nohost 0\n";
  char buf[64];
  for (int k = 0; k < scans; ++k) {
    const laser::LaserScan s = sim::cast_scan(scene, pose, m, rng);
    log += "FLASER 361";
    for (float r : s.ranges_m) std::snprintf(buf, sizeof buf, " %.3f", r), log += buf;
    std::snprintf(buf, sizeof buf, " %.5f %.5f %.6f", pose.x_m, pose.y_m, pose.theta_rad);
    log += buf;
    log += buf;
    log += " 1.0 host 1.0\n";
    const laser::Pose2d step{0.05, 0.0, std::numbers::pi / 180.0};
    const laser::Pose2d next = pose.compose(step);
    if (sim::cast_ray(scene, pose.position_m(),
                      (next.position_m() - pose.position_m()).normalized()) > 1.0)
      pose = next;
    else
      pose.theta_rad += 0.3;
  }
  return log;
}

TEST(ScanFeaturesApp, WritesEveryOutputAndAligns) {
  const fs::path dir = test::scratch_dir();
  const fs::path log = dir / "room.log", out = dir / "out";
  test::write_text(log, room_log(12));
  const auto r = run_app("scan-features", log.string() + " --scan 3 --align -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"features.jsonl", "scan_3.png", "align.json", "summary.json"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  std::ifstream in(out / "features.jsonl");
  std::string line;
  int lines = 0, walls = 0;
  while (std::getline(in, line)) {
    const json j = json::parse(line);
    EXPECT_EQ(j["scan"], lines++);
    walls += static_cast<int>(j["walls"].size());
    for (const auto& c : j["corners"]) EXPECT_TRUE(c.contains("p_map") && c.contains("type"));
  }
  EXPECT_EQ(lines, 12);
  EXPECT_GT(walls, 12 * 2);
  const json align = json::parse(test::read_text(out / "align.json"));
  EXPECT_EQ(align["summary"]["pairs"], 11);
  for (const char* k : {"point_to_point", "point_to_line"}) {
    EXPECT_LE(align["summary"][k]["median_translation_error_m"].get<double>(), 0.01) << k;
    EXPECT_LE(align["summary"][k]["median_rotation_error_deg"].get<double>(), 0.2) << k;
  }
  const json summary = json::parse(test::read_text(out / "summary.json"));
  EXPECT_EQ(summary["program"], "scan-features");
  EXPECT_TRUE(summary["parameters"].contains("doors"));
  EXPECT_TRUE(summary["timings_ms"].contains("features"));
}

TEST(ScanFeaturesApp, OptionsConfigAndHelp) {
  auto r = run_app("scan-features", "--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("Examples"), std::string::npos);
  const auto shipped = run_app("scan-features", "-c " + std::string(INDOORMAP_SOURCE_DIR) +
                                                    "/config/scan-features.yaml --print-config");
  const auto builtin = run_app("scan-features", "--print-config");
  ASSERT_EQ(builtin.exit_code, 0);
  EXPECT_EQ(shipped.out, builtin.out);  // the shipped file documents the defaults
  const fs::path dir = test::scratch_dir();
  test::write_text(dir / "c.yaml", "doors:\n  max_width_m: 1.5\n");
  r = run_app("scan-features", "-c " + (dir / "c.yaml").string() + " --print-config");
  EXPECT_NE(r.out.find("max_width_m: 1.5"), std::string::npos);
  test::write_text(dir / "log", room_log(2));
  r = run_app("scan-features", "-q " + (dir / "log").string() + " -o " + (dir / "q").string());
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_TRUE(fs::exists(dir / "q" / "scan_0.png"));
}

TEST(ScanFeaturesApp, BadInputIsExitTwoWithoutOutput) {
  const fs::path dir = test::scratch_dir();
  const fs::path out = dir / "out";
  auto r = run_app("scan-features", (dir / "missing.log").string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("missing.log"), std::string::npos);
  test::write_text(dir / "bad.log", room_log(3) + "FLASER 3 1.0 2.0\n");
  r = run_app("scan-features", (dir / "bad.log").string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.log"), std::string::npos);
  EXPECT_NE(r.err.find("line"), std::string::npos);
  test::write_text(dir / "ok.log", room_log(3));
  r = run_app("scan-features", (dir / "ok.log").string() + " --scan 7 -o " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--scan 7"), std::string::npos);
  test::write_text(dir / "c.yaml", "doors:\n  min_width_m: -1\n");
  r = run_app("scan-features", "-c " + (dir / "c.yaml").string() + " " + (dir / "ok.log").string() +
                                   " -o " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("doors.min_width_m"), std::string::npos);
  r = run_app("scan-features", (dir / "ok.log").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(empty_or_missing(out));
  test::write_text(dir / "empty.log", "# nothing\nODOM 0 0 0 0 0 0 0 host 0\n");
  r = run_app("scan-features", (dir / "empty.log").string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_TRUE(empty_or_missing(out));
}

}  // namespace
