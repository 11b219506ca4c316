// Progress on stderr (apps/common/progress.hpp): a bar under a terminal, periodic lines through
// a pipe, nothing with -q. INDOORMAP_PROGRESS_S=0 makes every report of a short step visible
// (docs/progress.md), so the steps stay small.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "test_support.hpp"

namespace fs = std::filesystem;
using indoormap::test::read_text;
using indoormap::test::run_app;
using indoormap::test::scratch_dir;

namespace {

const std::string kScene = std::string(INDOORMAP_SOURCE_DIR) + "/scenes/office.yaml";

/// Runs `cmd` under a pseudo-terminal (util-linux script); returns what the terminal showed.
std::string run_in_pty(const std::string& cmd, const fs::path& dir) {
  const fs::path log = dir / "pty.txt";
  const std::string full = "script -qfec \"" + cmd + "\" /dev/null > " + log.string() + " 2>&1";
  EXPECT_EQ(std::system(full.c_str()), 0) << full;
  return read_text(log);
}

int count(const std::string& s, const std::string& what) {
  int n = 0;
  for (std::size_t at = 0; (at = s.find(what, at)) != std::string::npos; at += what.size()) ++n;
  return n;
}

}  // namespace

TEST(ProgressSlow, SceneSimDrawsABarOnATerminal) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1)";
  const fs::path dir = scratch_dir();
  const std::string shown =
      run_in_pty("env INDOORMAP_PROGRESS_S=0 " + std::string(INDOORMAP_BIN_DIR) + "/scene-sim " +
                     kScene + " -o " + (dir / "out").string(),
                 dir);
  // The bar is redrawn in place: several carriage returns each followed by the bar's text.
  EXPECT_GE(count(shown, "\rscene-sim: casting rays ["), 3) << shown;
  EXPECT_NE(shown.find("100%"), std::string::npos) << shown;
  EXPECT_NE(shown.find("rays/s"), std::string::npos) << shown;
  EXPECT_NE(shown.find(" left"), std::string::npos) << shown;
}

TEST(ProgressSlow, SceneSimPrintsLinesThroughAPipe) {
  const fs::path dir = scratch_dir();
  const auto r =
      run_app("scene-sim", kScene + " -o " + (dir / "out").string(), "INDOORMAP_PROGRESS_S=0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;  // no bar in a file
  EXPECT_GE(count(r.err, "scene-sim: casting rays: "), 3) << r.err;
  EXPECT_NE(r.err.find("scene-sim: casting rays: 100% (577.4 k of 577.4 k rays"), std::string::npos)
      << r.err;
  // With the default interval (5 s) this short step prints no progress line at all.
  const auto quiet_default = run_app("scene-sim", kScene + " -o " + (dir / "out2").string());
  ASSERT_EQ(quiet_default.exit_code, 0) << quiet_default.err;
  EXPECT_EQ(quiet_default.err.find("casting rays"), std::string::npos) << quiet_default.err;
}

TEST(ProgressSlow, QuietSilencesProgressEvenOnATerminal) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1)";
  const fs::path dir = scratch_dir();
  const std::string bin = INDOORMAP_BIN_DIR;
  // stdout to a file, so the terminal shows stderr only.
  const std::string shown =
      run_in_pty("env INDOORMAP_PROGRESS_S=0 " + bin + "/scene-sim " + kScene + " -q -o " +
                     (dir / "out").string() + " > " + (dir / "stdout.txt").string(),
                 dir);
  EXPECT_EQ(shown, "") << shown;
  const auto r = run_app("pcd-to-map",
                         std::string(INDOORMAP_SOURCE_DIR) + "/clouds/office/cloud.pcd -q -o " +
                             (dir / "map").string(),
                         "INDOORMAP_PROGRESS_S=0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

TEST(ProgressSlow, PcdToMapReportsTheGhostFilter) {
  const fs::path dir = scratch_dir();
  const auto r = run_app(
      "pcd-to-map",
      std::string(INDOORMAP_SOURCE_DIR) + "/clouds/office/cloud.pcd -o " + (dir / "map").string(),
      "INDOORMAP_PROGRESS_S=0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GE(count(r.err, "ghost filter: "), 3) << r.err;
  EXPECT_NE(r.err.find("ghost filter: 100%"), std::string::npos) << r.err;
}
