// Reliability round 2, through the apps: every file an app reads is checked by one function
// (indoormap::check_input_file: a FIFO or a directory is exit 2 naming the file, never a hang);
// the silent acceptances of round 1 are errors or warnings; plan-route's work budget is a result
// (exit 3). Output sets: test_output_set.cpp. Rows of docs/robustness.md ("Reliability, round 2").
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "map_fixtures.hpp"
#include "reliability_fixtures.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using namespace indoormap::reliability;
using test::replace_all;

namespace {

// ------------------------------------------------------------------ FIFOs and directories

enum class Kind { kFifo, kDirectory };

struct InputCase {
  std::string name;
  std::string app;
  std::string args;  ///< {d}: the scratch dir, {bad}: the FIFO or directory; outputs to {d}/out
  std::string bad;   ///< file name of the bad input in {d}
};

void PrintTo(const InputCase& c, std::ostream* os) {
  *os << c.name;
}

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
  const std::string problem =
      kind == Kind::kFifo ? ": is not a regular file (a FIFO" : ": is a directory, expected ";
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
            InputCase{"explore_sim_map", "explore-sim", "{bad} -o {d}/out", "map.yaml"}),
        ::testing::Values(Kind::kFifo, Kind::kDirectory)),
    [](const auto& info) {
      return std::get<0>(info.param).name +
             (std::get<1>(info.param) == Kind::kFifo ? "_fifo" : "_directory");
    });

// ------------------------------------------------------------------ silent acceptances

struct RefusedCase {
  std::string name;
  std::string app;
  std::vector<std::pair<std::string, std::string>> files;  ///< written into {d}
  std::string args;    ///< {d}: the scratch dir; outputs to {d}/out
  int exit_code;       ///< 2 for the errors; 0 for a warning
  std::string expect;  ///< substring of stderr ({d} replaced)
};

void PrintTo(const RefusedCase& c, std::ostream* os) {
  *os << c.name;
}

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

const std::string kPly =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
    "property float y\nproperty float z\nend_header\n";
const std::string kMapYaml = "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n";

INSTANTIATE_TEST_SUITE_P(
    Cases, NoLongerSilent,
    ::testing::Values(
        RefusedCase{"cloud_points_1e308",
                    "pcd-to-map",
                    {{"c.xyz", "0 0 0\n1e308 0 0\n0 1 1\n"}},
                    "{d}/c.xyz -o {d}/out",
                    2,
                    "{d}/c.xyz: no map: the layout has no wall, furniture or free cell"},
        RefusedCase{"ply_ascii_extra_value",
                    "pcd-to-map",
                    {{"c.ply", kPly + "0 0 0 7\n1 0 0\n0 1 1\n"}},
                    "{d}/c.ply -o {d}/out",
                    2,
                    "{d}/c.ply:8: PLY data line has more values than the 3 properties of "
                    "'vertex'"},
        RefusedCase{"ply_ascii_short_line",
                    "pcd-to-map",
                    {{"c.ply", kPly + "0 0 0\n1 0\n0 1 1\n0 0 0\n"}},
                    "{d}/c.ply -o {d}/out",
                    2,
                    "{d}/c.ply:9: PLY data line has fewer values than the 3 properties"},
        RefusedCase{
            "yaml_key_given_twice",
            "pcd-to-map",
            {{"c.yaml", "voxel:\n  cell_m: 0.05\nvoxel:\n  cell_m: 0.1\n"}, {"c.xyz", "0 0 0\n"}},
            "-c {d}/c.yaml {d}/c.xyz -o {d}/out",
            2,
            "{d}/c.yaml:3: key 'voxel' is given twice"},
        RefusedCase{"yaml_nested_key_given_twice",
                    "plan-route",
                    {{"c.yaml", "robot:\n  width_m: 0.5\n  width_m: 0.6\n"}},
                    "-c {d}/c.yaml --map {d}/m.pgm --resolution 0.05 --start 0,0 --goal 1,1 -o "
                    "{d}/out",
                    2,
                    "{d}/c.yaml:3: key 'robot.width_m' is given twice"},
        RefusedCase{"map_yaml_mode_banana",
                    "plan-route",
                    {{"m.yaml", kMapYaml + "mode: banana\n"}, {"m.pgm", map_fixtures::kPgm}},
                    "--map {d}/m.yaml --start 0,0 --goal 0.05,0 -o {d}/out",
                    2,
                    "{d}/m.yaml:4: key 'mode': 'banana' is not supported (only 'trinary'"},
        RefusedCase{"scene_sim_seed_negative",
                    "scene-sim",
                    {},
                    "--random --seed -1 -o {d}/out",
                    2,
                    "--seed"},
        RefusedCase{"explore_sim_seed_negative",
                    "explore-sim",
                    {{"m.pgm", map_fixtures::kPgm}},
                    "{d}/m.pgm --resolution 0.05 --seed -1 -o {d}/out",
                    2,
                    "--seed"},
        RefusedCase{"tdtk_scan_without_pose",
                    "pcd-to-map",
                    {{"scan000.3d", tdtk_room()}},
                    "{d} -q -o {d}/out",
                    0,
                    "pcd-to-map: warning: {d}/scan000.3d: no scan000.pose or scan000.frames "
                    "beside it: read with the identity pose"}),
    [](const auto& info) { return info.param.name; });

}  // namespace

namespace {

TEST(PlanRouteBudget, ReachingItIsExitThreeWithTheBudgetNamed) {
  const auto dir = test::scratch_dir();
  const std::string map = "--map " + small_map(dir).string();
  // Moves of at most 0.5 m to a goal 2.2 m away need five moves; two expanded nodes cannot.
  test::write_text(dir / "c.yaml", "planner:\n  d_max_m: 0.5\n  max_nodes: 2\n");
  auto r = run_limited(
      "plan-route", map + " -c " + (dir / "c.yaml").string() + kPlanArgs + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("plan-route: no route found within the work budget: planner.max_nodes 2 "
                       "nodes reached"),
            std::string::npos)
      << r.err;
  const std::string summary = test::read_text(dir / "out" / "summary.json");
  EXPECT_NE(summary.find("\"budget_reached\": \"planner.max_nodes\""), std::string::npos)
      << summary;
  // max_seconds is validated beside its definition.
  test::write_text(dir / "s.yaml", "planner:\n  max_seconds: 0\n");
  r = run_limited("plan-route",
                  map + " -c " + (dir / "s.yaml").string() + kPlanArgs + (dir / "out2").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("planner.max_seconds: must be in (0, 86400] s"), std::string::npos) << r.err;
}

}  // namespace
