// Output sets through the apps (app::OutputSet): a failure part-way (a full disk, injected with
// INDOORMAP_TEST_FAIL_WRITE; a directory where summary.json goes; `objects` a plain file) leaves
// the output directory byte for byte as it was; files of the app's earlier run that this run does
// not write are removed, files the manifest does not list are kept. Rows of docs/robustness.md
// ("Reliability, round 2").
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "reliability_fixtures.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using namespace indoormap::reliability;

namespace {

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
  EXPECT_NE(manifest.find("plan-route report.html\n"), std::string::npos) << manifest;
  EXPECT_EQ(manifest.find("extra.png"), std::string::npos) << manifest;
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
