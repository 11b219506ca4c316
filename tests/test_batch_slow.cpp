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

}  // namespace

TEST(Batch, ParallelRecipeReportsEachInputAndIndexesAll) {
  if (std::system("command -v parallel >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "GNU parallel not installed (scripts/setup.sh installs it)";
  const fs::path dir = indoormap::test::scratch_dir();
  indoormap::test::write_text(dir / "small.xyz", box_room_xyz(4.0, 3.0, 1));
  indoormap::test::write_text(dir / "wide.xyz", box_room_xyz(6.0, 4.0, 2));
  // The office cloud cut in its data section: its header promises more points than it holds.
  const std::string office =
      indoormap::test::read_text(fs::path(INDOORMAP_SOURCE_DIR) / "clouds/office/cloud.pcd");
  ASSERT_GT(office.size(), 100000u);
  indoormap::test::write_text(dir / "broken.pcd", office.substr(0, 50000));
  // One line carries its own option (the scanner of that input), as docs/batch.md shows.
  indoormap::test::write_text(
      dir / "inputs.txt", "# three inputs\n" + (dir / "small.xyz").string() +
                              " --scanner 2,1.5,1.2\n" + (dir / "broken.pcd").string() + "\n\n" +
                              (dir / "wide.xyz").string() + "\n");
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
}
