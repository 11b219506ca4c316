// pcd-to-map as a user runs it: outputs and their formats, config handling, and every kind of bad
// input with its message, exit code and the promise of no partial output.
#include <gtest/gtest.h>

#include <random>

#include "config.hpp"
#include "indoormap/core/errors.hpp"
#include "map_yaml.hpp"
#include "test_support.hpp"

using namespace indoormap;
namespace fs = std::filesystem;
using test::run_app;

namespace {

// A furnished box room (6 x 5 x 2.7 m) sampled every 3 cm, as XYZ text, with a desk and a cabinet.
std::string room_xyz() {
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 0.003);
  std::ostringstream s;
  s.precision(4);
  s << std::fixed << "# synthetic test room\n";
  auto put = [&](double x, double y, double z) {
    s << x + n(rng) << " " << y + n(rng) << " " << z + n(rng) << "\n";
  };
  const double w = 6, d = 5, h = 2.7, st = 0.03;
  for (double x = 0; x <= w; x += st)
    for (double y = 0; y <= d; y += st) {
      put(x, y, 0);
      put(x, y, h);
    }
  for (double z = 0; z <= h; z += st) {
    for (double x = 0; x <= w; x += st) {
      put(x, 0, z);
      put(x, d, z);
    }
    for (double y = 0; y <= d; y += st) {
      put(0, y, z);
      put(w, y, z);
    }
  }
  for (double x = 0.2; x <= 1.8; x += st)  // desk top against the south wall
    for (double y = 0.1; y <= 0.9; y += st) put(x, y, 0.75);
  for (double y = 2.0; y <= 3.5; y += st)  // cabinet front against the east wall
    for (double z = 0; z <= 1.9; z += st) put(5.5, y, z);
  return s.str();
}

fs::path room_file() {
  static const fs::path p = [] {
    // One file per process: ctest runs each test in its own process, in parallel, and a file
    // shared between them would be read while another process rewrites it.
    auto dir = fs::temp_directory_path() / "indoormap-tests" / "shared";
    fs::create_directories(dir);
    auto f = dir / ("room_" + std::to_string(::getpid()) + ".xyz");
    test::write_text(f, room_xyz());
    return f;
  }();
  return p;
}

bool empty_or_missing(const fs::path& dir) {
  return !fs::exists(dir) || fs::is_empty(dir);
}

}  // namespace

// -q: nothing on stderr for a clean run (no progress, no run report), the same outputs; without
// it the run report is there.
TEST(PcdToMap, QuietPrintsNothingOnStderr) {
  const fs::path dir = test::scratch_dir();
  const std::string args = room_file().string() + " --scanner 3,2.5,1.2 -o ";
  const auto loud = run_app("pcd-to-map", args + (dir / "a").string());
  ASSERT_EQ(loud.exit_code, 0) << loud.err;
  EXPECT_NE(loud.err.find("points ("), std::string::npos) << loud.err;
  const auto quiet = run_app("pcd-to-map", args + (dir / "b").string() + " -q");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  EXPECT_EQ(test::read_text(dir / "a" / "map.pgm"), test::read_text(dir / "b" / "map.pgm"));
  const auto fe = run_app("furniture-extract", args + (dir / "c").string() + " --quiet");
  ASSERT_EQ(fe.exit_code, 0) << fe.err;
  EXPECT_EQ(fe.err, "");
}

TEST(PcdToMap, WritesEveryOutputInItsFormat) {
  const auto out = test::scratch_dir() / "out";
  auto r = run_app("pcd-to-map", room_file().string() + " --scanner 3,2.5,1.2 -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"map.pgm", "map.yaml", "layout.pgm", "layout.png", "summary.json"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  // No temporary files are left behind; the one hidden file is the output-set manifest.
  for (const auto& e : fs::directory_iterator(out))
    if (e.path().filename() != ".indoormap-outputs") {
      EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
    }

  // The ROS map loads the way map_server reads it; it is the navigation map (summary.json
  // nav_map), not M_r: a free cell there is never a wall or furniture cell of M_r's interior.
  formats::RosMap ros = app::read_ros_map(out / "map.yaml");
  const std::string pgm = test::read_text(out / "layout.pgm");
  ASSERT_EQ(pgm.substr(0, 3), "P5\n");
  const int w = ros.geometry.width(), h = ros.geometry.height();
  const std::string header = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
  ASSERT_EQ(pgm.substr(0, header.size()), header);
  ASSERT_EQ(pgm.size(), header.size() + static_cast<std::size_t>(w) * h);
  int free_cells = 0, ros_free = 0, ros_occupied = 0;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const auto raw =
          static_cast<Cell>(pgm[header.size() + static_cast<std::size_t>(h - 1 - r) * w + c]);
      const Cell ros_cell = ros.cells.at(c, r);
      free_cells += raw == Cell::kFree;
      ros_free += ros_cell == Cell::kFree;
      ros_occupied += ros_cell == Cell::kWall;
    }
  const auto nav = nlohmann::json::parse(test::read_text(out / "summary.json"))["nav_map"];
  EXPECT_EQ(ros_free, nav["cells"]["free"].get<int>());
  EXPECT_EQ(ros_occupied, nav["cells"]["occupied"].get<int>());
  EXPECT_NEAR(ros.meta.resolution_m, 0.05, 1e-12);
  // The scanner cell (3, 2.5) is free, in map metres through the YAML origin.
  EXPECT_EQ(ros.cells.at(ros.geometry.cell_of({3.0, 2.5})), Cell::kFree);
  EXPECT_GT(free_cells * 0.0025, 15.0);

  auto s = nlohmann::json::parse(test::read_text(out / "summary.json"));
  EXPECT_EQ(s["program"], "pcd-to-map");
  EXPECT_EQ(s["points"]["dropped_nonfinite"], 0);
  EXPECT_NEAR(s["floor_z_m"].get<double>(), 0.0, 0.05);
  EXPECT_NEAR(s["ceiling_z_m"].get<double>(), 2.7, 0.05);
  EXPECT_TRUE(s["ceiling_found"].get<bool>());
  for (const char* k : {"inputs", "levelling", "grid", "wall_band", "furniture_band", "layers",
                        "scanners_map_m", "timings_ms", "parameters", "version"})
    EXPECT_TRUE(s.contains(k)) << k;
  EXPECT_EQ(s["scanner_source"], "config");
  EXPECT_GT(s["layout_cells"]["furniture"].get<int>(), 0);
}

TEST(PcdToMap, HelpAndPrintConfig) {
  auto r = run_app("pcd-to-map", "--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("Examples"), std::string::npos);
  r = run_app("pcd-to-map", "--print-config --cell-m 0.1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("cell_m: 0.1"), std::string::npos);
  // The printed config reads back to the same parameters.
  const auto dir = test::scratch_dir();
  test::write_text(dir / "printed.yaml", r.out);
  app::PipelineConfig c;
  app::merge_config_file(c, (dir / "printed.yaml").string());
  EXPECT_DOUBLE_EQ(c.map.voxel.cell_m, 0.1);
}

// The help names every input kind the loader reads and every file a run writes (issue 19).
TEST(PcdToMap, HelpListsEveryInputKindAndEveryOutput) {
  const auto help = run_app("pcd-to-map", "--help");
  ASSERT_EQ(help.exit_code, 0);
  for (const char* kind : {".pcd", ".ply", ".xyz", ".txt", ".csv", ".las", "3DTK", "storey_<k>/"})
    EXPECT_NE(help.out.find(kind), std::string::npos) << kind;
  const fs::path dir = test::scratch_dir();
  const auto r = run_app(
      "pcd-to-map", room_file().string() + " --scanner 3,2.5,1.2 -q -o " + (dir / "o").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto summary = nlohmann::json::parse(test::read_text(dir / "o" / "summary.json"));
  ASSERT_GE(summary["outputs"].size(), 10u);
  for (const auto& f : summary["outputs"]) {
    EXPECT_NE(help.out.find(f.get<std::string>()), std::string::npos) << f;
    EXPECT_TRUE(fs::exists(dir / "o" / f.get<std::string>())) << f;
  }
  for (const char* f : {"route.json", "route.png", "safe.pgm", "safe.yaml"})
    EXPECT_NE(help.out.find(f), std::string::npos) << f;
}

// furniture-extract plans no route: --start / --goal are refused naming the apps that plan,
// exit 2, nothing written (they were accepted and ignored).
TEST(FurnitureExtract, RefusesStartAndGoal) {
  const fs::path dir = test::scratch_dir();
  for (const std::string opt : {"--start 1,1 --goal 2,2", "--goal 2,2"}) {
    const auto r = run_app("furniture-extract",
                           room_file().string() + " " + opt + " -o " + (dir / "o").string());
    EXPECT_EQ(r.exit_code, 2) << opt;
    EXPECT_NE(r.err.find("furniture-extract plans no route"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("plan-route --map"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("pcd-to-map CLOUD --start"), std::string::npos) << r.err;
    EXPECT_TRUE(empty_or_missing(dir / "o"));
  }
}

// Options that cannot act on the inputs are refused (exit 2, nothing written): --scans without a
// 3DTK input; --unit / --up-axis when every input is 3DTK (converted by its own convention).
TEST(PcdToMap, RefusesOptionsThatCannotActOnTheInputs) {
  const fs::path dir = test::scratch_dir();
  auto r = run_app("pcd-to-map", room_file().string() + " --scans 0-2 -o " + (dir / "a").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--scans 0-2: selects scans of a 3DTK scan directory"), std::string::npos)
      << r.err;
  EXPECT_TRUE(empty_or_missing(dir / "a"));
  fs::create_directories(dir / "scans");
  test::write_text(dir / "scans" / "scan000.3d", "0 0 0\n");
  for (const std::string opt : {"--unit mm", "--up-axis y"}) {
    r = run_app("pcd-to-map", (dir / "scans").string() + " " + opt + " -o " + (dir / "b").string());
    EXPECT_EQ(r.exit_code, 2) << opt;
    EXPECT_NE(r.err.find(opt.substr(0, opt.find(' ')) + ": 3DTK scans are converted"),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(empty_or_missing(dir / "b"));
  }
  // --print-config alone is not refused.
  EXPECT_EQ(run_app("pcd-to-map", "--scans 0-2 --print-config").exit_code, 0);
}

TEST(PcdToMap, DocumentedDefaultsAreTheCodeDefaults) {
  app::PipelineConfig from_file;
  app::merge_config_file(from_file, std::string(INDOORMAP_SOURCE_DIR) + "/config/default.yaml");
  EXPECT_EQ(app::to_yaml(from_file), app::to_yaml(app::PipelineConfig{}));
}

TEST(PcdToMap, ConfigErrorsNameFileKeyAndLine) {
  const auto dir = test::scratch_dir();
  test::write_text(dir / "typo.yaml", "voxel:\n  cel_m: 0.1\n");
  auto r = run_app("pcd-to-map", room_file().string() + " -c " + (dir / "typo.yaml").string() +
                                     " -o " + (dir / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("typo.yaml:2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("voxel.cel_m"), std::string::npos) << r.err;
  test::write_text(dir / "type.yaml", "level:\n  max_tilt_deg: steep\n");
  r = run_app("pcd-to-map", room_file().string() + " -c " + (dir / "type.yaml").string() + " -o " +
                                (dir / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("level.max_tilt_deg"), std::string::npos) << r.err;
  r = run_app("pcd-to-map", room_file().string() + " --cell-m -1 -o " + (dir / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("voxel.cell_m"), std::string::npos) << r.err;
  r = run_app("pcd-to-map", room_file().string() + " --bogus -o " + (dir / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(empty_or_missing(dir / "o"));
}

struct BadInput {
  std::string name;
  std::string file_name;
  std::string content;
  std::string expect;  ///< substring of the message
  std::string extra_args;
};

void PrintTo(const BadInput& b, std::ostream* os) {
  *os << b.name;
}

class PcdToMapBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(PcdToMapBadInput, ClearMessageExitTwoNoOutput) {
  const auto& p = GetParam();
  const auto dir = test::scratch_dir();
  const auto in = dir / p.file_name;
  if (p.content != "<missing>") test::write_text(in, p.content);
  const auto out = dir / "out";
  auto r = run_app("pcd-to-map", in.string() + " -o " + out.string() + " " + p.extra_args);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(p.expect), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(p.file_name), std::string::npos) << "message must name the file: " << r.err;
  EXPECT_TRUE(empty_or_missing(out)) << "partial output left in " << out;
}

namespace {
std::string flat_cloud() {
  std::string s;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 50; ++j)
      s += std::to_string(i * 0.05) + " " + std::to_string(j * 0.05) + " 1.0\n";
  return s;
}
}  // namespace

INSTANTIATE_TEST_SUITE_P(
    Cases, PcdToMapBadInput,
    ::testing::Values(
        BadInput{"missing", "nothere.pcd", "<missing>", "nothere.pcd: no such file", ""},
        BadInput{"empty_xyz", "empty.xyz", "", "empty.xyz: empty cloud: no points", ""},
        BadInput{"malformed_line", "bad.xyz", "1 2 3\n4 5 6\n7 eight 9\n",
                 "bad.xyz:3: malformed line, expected 'x y z ...'", ""},
        BadInput{"empty_pcd", "empty.pcd", "", "empty.pcd: empty file (no PCD header)", ""},
        BadInput{"pcd_without_fields", "nofields.pcd",
                 "VERSION 0.7\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\nPOINTS "
                 "1\nDATA ascii\n1 2 3\n",
                 "nofields.pcd:8: PCD header: no FIELDS line before DATA", ""},
        BadInput{"pcd_huge_dims", "huge.pcd",
                 "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH "
                 "65536\nHEIGHT 65536\n"
                 "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 0\nDATA binary\n",
                 "huge.pcd:9: PCD header: WIDTH 65536 x HEIGHT 65536 does not equal POINTS 0", ""},
        BadInput{"pcd_huge_points", "short.pcd",
                 "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH "
                 "4000000000\nHEIGHT 1\n"
                 "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4000000000\nDATA binary\nabc",
                 "short.pcd:10: PCD data section too short for POINTS 4000000000 (truncated file?)",
                 ""},
        BadInput{"all_nan", "nan.xyz", "nan nan nan\nnan 1 2\ninf 0 0\n",
                 "nan.xyz: empty cloud: all 3 points are non-finite (NaN / Inf)", ""},
        BadInput{"one_height", "flat.xyz", flat_cloud(), "one height", ""},
        BadInput{"unknown_extension", "cloud.las2", "1 2 3\n",
                 "cloud.las2: unknown file type '.las2' (supported:", ""},
        BadInput{"las_not_lasf", "cloud.las", "1 2 3\n",
                 "cloud.las: LAS: not a LAS file (no 'LASF' signature)", ""},
        BadInput{"laz", "cloud.LAZ", "LASF", "cloud.LAZ: compressed LAS (LAZ) is not read", ""},
        BadInput{"e57", "cloud.e57", "ASTM-E57", "cloud.e57: E57 is not read: convert it", ""}),
    [](const auto& info) { return info.param.name; });

TEST(PcdToMap, GridAboveBudgetIsRefusedBeforeAllocating) {
  const auto dir = test::scratch_dir();
  test::write_text(dir / "small.yaml", "voxel:\n  max_cells: 1000\n");
  auto r = run_app("pcd-to-map", room_file().string() + " -c " + (dir / "small.yaml").string() +
                                     " -o " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("max_cells"), std::string::npos) << r.err;
  EXPECT_TRUE(empty_or_missing(dir / "out"));
}

TEST(PcdToMap, UnwritableOutputDirectory) {
  const auto dir = test::scratch_dir();
  test::write_text(dir / "a_file", "x");
  auto r = run_app("pcd-to-map", room_file().string() + " -o " + (dir / "a_file" / "out").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("a_file"), std::string::npos) << r.err;
  r = run_app("pcd-to-map", room_file().string() + " -o " + (dir / "a_file").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("not a directory"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_text(dir / "a_file"), "x");  // not clobbered
}

TEST(PcdToMap, NoInputOrNoOutputIsUsageError) {
  EXPECT_EQ(run_app("pcd-to-map", "-o /tmp/x").exit_code, 2);
  EXPECT_EQ(run_app("pcd-to-map", room_file().string()).exit_code, 2);
}
