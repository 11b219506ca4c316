// report.html of every app, opened in a real headless browser (Debian's chromium): the page
// loads, every picture shows (the page's own check script: complete && naturalWidth > 0, read
// back through --dump-dom), its numbers equal summary.json's, and a screenshot of pcd-to-map's
// page on the default office cloud is not blank. Skips, saying so, when chromium is absent.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "reliability_fixtures.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using nlohmann::json;
using reliability::run_limited;

namespace {

bool have_chromium() {
  return std::system("command -v chromium >/dev/null 2>&1") == 0;
}

#define REQUIRE_CHROMIUM()                                                                   \
  if (!have_chromium())                                                                      \
  GTEST_SKIP() << "chromium not found: install Debian's chromium (scripts/setup.sh) to run " \
                  "the browser test of report.html"

/// Runs headless chromium once on file://page with a fresh profile and a time limit; returns
/// the DOM after load (--dump-dom). screenshot: also writes a 1200 x 2000 PNG there.
std::string browse(const fs::path& page, const fs::path& screenshot = {}) {
  // Its own profile and DOM file per call, away from the test's scratch_dir (which
  // scratch_dir() would empty, outputs and all).
  static int calls = 0;
  const fs::path work = fs::temp_directory_path() / "indoormap-tests" /
                        ("chromium-" + std::to_string(::getpid()) + "-" + std::to_string(++calls));
  fs::remove_all(work);
  fs::create_directories(work);
  const fs::path dom = work / "dom.html";
  const std::string command =
      "timeout -k 5 40 chromium --headless --no-sandbox --disable-gpu --no-first-run "
      "--user-data-dir=" +
      (work / "profile").string() + " --window-size=1200,2000 --virtual-time-budget=5000 " +
      (screenshot.empty() ? "" : "--screenshot=" + screenshot.string() + " ") +
      "--dump-dom file://" + fs::absolute(page).string() + " >" + dom.string() + " 2>/dev/null";
  std::system(command.c_str());
  std::string text = test::read_text(dom);
  fs::remove_all(work);  // the profile is a few MB
  return text;
}

std::string unescape(std::string s) {
  for (const auto& [from, to] :
       {std::pair{"&lt;", "<"}, std::pair{"&gt;", ">"}, std::pair{"&quot;", "\""},
        std::pair{"&#39;", "'"}, std::pair{"&nbsp;", " "}, std::pair{"&amp;", "&"}})
    s = test::replace_all(s, from, to);
  return s;
}

/// The value of attribute name in the first tag starting with tag_start, or "".
std::string attribute(const std::string& dom, const std::string& tag_start,
                      const std::string& name) {
  const auto at = dom.find(tag_start);
  if (at == std::string::npos) return "";
  const auto end = dom.find('>', at);
  const std::string tag = dom.substr(at, end - at);
  const auto a = tag.find(" " + name + "=\"");
  if (a == std::string::npos) return "";
  const auto from = a + name.size() + 3;
  return tag.substr(from, tag.find('"', from) - from);
}

/// Checks every `<td class="v" data-key=K>V</td>` against summary at pointer K; returns how many.
int check_figures(const std::string& dom, const json& summary) {
  const std::string open = "<td class=\"v\" data-key=\"";
  int checked = 0;
  for (auto at = dom.find(open); at != std::string::npos; at = dom.find(open, at + 1)) {
    const auto k0 = at + open.size(), k1 = dom.find('"', k0);
    const auto v0 = dom.find('>', k1) + 1, v1 = dom.find("</td>", v0);
    const std::string key = unescape(dom.substr(k0, k1 - k0));
    const std::string text = unescape(dom.substr(v0, v1 - v0));
    const json::json_pointer ptr(key);
    if (!summary.contains(ptr)) {
      ADD_FAILURE() << key << " is not in summary.json";
      continue;
    }
    const json& v = summary.at(ptr);
    if (v.is_number_integer() || v.is_number_unsigned()) {
      EXPECT_EQ(text, v.dump()) << key;
    } else if (v.is_number()) {  // shown with 6 significant digits
      const double want = v.get<double>();
      EXPECT_NEAR(std::stod(text), want, 5e-6 * std::abs(want) + 1e-300) << key << ": " << text;
    } else if (v.is_boolean()) {
      EXPECT_EQ(text, v.get<bool>() ? "true" : "false") << key;
    } else if (v.is_string()) {
      EXPECT_EQ(text, v.get<std::string>()) << key;
    } else {
      EXPECT_TRUE(v.is_null()) << key;
      EXPECT_EQ(text, "none") << key;
    }
    ++checked;
  }
  return checked;
}

/// Opens dir/page in the browser: it loads, every picture shows, at least min_figures of its
/// numbers are checked against dir/summary_file and its inputs carry their SHA-256.
/// screenshot: also writes the browser's screenshot of the page there.
void check_report(const fs::path& dir, const std::string& summary_file = "summary.json",
                  const std::string& page = "report.html", int min_pictures = 1,
                  int min_figures = 10, const fs::path& screenshot = {}) {
  SCOPED_TRACE(dir / page);
  ASSERT_TRUE(fs::exists(dir / page));
  const std::string html = test::read_text(dir / page);
  EXPECT_EQ(html.find("http://"), std::string::npos) << "the page reaches the network";
  EXPECT_EQ(html.find("https://"), std::string::npos) << "the page reaches the network";
  const std::string dom = browse(dir / page, screenshot);
  ASSERT_EQ(attribute(dom, "<p id=\"check\"", "data-loaded"), "true")
      << "the page did not load or its script did not run:\n"
      << dom.substr(0, 2000);
  const std::string images = attribute(dom, "<p id=\"check\"", "data-images");
  std::size_t in_file = 0;
  for (auto at = html.find("<img "); at != std::string::npos; at = html.find("<img ", at + 1))
    ++in_file;
  EXPECT_EQ(images, std::to_string(in_file));
  EXPECT_GE(in_file, static_cast<std::size_t>(min_pictures));
  EXPECT_EQ(attribute(dom, "<p id=\"check\"", "data-images-shown"), images)
      << "a picture did not show";
  const json summary = json::parse(test::read_text(dir / summary_file));
  EXPECT_GE(check_figures(dom, summary), min_figures);
  for (std::size_t i = 0; i < summary["provenance"]["inputs"].size(); ++i)
    EXPECT_NE(dom.find("data-key=\"/provenance/inputs/" + std::to_string(i) + "/sha256\""),
              std::string::npos);
  // Every output is listed, with its line.
  for (const auto& f : summary.value("outputs", json::array()))
    EXPECT_NE(dom.find("<code>" + f.get<std::string>() + "</code>"), std::string::npos) << f;
}

/// A CARMEN log of a robot driving a loop in an 8 x 6 m box: 30 FLASER scans of 181 beams.
std::string box_log() {
  const double pi = 3.14159265358979323846;
  auto range = [](double x, double y, double a) {
    const double c = std::cos(a), s = std::sin(a);
    double t = 1e9;
    if (c > 1e-9) t = std::min(t, (8.0 - x) / c);
    if (c < -1e-9) t = std::min(t, -x / c);
    if (s > 1e-9) t = std::min(t, (6.0 - y) / s);
    if (s < -1e-9) t = std::min(t, -y / s);
    return t;
  };
  std::string log = "# generated\nPARAM robot_front_laser_max 50 1 h 1\n";
  char buf[64];
  for (int k = 0; k < 30; ++k) {
    const double a = 2 * pi * k / 30, x = 4 + 2 * std::cos(a), y = 3 + 1.5 * std::sin(a),
                 th = a + pi / 2;
    log += "FLASER 181";
    for (int i = 0; i < 181; ++i)
      std::snprintf(buf, sizeof buf, " %.3f", range(x, y, th - pi / 2 + i * pi / 180)), log += buf;
    std::snprintf(buf, sizeof buf, " %.4f %.4f %.5f", x, y, th);
    log += std::string(buf) + buf + " 1.0 host 1.0\n";
  }
  return log;
}

}  // namespace

// pcd-to-map on the default office cloud, then map-eval on its result (one test: the office run
// is the longest app run here, and ctest runs each test in a process of its own).
TEST(ReportBrowser, PcdToMapOfficeAndMapEvalReportsShowTheirPicturesAndSummaryNumbers) {
  REQUIRE_CHROMIUM();
  const fs::path dir = test::scratch_dir();  // once: every call empties it
  const fs::path res = dir / "office", eval = dir / "eval", shot = dir / "office.png";
  auto r = run_limited("pcd-to-map", std::string(INDOORMAP_SOURCE_DIR) +
                                         "/clouds/office/cloud.pcd -q -o " + res.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_report(res, "summary.json", "report.html", 4, 100, shot);
  const cv::Mat img = cv::imread(shot.string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(img.empty()) << "no screenshot";
  EXPECT_EQ(img.cols, 1200);
  EXPECT_EQ(img.rows, 2000);
  cv::Mat grey;
  cv::cvtColor(img, grey, cv::COLOR_BGR2GRAY);
  const double dark_share = cv::countNonZero(grey < 200) / static_cast<double>(grey.total());
  EXPECT_GT(dark_share, 0.01) << "the screenshot is blank";
  cv::Mat hsv;
  cv::cvtColor(img, hsv, cv::COLOR_BGR2HSV);
  std::vector<cv::Mat> ch;
  cv::split(hsv, ch);
  EXPECT_GT(cv::countNonZero(ch[1] > 80), 1000) << "no coloured picture on screen";

  // map-eval: report.html in an output directory of its own; into the result's directory it
  // writes eval.html and keeps the result's report.html.
  const std::string truth = std::string(INDOORMAP_SOURCE_DIR) + "/clouds/office/ground_truth.json";
  r = run_limited("map-eval",
                  "--truth " + truth + " --result " + res.string() + " -o " + eval.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_report(eval, "eval.json", "report.html", 0, 10);
  const std::string before = test::read_text(res / "report.html");
  r = run_limited("map-eval", "--truth " + truth + " --result " + res.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(res / "eval.html"));
  EXPECT_EQ(test::read_text(res / "report.html"), before);
}

TEST(ReportBrowser, EveryOtherAppsReportShowsItsPicturesAndSummaryNumbers) {
  REQUIRE_CHROMIUM();
  const fs::path dir = test::scratch_dir();
  test::write_text(dir / "desk.xyz", reliability::room_xyz(true));  // a 4 x 3 m room, one desk
  const std::string cloud = (dir / "desk.xyz").string() + " --scanner 1,1,1.2";
  const std::string map = reliability::small_map(dir).string();
  test::write_text(dir / "box.log", box_log());
  const std::string log = (dir / "box.log").string();
  const std::pair<std::string, std::string> runs[] = {
      {"furniture-extract", cloud + " -q"},
      {"plan-route", "--map " + map + " --start 0.5,0.5 --goal 2.5,1.5 -q"},
      {"scene-sim", "--random --seed 5 --rooms 2 --step-deg 2 -q"},
      {"grid-areas", map + " -q"},
      {"laser-to-map", log + " -q"},
      {"explore-sim", map + " --seed 3 -q"},
      {"scan-features", log + " --scan 3 -q"},
  };
  for (const auto& [app, args] : runs) {
    const fs::path out = dir / app;
    const auto r = run_limited(app, args + " -o " + out.string());
    ASSERT_EQ(r.exit_code, 0) << app << ": " << r.err;
    check_report(out, "summary.json", "report.html", app == "scene-sim" ? 0 : 1, 8);
  }
}
