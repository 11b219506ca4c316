// Bad input across the apps, one row of docs/robustness.md per case: the exit code, the message
// (which names the file) and, for the apps, that no output is left behind. Library rows cover
// readers whose app lands later (read_ros_map: plan-route) with the exception type the app maps
// to its exit code (run_guarded: InputError / UsageError / BudgetError -> 2).
#include <gtest/gtest.h>

#include <cstring>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/core/errors.hpp"
#include "map_fixtures.hpp"
#include "test_support.hpp"

using namespace indoormap;
namespace fs = std::filesystem;
using map_fixtures::kPgm;
using map_fixtures::png_header;
using test::replace_all;

namespace {

std::string pcd(const std::string& data, std::uint64_t n, const std::string& fields = "x y z",
                const std::string& type = "F F F") {
  return "VERSION 0.7\nFIELDS " + fields + "\nSIZE 4 4 4\nTYPE " + type + "\nCOUNT 1 1 1\nWIDTH " +
         std::to_string(n) + "\nHEIGHT 1\nPOINTS " + std::to_string(n) + "\nDATA " + data + "\n";
}

std::string ply(const std::string& format, std::uint64_t n, const std::string& props = "xyz") {
  std::string s = "ply\nformat " + format + " 1.0\nelement vertex " + std::to_string(n) + "\n";
  for (char c : props) s += std::string("property float ") + c + "\n";
  return s + "end_header\n";
}

// A valid room (two heights, walls), small enough to run fast: a 2 x 2 x 2.5 m box every 10 cm.
std::string box_xyz() {
  std::string s;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      const double a = i * 0.1, b = j * 0.1;
      s += std::to_string(a) + " " + std::to_string(b) + " 0\n";
      s += std::to_string(a) + " " + std::to_string(b) + " 2.5\n";
    }
  return s;
}

}  // namespace

// ------------------------------------------------------------------------------ pcd-to-map

struct AppCase {
  std::string name;
  /// Files to create (path relative to the scratch dir; a path ending in '/' is a directory).
  std::vector<std::pair<std::string, std::string>> files;
  std::string args;  ///< {d} is the scratch dir; outputs go to {d}/out
  int exit_code;
  std::string expect;    ///< substring of stderr ({d} replaced too)
  bool prefixed = true;  ///< "pcd-to-map: <message>" (CLI11's own parse errors are not)
};

void PrintTo(const AppCase& c, std::ostream* os) {
  *os << c.name;
}

class PcdToMapRefuses : public ::testing::TestWithParam<AppCase> {};

TEST_P(PcdToMapRefuses, WithMessageExitCodeAndNoOutput) {
  const auto& c = GetParam();
  const auto dir = test::scratch_dir();
  for (const auto& [name, content] : c.files) {
    if (name.ends_with('/'))
      fs::create_directories(dir / name);
    else {
      fs::create_directories((dir / name).parent_path());
      test::write_text(dir / name, content);
    }
  }
  const auto r = test::run_app("pcd-to-map", replace_all(c.args, "{d}", dir.string()));
  EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
  EXPECT_NE(r.err.find(replace_all(c.expect, "{d}", dir.string())), std::string::npos) << r.err;
  if (c.prefixed) {
    EXPECT_EQ(r.err.rfind("pcd-to-map: ", 0), 0u) << r.err;
  }
  if (fs::is_regular_file(dir / "out")) {
    EXPECT_EQ(test::read_text(dir / "out"), "keep") << "clobbered";
  } else {
    EXPECT_TRUE(!fs::exists(dir / "out") || fs::is_empty(dir / "out")) << "partial output";
  }
}

const std::string kIn = "{d}/in";
const std::string kOut = " -o {d}/out";

INSTANTIATE_TEST_SUITE_P(
    Cases, PcdToMapRefuses,
    ::testing::Values(
        // Clouds: any format.
        AppCase{"directory_with_cloud_extension",
                {{"in.pcd/", ""}},
                kIn + ".pcd" + kOut,
                2,
                "in.pcd: is a directory, expected a file"},
        AppCase{"budget_over_two_inputs",
                {{"a.xyz", "1 2 3\n4 5 6\n"},
                 {"b.xyz", "1 2 3\n4 5 6\n"},
                 {"c.yaml", "input:\n  max_points: 3\n"}},
                "{d}/a.xyz {d}/b.xyz -c {d}/c.yaml" + kOut,
                2,
                "b.xyz: 2 points exceed the point budget (max_points 3, 2 already loaded)"},
        // PCD.
        AppCase{"pcd_binary_truncated",
                {{"in.pcd", pcd("binary", 4) + std::string(20, 'a')}},
                kIn + ".pcd" + kOut,
                2,
                "PCD data section too short for POINTS 4 (truncated file?)"},
        AppCase{"pcd_ascii_short_line",
                {{"in.pcd", pcd("ascii", 2) + "1 2 3\n4 5\n\n\n"}},
                kIn + ".pcd" + kOut,
                2,
                "in.pcd:11: PCD data line has 2 values, expected 3"},
        AppCase{"pcd_ascii_fewer_lines",
                {{"in.pcd", pcd("ascii", 3) + "1 2 3\n4 5 6\n"}},
                kIn + ".pcd" + kOut,
                2,
                "PCD data section too short for POINTS 3 (truncated file?)"},
        AppCase{"pcd_ascii_not_a_number",
                {{"in.pcd", pcd("ascii", 1) + "1 two 3\n"}},
                kIn + ".pcd" + kOut,
                2,
                "PCD value 'two' of field y is not a number"},
        AppCase{"pcd_xyz_not_float",
                {{"in.pcd", pcd("ascii", 1, "x y z", "F I F") + "1 2 3\n"}},
                kIn + ".pcd" + kOut,
                2,
                "PCD header: field 'y' must be a float (TYPE F, COUNT 1)"},
        AppCase{"pcd_unknown_header_line",
                {{"in.pcd", "VERSION 0.7\nCOLOUR red\n" + pcd("ascii", 1).substr(12) + "1 2 3\n"}},
                kIn + ".pcd" + kOut,
                2,
                "in.pcd:2: PCD header: unknown header line 'COLOUR red'"},
        AppCase{
            "pcd_header_crlf_ok_but_truncated",
            {{"in.pcd", replace_all(pcd("ascii", 3), "\n", "\r\n") + "1 2 3\r\n4 5 6\r\n\r\n\r\n"}},
            kIn + ".pcd" + kOut,
            2,
            "PCD data has 2 points but POINTS says 3"},
        AppCase{"pcd_compressed_sizes_wrong",
                {{"in.pcd", pcd("binary_compressed", 4) + std::string("\x09\0\0\0\x31\0\0\0", 8) +
                                std::string(60, 'z')}},
                kIn + ".pcd" + kOut,
                2,
                "PCD binary_compressed: uncompressed size 49 does not match"},
        // Found by the pcd fuzz target: PCL ends its header at a blank line and then crashes.
        AppCase{
            "pcd_header_blank_line_with_cr",
            {{"in.pcd", " \r\n" + pcd("binary", 1) + std::string(12, '\0')}},
            kIn + ".pcd" + kOut,
            2,
            "in.pcd:1: PCD header: blank line of spaces, tabs or a CR alone (only empty lines are "
            "allowed)"},
        // Also found by fuzzing: PCL reads header lines on after DATA, into the binary data.
        AppCase{"pcd_binary_data_looks_like_header",
                {{"in.pcd", pcd("binary", 1) + "COUNT 1 1 1\n"}},
                kIn + ".pcd" + kOut,
                2,
                "in.pcd:9: PCD header: the data section starts with bytes that PCL would read as a "
                "COUNT header line"},
        AppCase{"pcd_points_over_budget",
                {{"in.pcd", pcd("binary", 4) + std::string(48, '\0')},
                 {"c.yaml", "input:\n  max_points: 3\n"}},
                kIn + ".pcd -c {d}/c.yaml" + kOut,
                2,
                "4 points exceed the point budget (max_points 3)"},
        // PLY.
        AppCase{"ply_not_ply",
                {{"in.ply", "PLY\nformat ascii 1.0\n"}},
                kIn + ".ply" + kOut,
                2,
                "in.ply:1: PLY header: the file does not start with 'ply'"},
        AppCase{"ply_vertex_count_beyond_body",
                {{"in.ply", ply("binary_little_endian", 4000000000) + std::string(24, 'a')}},
                kIn + ".ply" + kOut,
                2,
                "PLY data section too short for 4000000000 'vertex' elements"},
        AppCase{"ply_no_vertex",
                {{"in.ply", "ply\nformat ascii 1.0\nelement face 1\nend_header\n\n"}},
                kIn + ".ply" + kOut,
                2,
                "PLY header: no 'element vertex'"},
        AppCase{"ply_no_z",
                {{"in.ply", ply("ascii", 1, "xy") + "1 2\n"}},
                kIn + ".ply" + kOut,
                2,
                "PLY header: vertex has no property 'z'"},
        AppCase{"ply_ascii_not_a_number",
                {{"in.ply", ply("ascii", 2) + "1 2 3\n4 abc 6\n"}},
                kIn + ".ply" + kOut,
                2,
                "in.ply:9: PLY value 'abc' is not a number"},
        AppCase{"ply_binary_truncated",
                {{"in.ply",
                  "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n"
                  "property float y\nproperty float z\nproperty list uchar int f\nend_header\n" +
                      std::string(25, '\0') + "\x09" + std::string(12, '\0')}},
                kIn + ".ply" + kOut,
                2,
                "PLY data section ends early (truncated file)"},
        // XYZ text.
        AppCase{"xyz_two_values",
                {{"in.xyz", "1 2 3\n1 2\n"}},
                kIn + ".xyz" + kOut,
                2,
                "in.xyz:2: malformed line, expected 'x y z ...'"},
        AppCase{"xyz_line_over_1mib",
                {{"in.xyz", "1 2 3 " + std::string(3 << 20, '7') + "\n"}},
                kIn + ".xyz" + kOut,
                2,
                "in.xyz:1: line longer than 1 MiB"},
        AppCase{"xyz_binary_junk",
                {{"in.xyz", std::string("\x01\x02\xff\0\x7f\n", 6)}},
                kIn + ".xyz" + kOut,
                2,
                "in.xyz:1: malformed line"},
        // 3DTK.
        AppCase{"tdtk_dir_without_scans",
                {{"scans/readme.txt", "x"}},
                "{d}/scans" + kOut,
                2,
                "scans: no 3DTK scan files (scanNNN.3d) in this directory"},
        AppCase{"tdtk_scans_range_empty",
                {{"scans/scan000.3d", "0 0 100\n"}},
                "{d}/scans --scans 5-7" + kOut,
                2,
                "no 3DTK scan files (scanNNN.3d) in this directory "
                "within scan numbers 5..7"},
        AppCase{"tdtk_bad_pose",
                {{"scans/scan000.3d", "0 0 100\n"}, {"scans/scan000.pose", "1 2\n0 0 0\n"}},
                "{d}/scans" + kOut,
                2,
                "scan000.pose:1: pose line 1 must be the translation 'x y z' in cm"},
        AppCase{"tdtk_bad_frames",
                {{"scans/scan000.3d", "0 0 100\n"}, {"scans/scan000.frames", "1 0 0 1 2\n"}},
                "{d}/scans" + kOut,
                2,
                "scan000.frames:1: frames line must hold 16 numbers"},
        // Config file and command line.
        AppCase{"config_missing",
                {{"in.xyz", box_xyz()}},
                kIn + ".xyz -c {d}/none.yaml" + kOut,
                2,
                "none.yaml: cannot open the config file"},
        AppCase{"config_invalid_yaml",
                {{"in.xyz", box_xyz()}, {"c.yaml", "voxel: [1,\n"}},
                kIn + ".xyz -c {d}/c.yaml" + kOut,
                2,
                "invalid YAML"},
        AppCase{"config_not_a_mapping",
                {{"in.xyz", box_xyz()}, {"c.yaml", "- voxel\n"}},
                kIn + ".xyz -c {d}/c.yaml" + kOut,
                2,
                "c.yaml: the config must be a mapping of sections"},
        AppCase{"config_unknown_section",
                {{"in.xyz", box_xyz()}, {"c.yaml", "voxels:\n  cell_m: 1\n"}},
                kIn + ".xyz -c {d}/c.yaml" + kOut,
                2,
                "c.yaml:1: unknown section 'voxels'"},
        AppCase{"config_key_not_a_name",
                {{"in.xyz", box_xyz()}, {"c.yaml", "? [a, b]\n: 1\n"}},
                kIn + ".xyz -c {d}/c.yaml" + kOut,
                2,
                "c.yaml:1: keys must be names, not lists or mappings"},
        AppCase{"config_integer_not_integral",
                {{"in.xyz", box_xyz()}, {"c.yaml", "level:\n  iterations: 2.5\n"}},
                kIn + ".xyz -c {d}/c.yaml" + kOut,
                2,
                "c.yaml:2: key 'level.iterations': expected an integer in range"},
        AppCase{"config_integer_nan",
                {{"in.xyz", box_xyz()}, {"c.yaml", "input:\n  max_points: .nan\n"}},
                kIn + ".xyz -c {d}/c.yaml" + kOut,
                2,
                "key 'input.max_points': expected an integer in range"},
        AppCase{"config_out_of_range",
                {{"in.xyz", box_xyz()}, {"c.yaml", "voxel:\n  cell_m: 0\n"}},
                kIn + ".xyz -c {d}/c.yaml" + kOut,
                2,
                "invalid parameter voxel.cell_m: must be in [0.001, 10] m"},
        AppCase{"config_bad_up_axis",
                {{"in.xyz", box_xyz()}, {"c.yaml", "input:\n  up_axis: x\n"}},
                kIn + ".xyz -c {d}/c.yaml" + kOut,
                2,
                "key 'input.up_axis': expected 'z' or 'y', got 'x'"},
        AppCase{"cli_unit_not_a_number",
                {{"in.xyz", box_xyz()}},
                kIn + ".xyz --unit feet" + kOut,
                2,
                "--unit: 'feet' is not a number"},
        AppCase{"cli_scans_reversed",
                {{"in.xyz", box_xyz()}},
                kIn + ".xyz --scans 5-2" + kOut,
                2,
                "--scans: expected A-B with 0 <= A <= B, got '5-2'"},
        AppCase{"cli_scanner_two_values",
                {{"in.xyz", box_xyz()}},
                kIn + ".xyz --scanner 1,2" + kOut,
                2,
                "--scanner: expected X,Y,Z, got '1,2'"},
        AppCase{"cli_up_axis_invalid",
                {{"in.xyz", box_xyz()}},
                kIn + ".xyz --up-axis x" + kOut,
                2,
                "--up-axis: x not in {z,y}",
                false},
        AppCase{"cli_no_input", {}, "-o {d}/out", 2, "no input given (see --help)"},
        AppCase{"cli_no_output",
                {{"in.xyz", box_xyz()}},
                kIn + ".xyz",
                2,
                "no output directory given: use -o DIR"},
        AppCase{"output_dir_is_a_file",
                {{"in.xyz", box_xyz()}, {"out", "keep"}},
                kIn + ".xyz" + kOut,
                1,
                "cannot write '{d}/out': exists and is not a directory"}),
    [](const auto& info) { return info.param.name; });

// ------------------------------------------------------------------------------ loaders

// Found writing the PLY fuzz target (fuzz_ply times out on it): an element without properties and a
// huge count before the vertices looped count times (a hang, 2^64 iterations).
TEST(LoaderRefuses, PlyEmptyElementWithHugeCountIsSkippedNotLooped) {
  const auto dir = test::scratch_dir();
  test::write_text(dir / "e.ply", "ply\nformat ascii 1.0\nelement pad 18446744073709551615\n" +
                                      ply("ascii", 1).substr(21) + "1 2 3\n");
  const auto r = cloud_io::load_cloud((dir / "e.ply").string());
  ASSERT_EQ(r.cloud.points.size(), 1u);
}

// ------------------------------------------------------------------------------ plan-route,
// map-eval Rows found writing the plain_map, plan_config and layout_pgm fuzz targets: each app run
// on the bad file exits 2 with `<app>: <file>[:line]: problem` and leaves {d}/out empty.

struct OtherAppCase {
  std::string name;
  std::string app;
  /// Files to create (path relative to the scratch dir; a path ending in '/' is a directory).
  std::vector<std::pair<std::string, std::string>> files;
  std::string args;    ///< {d} is the scratch dir; outputs go to {d}/out
  std::string expect;  ///< substring of stderr after "<app>: " ({d} replaced too)
};

void PrintTo(const OtherAppCase& c, std::ostream* os) {
  *os << c.name;
}

class AppRefuses : public ::testing::TestWithParam<OtherAppCase> {};

TEST_P(AppRefuses, WithMessageExitCode2AndNoOutput) {
  const auto& c = GetParam();
  const auto dir = test::scratch_dir();
  for (const auto& [name, content] : c.files) {
    if (name.ends_with('/')) {
      fs::create_directories(dir / name);
    } else {
      fs::create_directories((dir / name).parent_path());
      test::write_text(dir / name, content);
    }
  }
  const auto r = test::run_app(c.app, replace_all(c.args, "{d}", dir.string()));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.rfind(c.app + ": ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(replace_all(c.expect, "{d}", dir.string())), std::string::npos) << r.err;
  EXPECT_TRUE(!fs::exists(dir / "out") || fs::is_empty(dir / "out")) << "partial output";
}

namespace {
const std::string kPlan = " --resolution 0.05 --start 0.1,0.1 --goal 0.2,0.1 -o {d}/out";
const std::string kTruth =
    R"({"format": "indoormap-ground-truth", "rooms": [], "furniture": [], "layout": )"
    R"({"image": "truth.pgm", "resolution": 0.05, "origin": [0, 0], "width": 2, "height": 2}})";
const std::string kEval = "--truth {d}/truth.json --result {d}/result -o {d}/out";
}  // namespace

INSTANTIATE_TEST_SUITE_P(
    Cases, AppRefuses,
    ::testing::Values(
        OtherAppCase{"plan_route_plain_png_dims_overflow",
                     "plan-route",
                     {{"m.png", png_header(0xffffffffu, 0xffffffffu)}},
                     "--map {d}/m.png" + kPlan,
                     "{d}/m.png: map of 4294967295 x 4294967295 cells is above the budget of "
                     "100000000 cells"},
        OtherAppCase{"plan_route_plain_map_is_a_directory",
                     "plan-route",
                     {{"m.png/", ""}},
                     "--map {d}/m.png" + kPlan,
                     "{d}/m.png: map image is not a regular file"},
        OtherAppCase{"plan_route_config_integer_nan",
                     "plan-route",
                     {{"c.yaml", "planner:\n  max_routes: .nan\n"}, {"m.pgm", kPgm}},
                     "-c {d}/c.yaml --map {d}/m.pgm" + kPlan,
                     "{d}/c.yaml:2: key 'planner.max_routes': expected an integer in range"},
        OtherAppCase{"map_eval_layout_pgm_huge_short",
                     "map-eval",
                     {{"truth.json", kTruth},
                      {"truth.pgm", kPgm},
                      {"result/layout.pgm", "P5\n100000 4000\n255\n" + std::string(2, '\0')}},
                     kEval,
                     "{d}/result/layout.pgm: PGM data truncated: 100000 x 4000 pixels need "
                     "400000000 bytes, the file holds 2"},
        OtherAppCase{"map_eval_layout_pgm_is_a_directory",
                     "map-eval",
                     {{"truth.json", kTruth}, {"truth.pgm", kPgm}, {"result/layout.pgm/", ""}},
                     kEval,
                     "{d}/result/layout.pgm: is a directory, expected a PGM file"}),
    [](const auto& info) { return info.param.name; });
