// laser-to-map end to end: a small generated CARMEN log (a simulated room) to every output, the
// options and config, bad logs (exit 2, the file and line named, no output at all), a log
// without scans (exit 3), and the three shared CARMEN logs when ../shared/data is present.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using indoormap::test::run_app;
using nlohmann::json;
constexpr double kPi = std::numbers::pi;

bool empty_or_missing(const fs::path& dir) {
  return !fs::exists(dir) || fs::is_empty(dir);
}

/// Range from (x, y) along angle a to the walls of the box [0, 8] x [0, 6] (inside it).
double box_range(double x, double y, double a) {
  const double dx = std::cos(a), dy = std::sin(a);
  double t = 1e9;
  if (dx > 1e-12) t = std::min(t, (8.0 - x) / dx);
  if (dx < -1e-12) t = std::min(t, -x / dx);
  if (dy > 1e-12) t = std::min(t, (6.0 - y) / dy);
  if (dy < -1e-12) t = std::min(t, -y / dy);
  return t;
}

/// A FLASER line of n beams over 180 degrees (the reader's convention) measured from pose
/// (x, y, th), reporting that pose moved by (ex, ey, eth) (a pose error).
std::string flaser_in_box(int n, double x, double y, double th, double ex = 0, double ey = 0,
                          double eth = 0) {
  std::string s = "FLASER ";
  s += std::to_string(n);
  const double step = n % 2 == 1 ? kPi / (n - 1) : kPi / n;
  char buf[64];
  for (int i = 0; i < n; ++i) {
    std::snprintf(buf, sizeof buf, " %.3f", box_range(x, y, th - kPi / 2 + i * step));
    s += buf;
  }
  std::snprintf(buf, sizeof buf, " %.4f %.4f %.5f", x + ex, y + ey, th + eth);
  s += buf;
  s += buf;
  return s + " 1.0 host 1.0\n";
}

/// A robot driving a loop in the box, 40 scans of 181 beams.
std::string room_log() {
  std::string s = "# generated\nPARAM robot_front_laser_max 50 1 h 1\n";
  for (int k = 0; k < 40; ++k) {
    const double a = 2 * kPi * k / 40;
    s += flaser_in_box(181, 4.0 + 2.0 * std::cos(a), 3.0 + 1.5 * std::sin(a), a + kPi / 2);
    s += "ODOM 1 2 3 0 0 0 1.0 host 1.0\n";
  }
  return s;
}

/// room_log with a pose error on every third scan (up to 0.08 m and 1.2 degrees).
std::string room_log_with_pose_error() {
  std::string s = "# generated\nPARAM robot_front_laser_max 50 1 h 1\n";
  for (int k = 0; k < 40; ++k) {
    const double a = 2 * kPi * k / 40, e = k % 3 == 0 ? 1.0 : 0.0;
    s += flaser_in_box(181, 4.0 + 2.0 * std::cos(a), 3.0 + 1.5 * std::sin(a), a + kPi / 2,
                       0.08 * e * std::cos(3 * a), 0.08 * e * std::sin(3 * a), 0.02 * e);
  }
  return s;
}

fs::path write_log(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path p = dir / name;
  indoormap::test::write_text(p, text);
  return p;
}

json read_json(const fs::path& p) {
  return json::parse(indoormap::test::read_text(p));
}

TEST(LaserToMap, WritesEveryOutputOfAGeneratedRoom) {
  const auto dir = indoormap::test::scratch_dir();
  const auto log = write_log(dir, "room.log", room_log());
  const auto out = dir / "out";
  for (const std::string method : {"himm", "logodds"}) {
    auto r = run_app("laser-to-map", log.string() + " --method " + method + " -o " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("consistency"), std::string::npos) << r.err;
    for (const char* f :
         {"map.pgm", "map.yaml", "map.png", "laser_map.json", "summary.json", "report.html"})
      EXPECT_TRUE(fs::exists(out / f)) << f;
    const json lm = read_json(out / "laser_map.json");
    EXPECT_EQ(lm["method"], method);
    EXPECT_EQ(lm["scans_read"], 40);
    EXPECT_EQ(lm["scans_mapped"], 40);
    EXPECT_EQ(lm["scans_skipped"], 0);
    EXPECT_EQ(lm["consistency"]["beams_checked"], 40 * 181);
    EXPECT_GE(lm["consistency"]["within_share"].get<double>(), 0.97) << method;
    EXPECT_LE(lm["consistency"]["median_abs_error_m"].get<double>(), 0.05) << method;
    EXPECT_GT(lm["grid"]["cells"]["occupied"].get<int>(), 2 * (160 + 120) / 2) << method;
    const json sm = read_json(out / "summary.json");
    EXPECT_EQ(sm["program"], "laser-to-map");
    EXPECT_EQ(sm["parameters"]["mapping"]["method"], method);
    EXPECT_EQ(sm["outputs"].size(), 6u);  // the five above and report.html
    const std::string yaml = indoormap::test::read_text(out / "map.yaml");
    EXPECT_NE(yaml.find("image: map.pgm"), std::string::npos) << yaml;
    EXPECT_NE(yaml.find("resolution: 0.05"), std::string::npos) << yaml;
  }
}

TEST(LaserToMap, OptionsConfigAndHelp) {
  const auto dir = indoormap::test::scratch_dir();
  auto r = run_app("laser-to-map", "--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("Examples"), std::string::npos) << r.out;
  r = run_app("laser-to-map", "--print-config --cell-m 0.1 --method himm");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("cell_m: 0.1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("method: himm"), std::string::npos) << r.out;
  // What --print-config prints reads back, and the documented defaults are the built-in ones.
  const auto cfg = write_log(dir, "printed.yaml", r.out);
  auto again = run_app("laser-to-map", "-c " + cfg.string() + " --print-config");
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.out, r.out);
  auto shipped = run_app("laser-to-map", "-c " + std::string(INDOORMAP_SOURCE_DIR) +
                                             "/config/laser-to-map.yaml --print-config");
  auto builtin = run_app("laser-to-map", "--print-config");
  EXPECT_EQ(shipped.exit_code, 0) << shipped.err;
  EXPECT_EQ(shipped.out, builtin.out);
  // -q: nothing on stderr; a coarser grid is used.
  const auto log = write_log(dir, "room.log", room_log());
  r = run_app("laser-to-map", "-q --cell-m 0.1 " + log.string() + " -o " + (dir / "q").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_DOUBLE_EQ(read_json(dir / "q" / "laser_map.json")["cell_m"].get<double>(), 0.1);
}

TEST(LaserToMap, BadUsageIsExitTwoWithoutOutput) {
  const auto dir = indoormap::test::scratch_dir();
  const auto log = write_log(dir, "room.log", room_log());
  const auto out = dir / "o";
  const auto bad_cfg = write_log(dir, "bad.yaml", "mapping:\n  cel_m: 0.1\n");
  const auto bad_val = write_log(dir, "val.yaml", "himm:\n  max_value: 20\n");
  const std::pair<std::string, std::string> cases[] = {
      {log.string() + " --method magic -o " + out.string(), "--method"},
      {log.string() + " --cell-m -1 -o " + out.string(), "cell_m"},
      {log.string(), "-o DIR"},
      {"-o " + out.string(), "no log"},
      {(dir / "nothere.log").string() + " -o " + out.string(), "nothere.log: no such file"},
      {"-c " + bad_cfg.string() + " " + log.string() + " -o " + out.string(), "cel_m"},
      {"-c " + bad_val.string() + " " + log.string() + " -o " + out.string(), "max_value"},
  };
  for (const auto& [args, expect] : cases) {
    const auto r = run_app("laser-to-map", args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(expect), std::string::npos) << args << "\n" << r.err;
    EXPECT_TRUE(empty_or_missing(out)) << args;
  }
}

struct BadLog {
  std::string name;     ///< file name (the message must name it)
  std::string content;  ///< "<gzip-cut>": a gzip of a good log cut short
  std::string expect;   ///< substring of the message, with the line
};

void PrintTo(const BadLog& b, std::ostream* os) {
  *os << b.name;
}

std::string good_lines() {
  std::string s;
  for (int k = 0; k < 3; ++k) s += flaser_in_box(181, 4.0, 3.0, 0.3 * k);
  return s;
}

class LaserToMapBadLog : public ::testing::TestWithParam<BadLog> {};

TEST_P(LaserToMapBadLog, ClearMessageExitTwoNoOutput) {
  const BadLog& b = GetParam();
  const auto dir = indoormap::test::scratch_dir();
  fs::path log;
  if (b.content == "<gzip-cut>") {
    std::string big;
    for (int k = 0; k < 300; ++k) big += flaser_in_box(181, 4.0, 3.0, 0.01 * k);
    const auto plain = write_log(dir, "whole.log", big);
    log = dir / b.name;
    ASSERT_EQ(std::system(("gzip -n -c " + plain.string() + " > " + log.string()).c_str()), 0);
    std::string bytes = indoormap::test::read_text(log);
    bytes.resize(bytes.size() - 40);
    indoormap::test::write_text(log, bytes);
  } else {
    log = write_log(dir, b.name, b.content);
  }
  const auto out = dir / "out";
  const auto r = run_app("laser-to-map", log.string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(b.name), std::string::npos) << "must name the file: " << r.err;
  EXPECT_NE(r.err.find(b.expect), std::string::npos) << r.err;
  EXPECT_TRUE(empty_or_missing(out)) << "partial output left in " << out;
}

std::string cut(std::string line, std::size_t n) {
  line.resize(line.size() - n);
  return line + "\n";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, LaserToMapBadLog,
    ::testing::Values(
        BadLog{"truncated.log", good_lines() + cut(flaser_in_box(181, 4, 3, 0), 20),
               "truncated.log:4: FLASER declares 181 beams"},
        BadLog{"count.log",
               good_lines() + indoormap::test::replace_all(flaser_in_box(181, 4, 3, 0),
                                                           "FLASER 181", "FLASER 180"),
               "count.log:4: FLASER declares 180 beams"},
        BadLog{"word.log",
               good_lines() + "ODOM 1\n" +
                   indoormap::test::replace_all(flaser_in_box(3, 4, 3, 0), "FLASER 3 ",
                                                "FLASER 3 1.0 abc "),
               "word.log:5: FLASER"},
        BadLog{"late.log", good_lines() + good_lines() + "FLASER 2 1.0\n", "late.log:7:"},
        BadLog{"cut.log.gz", "<gzip-cut>", "the gzip stream ends early"}),
    [](const ::testing::TestParamInfo<BadLog>& info) {
      std::string n = info.param.name;
      return n.substr(0, n.find('.'));
    });

TEST(LaserToMap, ALogWithoutScansIsExitThreeWithoutOutput) {
  const auto dir = indoormap::test::scratch_dir();
  const auto log =
      write_log(dir, "empty.log", "# nothing\nPARAM robot_frontlaser_offset 0 1 h 1\n");
  const auto r = run_app("laser-to-map", log.string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("no usable FLASER scan"), std::string::npos) << r.err;
  EXPECT_TRUE(empty_or_missing(dir / "out"));
}

// The pose refinement (pose_refine.*, default two passes) aligns the scans whose pose is off, and
// the map agrees with its scans again; without it (passes: 0) those scans disagree.
TEST(LaserToMap, PoseRefinementRepairsPoseErrors) {
  const auto dir = indoormap::test::scratch_dir();
  const auto log = write_log(dir, "room.log", room_log_with_pose_error());
  const auto cfg = write_log(dir, "off.yaml", "pose_refine:\n  passes: 0\n");
  const auto off = dir / "off", on = dir / "on";
  ASSERT_EQ(
      run_app("laser-to-map", "-q " + log.string() + " -c " + cfg.string() + " -o " + off.string())
          .exit_code,
      0);
  ASSERT_EQ(run_app("laser-to-map", "-q " + log.string() + " -o " + on.string()).exit_code, 0);
  const json a = read_json(off / "laser_map.json"), b = read_json(on / "laser_map.json");
  const double share_off = a["consistency"]["within_share"],
               share_on = b["consistency"]["within_share"];
  std::printf("[ figures  ] within 2 cells: log's poses %.3f, refined %.3f\n", share_off, share_on);
  EXPECT_TRUE(a["pose_refine"].empty());
  ASSERT_EQ(b["pose_refine"].size(), 2u);
  EXPECT_GE(b["pose_refine"][0]["scans_moved"].get<int>(), 14);  // the 14 scans with an error
  EXPECT_LE(b["pose_refine"][0]["max_shift_m"].get<double>(), 0.12);
  EXPECT_LT(share_off, 0.96);  // measured 0.944
  EXPECT_GE(share_on, 0.99);   // measured 0.998
}

// The shared logs with the app's defaults (pose refinement on), log-odds (the default method) and
// HIMM (--method himm). The issue asks for >= 80 % of beams within 2 cells; log-odds reaches it on
// all three since the whole-log map is unclamped (log_odds.clamp: false; measured intel 0.910,
// csail 0.840, freiburg-079 0.864; clamped 0.904 / 0.832 / 0.783, docs/laser-to-map.md, "Why
// freiburg-079's beams disagreed"). HIMM keeps the paper's rules (bounded counter, freeze at 15):
// measured 0.878 / 0.821 / 0.600, below 80 % on freiburg-079, so its floors guard the figures.
struct RealLog {
  const char* file;
  double min_himm, min_log_odds;
};

void PrintTo(const RealLog& l, std::ostream* os) {
  *os << l.file;
}

class LaserToMapRealLogs : public ::testing::TestWithParam<RealLog> {};

TEST_P(LaserToMapRealLogs, MapsTheLogAndReportsItsConsistency) {
  INDOORMAP_REQUIRE_DATA(logs, "carmen-logs");
  const RealLog& l = GetParam();
  const auto dir = indoormap::test::scratch_dir();
  for (const auto& [method, floor] : {std::pair{"logodds", l.min_log_odds}, {"himm", l.min_himm}}) {
    const auto out = dir / method;
    const auto r = run_app("laser-to-map", "-q " + (logs / l.file).string() + " --method " +
                                               method + " -o " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json lm = read_json(out / "laser_map.json");
    std::printf("[ figures  ] %s %s: %s\n", l.file, method, lm["consistency"].dump().c_str());
    EXPECT_GT(lm["scans_mapped"].get<int>(), 400);
    EXPECT_EQ(lm["scans_skipped"], 0);
    EXPECT_GE(lm["consistency"]["within_share"].get<double>(), floor) << l.file << " " << method;
    EXPECT_EQ(lm["pose_refine"].size(), 2u);  // the default
    EXPECT_TRUE(fs::exists(out / "map.png"));
  }
}

INSTANTIATE_TEST_SUITE_P(Shared, LaserToMapRealLogs,
                         ::testing::Values(RealLog{"intel-corrected.log.gz", 0.87, 0.90},
                                           RealLog{"csail-corrected.log.gz", 0.81, 0.83},
                                           RealLog{"freiburg-079-corrected.log.gz", 0.59, 0.86}),
                         [](const ::testing::TestParamInfo<RealLog>& info) {
                           std::string n = info.param.file;
                           n = n.substr(0, n.find('-'));
                           return n == "freiburg" ? std::string("freiburg079") : n;
                         });

}  // namespace
