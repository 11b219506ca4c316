// Reliability round 2, through the apps: every file an app reads is checked by one function
// (indoormap::check_input_file: a FIFO or a directory is exit 2 naming the file, never a hang),
// and every app writes its outputs as one set (app::OutputSet): a failure part-way leaves the
// output directory byte for byte as it was, and files of an earlier run that this run does not
// write are removed. Rows of docs/robustness.md ("Reliability, round 2").
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "indoormap/core/grid.hpp"
#include "indoormap/formats/ros_map.hpp"
#include "map_fixtures.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using test::replace_all;

namespace {

/// run_app with a time limit (a hang is a failure, not a stuck suite) and an environment prefix.
test::RunResult run_limited(const std::string& app, const std::string& args,
                            const std::string& env = "") {
  return test::run_app(app, args, env, 30);
}

/// Every file below dir (relative path -> bytes); directories as "<rel>/" -> "".
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> s;
  if (!fs::exists(dir)) return s;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = fs::relative(e.path(), dir).generic_string();
    if (e.is_directory())
      s[rel + "/"] = "";
    else
      s[rel] = test::read_text(e.path());
  }
  return s;
}

/// A 3 x 2 m room of 0.05 m cells with walls around it (plan-route's and explore-sim's input).
fs::path small_map(const fs::path& dir) {
  Grid<Cell> room(60, 40, Cell::kFree);
  for (int c = 0; c < 60; ++c) room.at(c, 0) = room.at(c, 39) = Cell::kWall;
  for (int r = 0; r < 40; ++r) room.at(0, r) = room.at(59, r) = Cell::kWall;
  formats::write_ros_map(dir, "map", room, GridGeometry({0, 0}, 0.05, 60, 40));
  return dir / "map.yaml";
}

const std::string kTruth =
    R"({"format": "indoormap-ground-truth", "rooms": [], "furniture": [], "layout": )"
    R"({"image": "truth.pgm", "resolution": 0.05, "origin": [0, 0], "width": 2, "height": 2}})";

// ------------------------------------------------------------------ FIFOs and directories

enum class Kind { kFifo, kDirectory };

struct InputCase {
  std::string name;
  std::string app;
  std::string args;  ///< {d}: the scratch dir, {bad}: the FIFO or directory; outputs to {d}/out
  std::string bad;   ///< file name of the bad input in {d}
};

void PrintTo(const InputCase& c, std::ostream* os) { *os << c.name; }

class BadInputFile : public ::testing::TestWithParam<std::tuple<InputCase, Kind>> {};

TEST_P(BadInputFile, IsExitTwoNamingTheFileWithoutOutput) {
  const auto& [c, kind] = GetParam();
  const auto dir = test::scratch_dir();
  test::write_text(dir / "c.xyz", "0 0 0\n1 0 0\n0 1 1\n");
  test::write_text(dir / "truth.json", kTruth);
  test::write_text(dir / "truth.pgm", map_fixtures::kPgm);
  test::write_text(dir / "m.pgm", map_fixtures::kPgm);
  fs::create_directories(dir / "result");
  const fs::path bad = dir / c.bad;
  if (kind == Kind::kFifo)
    ASSERT_EQ(::mkfifo(bad.c_str(), 0600), 0);
  else
    fs::create_directories(bad);
  const auto r = run_limited(
      c.app, replace_all(replace_all(c.args, "{bad}", bad.string()), "{d}", dir.string()));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  const std::string problem = kind == Kind::kFifo ? ": is not a regular file (a FIFO"
                                                  : ": is a directory, expected ";
  EXPECT_NE(r.err.find(c.app + ": " + bad.string() + problem), std::string::npos) << r.err;
  EXPECT_TRUE(!fs::exists(dir / "out") || fs::is_empty(dir / "out")) << "partial output";
}

const std::string kPlan = " --start 0.5,0.5 --goal 2,1 -o {d}/out";

INSTANTIATE_TEST_SUITE_P(
    Apps, BadInputFile,
    ::testing::Combine(
        ::testing::Values(
            InputCase{"pcd_to_map_config", "pcd-to-map", "-c {bad} {d}/c.xyz -o {d}/out", "f.yaml"},
            InputCase{"pcd_to_map_cloud", "pcd-to-map", "{bad} -o {d}/out", "f.pcd"},
            InputCase{"furniture_extract_config", "furniture-extract",
                      "-c {bad} {d}/c.xyz -o {d}/out", "f.yaml"},
            InputCase{"scene_sim_scene", "scene-sim", "{bad} -o {d}/out", "s.yaml"},
            InputCase{"scene_sim_config", "scene-sim", "--random -c {bad} -o {d}/out", "c.yaml"},
            InputCase{"plan_route_map_yaml", "plan-route", "--map {bad}" + kPlan, "map.yaml"},
            InputCase{"plan_route_config", "plan-route",
                      "-c {bad} --map {d}/m.pgm --resolution 0.05" + kPlan, "c.yaml"},
            InputCase{"map_eval_config", "map-eval",
                      "-c {bad} --truth {d}/truth.json --result {d}/result -o {d}/out", "c.yaml"},
            InputCase{"map_eval_truth", "map-eval", "--truth {bad} --result {d}/result -o {d}/out",
                      "t.json"},
            InputCase{"laser_to_map_log", "laser-to-map", "{bad} -o {d}/out", "l.log"},
            InputCase{"laser_to_map_config", "laser-to-map", "-c {bad} {d}/c.xyz -o {d}/out",
                      "c.yaml"},
            InputCase{"explore_sim_map", "explore-sim", "{bad} -o {d}/out", "map.yaml"},
            InputCase{"explore_sim_config", "explore-sim",
                      "-c {bad} {d}/m.pgm --resolution 0.05 -o {d}/out", "c.yaml"}),
        ::testing::Values(Kind::kFifo, Kind::kDirectory)),
    [](const auto& info) {
      return std::get<0>(info.param).name +
             (std::get<1>(info.param) == Kind::kFifo ? "_fifo" : "_directory");
    });

// ------------------------------------------------------------------ output sets

const std::string kPlanArgs = " --start 0.5,0.5 --goal 2.5,1.5 -q -o ";

TEST(OutputSet, AFailurePartWayLeavesTheOutputDirectoryAsItWas) {
  const auto dir = test::scratch_dir();
  const std::string map = "--map " + small_map(dir).string();
  const fs::path out = dir / "out";
  ASSERT_EQ(run_limited("plan-route", map + kPlanArgs + out.string()).exit_code, 0);
  test::write_text(out / "notes.txt", "the user's own file\n");
  const auto before = snapshot(out);
  ASSERT_TRUE(before.count("route.png") && before.count(".indoormap-outputs"));

  // A full disk while route.png is written (injected: the test hook of write_stream_atomic).
  auto r = run_limited("plan-route", map + " --goal 2,1 --start 0.5,0.5 -q -o " + out.string(),
                       "INDOORMAP_TEST_FAIL_WRITE=route.png");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("route.png': write failed: No space left on device"), std::string::npos)
      << r.err;
  EXPECT_EQ(snapshot(out), before);

  // A directory where summary.json goes: refused before anything is moved.
  fs::remove(out / "summary.json");
  fs::create_directories(out / "summary.json");
  const auto with_dir = snapshot(out);
  r = run_limited("plan-route", map + " --goal 2,1 --start 0.5,0.5 -q -o " + out.string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("summary.json': is a directory; nothing was written"), std::string::npos)
      << r.err;
  EXPECT_EQ(snapshot(out), with_dir);
  // No staging directory is left beside the output directory.
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find("indoormap-staging"), std::string::npos)
        << e.path();
}

TEST(OutputSet, FilesOfTheAppsEarlierRunAreRemovedOthersKept) {
  const auto dir = test::scratch_dir();
  const std::string map = "--map " + small_map(dir).string();
  const fs::path out = dir / "out";
  ASSERT_EQ(run_limited("plan-route", map + kPlanArgs + out.string()).exit_code, 0);
  // An earlier plan-route run that wrote one more file (old/extra.png), and the user's file.
  fs::create_directories(out / "old");
  test::write_text(out / "old" / "extra.png", "stale");
  test::write_text(out / "notes.txt", "mine");
  test::write_text(out / ".indoormap-outputs",
                   test::read_text(out / ".indoormap-outputs") +
                       "plan-route old/extra.png\nmap-eval eval.json\n");
  test::write_text(out / "eval.json", "{}");
  const auto r = run_limited("plan-route", map + kPlanArgs + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(out / "old")) << "stale file (and its emptied folder) left behind";
  EXPECT_EQ(test::read_text(out / "notes.txt"), "mine");
  EXPECT_EQ(test::read_text(out / "eval.json"), "{}");  // another app's file
  const std::string manifest = test::read_text(out / ".indoormap-outputs");
  EXPECT_NE(manifest.find("map-eval eval.json\n"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("plan-route summary.json\n"), std::string::npos) << manifest;
  EXPECT_EQ(manifest.find("extra.png"), std::string::npos) << manifest;
}

}  // namespace

namespace {

// ------------------------------------------------------------------ silent acceptances

struct RefusedCase {
  std::string name;
  std::string app;
  std::vector<std::pair<std::string, std::string>> files;  ///< written into {d}
  std::string args;    ///< {d}: the scratch dir; outputs to {d}/out
  int exit_code;       ///< 2 for the errors; 0 for a warning
  std::string expect;  ///< substring of stderr ({d} replaced)
};

void PrintTo(const RefusedCase& c, std::ostream* os) { *os << c.name; }

class NoLongerSilent : public ::testing::TestWithParam<RefusedCase> {};

TEST_P(NoLongerSilent, ErrorOrWarningWithTheDocumentedExitCode) {
  const auto& c = GetParam();
  const auto dir = test::scratch_dir();
  for (const auto& [name, content] : c.files) test::write_text(dir / name, content);
  const auto r = run_limited(c.app, replace_all(c.args, "{d}", dir.string()));
  EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
  EXPECT_NE(r.err.find(replace_all(c.expect, "{d}", dir.string())), std::string::npos) << r.err;
  if (c.exit_code != 0) {
    EXPECT_TRUE(!fs::exists(dir / "out") || fs::is_empty(dir / "out")) << "partial output";
  }
}

const std::string kPly = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                         "property float y\nproperty float z\nend_header\n";
const std::string kMapYaml = "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n";

// A 3DTK scan (cm, left-handed, y up) of a 4 x 3 m room, 2.5 m high: floor, ceiling, walls.
std::string tdtk_room() {
  std::string s;
  auto put = [&](double x, double y, double z) {  // output frame (m, z up) -> 3DTK
    s += std::to_string(-y * 100) + " " + std::to_string(z * 100) + " " +
         std::to_string(x * 100) + "\n";
  };
  for (double x = 0; x <= 4; x += 0.05)
    for (double y = 0; y <= 3; y += 0.05) {
      put(x, y, 0);
      put(x, y, 2.5);
    }
  for (double z = 0; z <= 2.5; z += 0.05) {
    for (double x = 0; x <= 4; x += 0.05) put(x, 0, z), put(x, 3, z);
    for (double y = 0; y <= 3; y += 0.05) put(0, y, z), put(4, y, z);
  }
  return s;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, NoLongerSilent,
    ::testing::Values(
        RefusedCase{"cloud_points_1e308", "pcd-to-map", {{"c.xyz", "0 0 0\n1e308 0 0\n0 1 1\n"}},
                    "{d}/c.xyz -o {d}/out", 2,
                    "{d}/c.xyz: no map: the layout has no wall, furniture or free cell"},
        RefusedCase{"ply_ascii_extra_value", "pcd-to-map",
                    {{"c.ply", kPly + "0 0 0 7\n1 0 0\n0 1 1\n"}}, "{d}/c.ply -o {d}/out", 2,
                    "{d}/c.ply:8: PLY data line has more values than the 3 properties of "
                    "'vertex'"},
        RefusedCase{"ply_ascii_short_line", "pcd-to-map",
                    {{"c.ply", kPly + "0 0 0\n1 0\n0 1 1\n0 0 0\n"}}, "{d}/c.ply -o {d}/out", 2,
                    "{d}/c.ply:9: PLY data line has fewer values than the 3 properties"},
        RefusedCase{"yaml_key_given_twice", "pcd-to-map",
                    {{"c.yaml", "voxel:\n  cell_m: 0.05\nvoxel:\n  cell_m: 0.1\n"},
                     {"c.xyz", "0 0 0\n"}},
                    "-c {d}/c.yaml {d}/c.xyz -o {d}/out", 2,
                    "{d}/c.yaml:3: key 'voxel' is given twice"},
        RefusedCase{"yaml_nested_key_given_twice", "plan-route",
                    {{"c.yaml", "robot:\n  width_m: 0.5\n  width_m: 0.6\n"}},
                    "-c {d}/c.yaml --map {d}/m.pgm --resolution 0.05 --start 0,0 --goal 1,1 -o "
                    "{d}/out",
                    2, "{d}/c.yaml:3: key 'robot.width_m' is given twice"},
        RefusedCase{"map_yaml_mode_banana", "plan-route",
                    {{"m.yaml", kMapYaml + "mode: banana\n"}, {"m.pgm", map_fixtures::kPgm}},
                    "--map {d}/m.yaml --start 0,0 --goal 0.05,0 -o {d}/out", 2,
                    "{d}/m.yaml:4: key 'mode': 'banana' is not supported (only 'trinary'"},
        RefusedCase{"scene_sim_seed_negative", "scene-sim", {}, "--random --seed -1 -o {d}/out",
                    2, "--seed"},
        RefusedCase{"explore_sim_seed_negative", "explore-sim", {{"m.pgm", map_fixtures::kPgm}},
                    "{d}/m.pgm --resolution 0.05 --seed -1 -o {d}/out", 2, "--seed"},
        RefusedCase{"tdtk_scan_without_pose", "pcd-to-map", {{"scan000.3d", tdtk_room()}},
                    "{d} -q -o {d}/out", 0,
                    "pcd-to-map: warning: {d}/scan000.3d: no scan000.pose or scan000.frames "
                    "beside it: read with the identity pose"}),
    [](const auto& info) { return info.param.name; });

}  // namespace

namespace {

// A 4 x 3 x 2.5 m room of points 5 cm apart (floor, ceiling, four walls), with a 0.8 x 0.6 m desk
// 0.75 m high in the middle when `desk`.
std::string room_xyz(bool desk) {
  std::string s;
  auto put = [&](double x, double y, double z) {
    char line[64];
    std::snprintf(line, sizeof line, "%.3f %.3f %.3f\n", x, y, z);
    s += line;
  };
  auto steps = [](double a, double b) { return static_cast<int>(std::lround((b - a) / 0.05)); };
  auto at = [](double a, int i) { return a + 0.05 * i; };
  for (int i = 0; i <= steps(0, 4); ++i)
    for (int j = 0; j <= steps(0, 3); ++j) put(at(0, i), at(0, j), 0), put(at(0, i), at(0, j), 2.5);
  for (int k = 0; k <= steps(0, 2.5); ++k) {
    for (int i = 0; i <= steps(0, 4); ++i) put(at(0, i), 0, at(0, k)), put(at(0, i), 3, at(0, k));
    for (int j = 0; j <= steps(0, 3); ++j) put(0, at(0, j), at(0, k)), put(4, at(0, j), at(0, k));
  }
  if (!desk) return s;
  for (int i = 0; i <= steps(1.5, 2.3); ++i)
    for (int j = 0; j <= steps(1.2, 1.8); ++j) put(at(1.5, i), at(1.2, j), 0.75);
  for (int k = 0; k <= steps(0, 0.75); ++k) {
    for (int i = 0; i <= steps(1.5, 2.3); ++i)
      put(at(1.5, i), 1.2, at(0, k)), put(at(1.5, i), 1.8, at(0, k));
    for (int j = 0; j <= steps(1.2, 1.8); ++j)
      put(1.5, at(1.2, j), at(0, k)), put(2.3, at(1.2, j), at(0, k));
  }
  return s;
}

TEST(OutputSet, FurnitureExtractRunWithoutObjectsRemovesTheEarlierObjectFiles) {
  const auto dir = test::scratch_dir();
  test::write_text(dir / "desk.xyz", room_xyz(true));
  test::write_text(dir / "empty.xyz", room_xyz(false));
  const fs::path out = dir / "out";
  const std::string opts = " --scanner 1,1,1.2 -q -o ";
  auto r = run_limited("furniture-extract", (dir / "desk.xyz").string() + opts + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(fs::exists(out / "objects")) << "the desk room should give object point files";
  ASSERT_FALSE(fs::is_empty(out / "objects"));

  // `objects` a plain file where the folder goes: exit 1, the directory byte for byte as before.
  const fs::path out2 = dir / "out2";
  fs::copy(out, out2, fs::copy_options::recursive);
  fs::remove_all(out2 / "objects");
  test::write_text(out2 / "objects", "a file in the way");
  const auto before = snapshot(out2);
  r = run_limited("furniture-extract", (dir / "desk.xyz").string() + opts + out2.string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("objects': exists and is not a directory"), std::string::npos) << r.err;
  EXPECT_EQ(snapshot(out2), before);

  // A run that finds no object: the earlier run's objects/object_*.pcd go, the user's file stays.
  test::write_text(out / "notes.txt", "mine");
  r = run_limited("furniture-extract", (dir / "empty.xyz").string() + opts + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(out / "objects")) << "stale object files left behind";
  EXPECT_EQ(test::read_text(out / "notes.txt"), "mine");
  EXPECT_TRUE(fs::exists(out / "objects.json"));
}

}  // namespace
