// Reliability round 3 (issue 18, "messages that mislead"): each case runs an app on a tiny input
// and checks the exit code and that the message names the file, the key and the real problem.
// Rows R27... of docs/robustness.md. The unit and up-axis hints are heuristics on the cloud's
// extent: ReliabilityHints checks that they fire on the wrong reading and stay silent on the
// right one (their margins on the project's cloud, the Jacobs scan and simulated scenes are
// measured in docs/robustness.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "map_fixtures.hpp"
#include "reliability_fixtures.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using namespace indoormap::reliability;
using test::replace_all;

namespace {

// A box room lx x ly x lz m of points `step` apart (floor, ceiling, four walls), z up, in `unit`
// (1: metres, 0.001: millimetres). y_up: written with y up (x, z, y), as a y-up scanner would.
std::string box_room(double lx, double ly, double lz, double step, double unit, bool y_up) {
  std::string s;
  auto put = [&](double x, double y, double z) {
    char line[96];
    if (y_up) std::swap(y, z);
    std::snprintf(line, sizeof line, "%.4f %.4f %.4f\n", x / unit, y / unit, z / unit);
    s += line;
  };
  const int nx = static_cast<int>(lx / step + 0.5), ny = static_cast<int>(ly / step + 0.5),
            nz = static_cast<int>(lz / step + 0.5);
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) put(i * step, j * step, 0), put(i * step, j * step, lz);
  for (int k = 1; k < nz; ++k) {
    for (int i = 0; i <= nx; ++i) put(i * step, 0, k * step), put(i * step, ly, k * step);
    for (int j = 1; j < ny; ++j) put(0, j * step, k * step), put(lx, j * step, k * step);
  }
  return s;
}

struct MessageCase {
  std::string name;
  std::string app;
  std::vector<std::pair<std::string, std::string>> files;  ///< written into {d}
  std::string args;  ///< {d}: the scratch dir; outputs to {d}/out
  int exit_code;
  std::string expect;     ///< substring of stderr ({d} replaced)
  std::string link = "";  ///< when set: {d}/<link> made a symbolic link to {d}/missing (dangling)
};

void PrintTo(const MessageCase& c, std::ostream* os) {
  *os << c.name;
}

class ReliabilityMessages : public ::testing::TestWithParam<MessageCase> {};

TEST_P(ReliabilityMessages, NameTheFileTheKeyAndTheRealProblem) {
  const auto& c = GetParam();
  const auto dir = test::scratch_dir();
  for (const auto& [name, content] : c.files) test::write_text(dir / name, content);
  if (!c.link.empty()) fs::create_symlink(dir / "missing", dir / c.link);
  const auto r = run_limited(c.app, replace_all(c.args, "{d}", dir.string()));
  EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
  EXPECT_NE(r.err.find(replace_all(c.expect, "{d}", dir.string())), std::string::npos) << r.err;
  if (c.exit_code != 0) {
    EXPECT_TRUE(!fs::exists(dir / "out") || fs::is_empty(dir / "out")) << "partial output";
    EXPECT_FALSE(fs::exists(dir / "missing")) << "the dangling link's target was created";
  }
}

const std::string kPlan = " --start 0.5,0.5 --goal 1,1 -o {d}/out";
const std::string kScan = "0 0 0\n100 0 0\n0 100 0\n0 0 100\n";  // a 3DTK scan (cm)
const std::string kPoints = "0 0 0\n1 0 0\n0 1 1\n";

INSTANTIATE_TEST_SUITE_P(
    Cases, ReliabilityMessages,
    ::testing::Values(
        MessageCase{"plan_route_resolution_negative",
                    "plan-route",
                    {{"m.pgm", map_fixtures::kPgm}},
                    "--map {d}/m.pgm --resolution -1" + kPlan,
                    2,
                    "--resolution -1: must be a positive finite number of metres per pixel (map "
                    "{d}/m.pgm)"},
        MessageCase{"out_dangling_symlink",
                    "pcd-to-map",
                    {{"c.xyz", kPoints}},
                    "{d}/c.xyz -q -o {d}/out",
                    1,
                    "cannot write '{d}/out': is a symbolic link to '{d}/missing', which does not "
                    "exist (a dangling link)",
                    "out"},
        MessageCase{"scans_beyond_the_limit",
                    "pcd-to-map",
                    {{"scan000.3d", kScan}},
                    "{d} --scans 0-9999999 -o {d}/out",
                    2,
                    "--scans: scan numbers are at most 1000000, got '0-9999999'"},
        MessageCase{"plan_route_resolution_tiny",
                    "plan-route",
                    {{"m.pgm", map_fixtures::kPgm}},
                    "--map {d}/m.pgm --resolution 1e-300" + kPlan,
                    2,
                    "{d}/m.pgm: the robot's clearance d_save = max(robot.width_m, robot.length_m) "
                    "/ 2 + robot.extra_m = "},
        MessageCase{"plan_route_robot_huge",
                    "plan-route",
                    {{"m.pgm", map_fixtures::kPgm}, {"c.yaml", "robot:\n  width_m: 1e9\n"}},
                    "-c {d}/c.yaml --map {d}/m.pgm --resolution 0.05" + kPlan,
                    2,
                    "robot.extra_m = 5e+08 m is 1e+10 cells of the map resolution 0.05 m, above "
                    "the limit of 2000 cells: check the robot size (metres)"},
        MessageCase{"plan_route_d_max_too_far",
                    "plan-route",
                    {{"m.pgm", map_fixtures::kPgm}, {"c.yaml", "planner:\n  d_max_m: 100\n"}},
                    "-c {d}/c.yaml --map {d}/m.pgm --resolution 0.05" + kPlan,
                    2,
                    "{d}/m.pgm: planner.d_max_m 100 m is 2000 cells of the map resolution 0.05 "
                    "m, above the limit of 300 cells"},
        MessageCase{"tdtk_pose_1e300",
                    "pcd-to-map",
                    {{"scan000.3d", kScan}, {"scan000.pose", "1e300 0 0\n0 0 0\n"}},
                    "{d} -o {d}/out",
                    2,
                    "{d}/scan000.pose:1: the pose's translation is 1e+300 cm from the origin"},
        MessageCase{
            "tdtk_frames_all_zero",
            "pcd-to-map",
            {{"scan000.3d", kScan}, {"scan000.frames", "0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 2\n"}},
            "{d} -o {d}/out",
            2,
            "{d}/scan000.frames:1: the matrix's rotation part has determinant 0, expected "
            "1"},
        MessageCase{"cloud_heights_far_apart",
                    "pcd-to-map",
                    {{"c.xyz", "0 0 0\n0 0 1000\n0 0 2000\n"}},
                    "{d}/c.xyz -o {d}/out",
                    2,
                    "all points lie at one height (within 0.050 m): no floor, furniture and walls "
                    "to tell apart; the points span heights 0 .. 2000 m, but they are more than "
                    "voxel.bounds_gap_m (1 m) apart"},
        MessageCase{"cloud_in_millimetres",
                    "pcd-to-map",
                    {{"c.xyz", box_room(4, 3, 2.5, 0.1, 0.001, false)}},
                    "{d}/c.xyz -o {d}/out",
                    2,
                    "the cloud spans 4000 x 3000 x 2500 m (read with a unit of 1 m): is it in "
                    "millimetres or centimetres? try --unit mm"},
        MessageCase{"cloud_in_millimetres_grid_over_budget",
                    "pcd-to-map",
                    {{"c.xyz", box_room(4, 3, 2.5, 0.1, 0.001, false)},
                     {"c.yaml", "voxel:\n  bounds_gap_m: 500\n"}},
                    "-c {d}/c.yaml {d}/c.xyz -o {d}/out",
                    2,
                    "{d}/c.xyz: the cloud spans 4000 x 3000 x 2500 m (read with a unit of 1 m): "
                    "is it in millimetres or centimetres? try --unit mm (or --unit cm, "
                    "input.unit_m) (the voxel grid would be"}),
    [](const auto& info) { return info.param.name; });

// The up-axis warning fires on a y-up room read as z up, and neither on the same room read with
// --up-axis y nor on a z-up room in millimetres read with --unit mm (nor does the unit hint).
TEST(ReliabilityHints, UpAxisAndUnitHintsFireOnlyOnTheWrongReading) {
  const auto dir = test::scratch_dir();
  test::write_text(dir / "y_up.xyz", box_room(6, 5, 2.5, 0.1, 1.0, true));
  test::write_text(dir / "mm.xyz", box_room(6, 5, 2.5, 0.1, 0.001, false));
  const std::string up_hint = "check --up-axis (z or y; input.up_axis)";
  auto run = [&](const std::string& args, const std::string& out) {
    return run_limited("pcd-to-map", args + " -q -o " + (dir / out).string());
  };
  auto r = run((dir / "y_up.xyz").string(), "wrong");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("pcd-to-map: warning: " + (dir / "y_up.xyz").string() +
                       ": the cloud is 5.05 m high but only 2.55 m wide along its narrower "
                       "side: is its up axis another one? " +
                       up_hint),
            std::string::npos)
      << r.err;
  r = run((dir / "y_up.xyz").string() + " --up-axis y", "right");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("--up-axis"), std::string::npos) << r.err;
  r = run((dir / "mm.xyz").string() + " --unit mm", "mm");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("--unit"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("--up-axis"), std::string::npos) << r.err;
}

}  // namespace
