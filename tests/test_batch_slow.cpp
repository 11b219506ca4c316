// Many scans at once (docs/batch.md): scripts/batch.sh runs pcd-to-map with GNU parallel on
// three small inputs, one of them a truncated PCD. Checks the outputs of the two good ones, the
// failure row of the broken one (the others still ran), and the index (CSV and JSON) against
// each run's summary.json.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A box room w x d x 2.6 m (sampled every 5 cm, XYZ text) with a low cabinet along one wall.
std::string box_room_xyz(double w, double d, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 0.003);
  std::ostringstream s;
  s.precision(4);
  s << std::fixed;
  auto put = [&](double x, double y, double z) {
    s << x + n(rng) << " " << y + n(rng) << " " << z + n(rng) << "\n";
  };
  const double h = 2.6, st = 0.05;
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
  for (double x = 0.5; x <= 1.5; x += st)  // cabinet top
    for (double y = 0.1; y <= 0.6; y += st) put(x, y, 0.9);
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// Three inputs in dir: two box rooms and a truncated PCD (input 2); returns the list file.
fs::path three_inputs(const fs::path& dir) {
  indoormap::test::write_text(dir / "small.xyz", box_room_xyz(4.0, 3.0, 1));
  indoormap::test::write_text(dir / "wide.xyz", box_room_xyz(6.0, 4.0, 2));
  // The office cloud cut in its data section: its header promises more points than it holds.
  const std::string office =
      indoormap::test::read_text(fs::path(INDOORMAP_SOURCE_DIR) / "clouds/office/cloud.pcd");
  EXPECT_GT(office.size(), 100000u);
  indoormap::test::write_text(dir / "broken.pcd", office.substr(0, 50000));
  // One line carries its own option (the scanner of that input), as docs/batch.md shows.
  indoormap::test::write_text(
      dir / "inputs.txt", "# three inputs\n" + (dir / "small.xyz").string() +
                              " --scanner 2,1.5,1.2\n" + (dir / "broken.pcd").string() + "\n\n" +
                              (dir / "wide.xyz").string() + "\n");
  return dir / "inputs.txt";
}

// A stand-in for Slurm's sbatch: logs its arguments, copies the script to a spool directory (as
// Slurm does), runs an --array=1-N%M job's tasks one after the other with SLURM_ARRAY_TASK_ID and
// the --export variables, runs any other job at once (the index job's afterany dependency holds:
// the tasks have ended), and prints a job id.
// clang-format off
const char* kFakeSbatch = R"sh(#!/usr/bin/env bash
here="$(dirname "$0")"
echo "$*" >>"$here/calls.txt"
array="" script=""
while [ $# -gt 0 ] && [ -z "$script" ]; do
  case "$1" in
    --array=*) array="${1#--array=}" ;;
    --export=ALL,*) export "${1#--export=ALL,}" ;;
    --*) ;;
    *) script=$1 ;;
  esac
  shift
done
mkdir -p "$here/spool" && cp "$script" "$here/spool/job.sh"
if [ -n "$array" ]; then
  range="${array%%%*}"
  for k in $(seq "${range%-*}" "${range#*-}"); do
    SLURM_ARRAY_TASK_ID=$k bash "$here/spool/job.sh" "$@" >/dev/null 2>&1
    echo "task $k exit $?" >>"$here/calls.txt"
  done
else
  bash "$here/spool/job.sh" "$@" >/dev/null 2>&1
  echo "job exit $?" >>"$here/calls.txt"
fi
echo "$((1000 + $(wc -l <"$here/calls.txt")))"
)sh";
// clang-format on

}  // namespace

TEST(Batch, ParallelRecipeReportsEachInputAndIndexesAll) {
  if (std::system("command -v parallel >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "GNU parallel not installed (scripts/setup.sh installs it)";
  const fs::path dir = indoormap::test::scratch_dir();
  three_inputs(dir);
  const fs::path out = dir / "out";
  const std::string cmd = std::string(INDOORMAP_SOURCE_DIR) + "/scripts/batch.sh -j 2 -b " +
                          INDOORMAP_BIN_DIR + "/pcd-to-map -o " + out.string() + " " +
                          (dir / "inputs.txt").string() + " -- --cell-m 0.1 >" +
                          (dir / "stdout").string() + " 2>" + (dir / "stderr").string();
  const int status = std::system(cmd.c_str());
  const std::string err = indoormap::test::read_text(dir / "stderr");
  ASSERT_TRUE(WIFEXITED(status)) << err;
  EXPECT_EQ(WEXITSTATUS(status), 1) << "one input failed: exit 1\n" << err;
  EXPECT_NE(err.find("broken.pcd"), std::string::npos) << err;

  // The good inputs: complete outputs; the broken one: none, and a log naming the file.
  for (const char* name : {"0001_small", "0003_wide"}) {
    EXPECT_TRUE(fs::exists(out / name / "map.pgm")) << name;
    EXPECT_TRUE(fs::exists(out / name / "objects.json")) << name;
    EXPECT_TRUE(fs::exists(out / name / "summary.json")) << name;
  }
  EXPECT_FALSE(fs::exists(out / "0002_broken"));
  const std::string log = indoormap::test::read_text(out / "logs" / "0002_broken.log");
  EXPECT_NE(log.find("broken.pcd"), std::string::npos) << log;

  // index.json: one row per input in list order, figures equal to each summary.json.
  const json index = json::parse(indoormap::test::read_text(out / "index.json"));
  EXPECT_EQ(index["inputs"], 3);
  EXPECT_EQ(index["ok"], 2);
  EXPECT_EQ(index["failed"], 1);
  EXPECT_EQ(index["not_run"], 0);
  ASSERT_EQ(index["rows"].size(), 3u);
  for (int k = 0; k < 3; ++k) {
    const json& row = index["rows"][k];
    EXPECT_EQ(row["k"], k + 1);
    EXPECT_GT(row["seconds"].get<double>(), 0.0);
    if (k == 1) {
      EXPECT_EQ(row["status"], "failed");
      EXPECT_EQ(row["exit_code"], 2);  // bad input
      EXPECT_NE(row["error"].get<std::string>().find("broken.pcd"), std::string::npos) << row;
      EXPECT_TRUE(row["points_kept"].is_null());
      continue;
    }
    EXPECT_EQ(row["status"], "ok") << row;
    EXPECT_EQ(row["exit_code"], 0);
    const json s = json::parse(
        indoormap::test::read_text(out / row["outdir"].get<std::string>() / "summary.json"));
    EXPECT_EQ(row["points_kept"], s["points"]["kept"]);
    EXPECT_EQ(row["grid_cells"], std::to_string(s["grid"]["size_cells"][0].get<int>()) + "x" +
                                     std::to_string(s["grid"]["size_cells"][1].get<int>()));
    EXPECT_EQ(row["objects"], s["objects"]["count"]);
    EXPECT_EQ(row["rooms"], s["rooms"]["count"]);
    EXPECT_EQ(row["room_closed"], s["border"]["closed"]);
    EXPECT_NEAR(row["room_height_m"].get<double>(), s["room_height_m"].get<double>(), 1e-3);
    EXPECT_DOUBLE_EQ(s["parameters"]["voxel"]["cell_m"].get<double>(), 0.1);  // the shared args
  }
  EXPECT_EQ(index["rows"][0]["input"].get<std::string>().find("--scanner 2,1.5,1.2"),
            (dir / "small.xyz").string().size() + 1);
  // The room of the wide input is wider: the rows are not mixed up.
  EXPECT_LT(index["rows"][0]["points_kept"].get<int>(), index["rows"][2]["points_kept"].get<int>());

  // index.csv: a header and the same three rows.
  const auto csv = lines_of(indoormap::test::read_text(out / "index.csv"));
  ASSERT_EQ(csv.size(), 4u);
  EXPECT_EQ(csv[0].rfind("k,input,outdir,status,exit_code,seconds,error,", 0), 0u) << csv[0];
  EXPECT_NE(csv[2].find(",failed,2,"), std::string::npos) << csv[2];
  EXPECT_NE(csv[1].find(",0001_small,ok,0,"), std::string::npos) << csv[1];

  // A run killed before its status line (a Slurm time limit, a lost node): the index of the
  // same OUTROOT still has its row, "not run", from OUTROOT/inputs.txt.
  fs::remove(out / "status" / "0003_wide.tsv");
  const std::string reindex = std::string(INDOORMAP_SOURCE_DIR) + "/scripts/batch.sh --index " +
                              out.string() + " 2>" + (dir / "stderr2").string();
  const int status2 = std::system(reindex.c_str());
  ASSERT_TRUE(WIFEXITED(status2));
  EXPECT_EQ(WEXITSTATUS(status2), 1);
  const json again = json::parse(indoormap::test::read_text(out / "index.json"));
  EXPECT_EQ(again["ok"], 1);
  EXPECT_EQ(again["not_run"], 1);
  ASSERT_EQ(again["rows"].size(), 3u);
  EXPECT_EQ(again["rows"][2]["status"], "not run");
  EXPECT_EQ(again["rows"][2]["input"], (dir / "wide.xyz").string());
  EXPECT_TRUE(again["rows"][2]["exit_code"].is_null());
}  // namespace

// scripts/batch_slurm.sh submit under the fake sbatch: an array of one task per input (each
// batch.sh --run-one, the failure kept to its task) and an afterany index job over them.
TEST(Batch, SlurmScriptSubmitsAnArrayAndAnIndexJob) {
  const fs::path dir = indoormap::test::scratch_dir();
  const fs::path list = three_inputs(dir);
  const fs::path fake = dir / "slurm";
  fs::create_directories(fake);
  indoormap::test::write_text(fake / "sbatch", kFakeSbatch);
  fs::permissions(fake / "sbatch", fs::perms::owner_all);
  const fs::path out = dir / "out";
  const std::string cmd = "PATH=" + fake.string() + ":$PATH PCD_TO_MAP=" + INDOORMAP_BIN_DIR +
                          "/pcd-to-map " + INDOORMAP_SOURCE_DIR +
                          "/scripts/batch_slurm.sh submit " + list.string() + " " + out.string() +
                          " -- --cell-m 0.1 2>" + (dir / "stderr").string();
  const int status = std::system(cmd.c_str());
  const std::string err = indoormap::test::read_text(dir / "stderr");
  ASSERT_TRUE(WIFEXITED(status)) << err;
  EXPECT_EQ(WEXITSTATUS(status), 0) << err;  // submitted
  const auto calls = lines_of(indoormap::test::read_text(fake / "calls.txt"));
  ASSERT_EQ(calls.size(), 6u) << indoormap::test::read_text(fake / "calls.txt");
  EXPECT_NE(calls[0].find("--array=1-3%50"), std::string::npos) << calls[0];
  EXPECT_NE(calls[0].find(" task " + list.string() + " " + out.string() + " --cell-m 0.1"),
            std::string::npos)
      << calls[0];
  EXPECT_EQ(calls[1], "task 1 exit 0");
  EXPECT_EQ(calls[2], "task 2 exit 2");  // the broken input's task fails alone
  EXPECT_EQ(calls[3], "task 3 exit 0");
  EXPECT_NE(calls[4].find("--dependency=afterany:1004 "), std::string::npos) << calls[4];
  EXPECT_NE(calls[4].find(" index " + out.string()), std::string::npos) << calls[4];
  EXPECT_EQ(calls[5], "job exit 1");  // the index job: one input failed
  EXPECT_NE(err.find("3 inputs: array job 1004"), std::string::npos) << err;

  const json index = json::parse(indoormap::test::read_text(out / "index.json"));
  EXPECT_EQ(index["ok"], 2);
  EXPECT_EQ(index["failed"], 1);
  ASSERT_EQ(index["rows"].size(), 3u);
  EXPECT_EQ(index["rows"][1]["exit_code"], 2);
  for (const char* name : {"0001_small", "0003_wide"}) {
    const json s = json::parse(indoormap::test::read_text(out / name / "summary.json"));
    EXPECT_DOUBLE_EQ(s["parameters"]["voxel"]["cell_m"].get<double>(), 0.1) << name;
  }
  EXPECT_FALSE(fs::exists(out / "0002_broken"));
}
