// Tests of the scene simulator's files (lib/sim, apps/scene-sim): the PCD and 3DTK exports, the
// app's outputs, determinism and errors. Geometry and the scanner model: test_sim.cpp.
#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/cloud_io/write.hpp"
#include "indoormap/formats/ground_truth_json.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace indoormap;

namespace {

std::string office_yaml() {
  return std::string(INDOORMAP_SOURCE_DIR) + "/scenes/office.yaml";
}

}  // namespace

TEST(SimOutput, BinaryPcdHeaderAndData) {
  const fs::path dir = test::scratch_dir();
  std::vector<Eigen::Vector3f> pts = {{1, 2, 3}, {-0.5f, 0.25f, 4}};
  cloud_io::write_pcd_binary((dir / "c.pcd").string(), pts, {0.5, 1.5, 1.25});
  const std::string b = test::read_text(dir / "c.pcd");
  const std::string header =
      "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F "
      "F\n"
      "COUNT 1 1 1\nWIDTH 2\nHEIGHT 1\nVIEWPOINT 0.5 1.5 1.25 1 0 0 0\nPOINTS 2\nDATA binary\n";
  ASSERT_EQ(b.substr(0, header.size()), header);
  ASSERT_EQ(b.size(), header.size() + 24);
  float v[6];
  std::memcpy(v, b.data() + header.size(), sizeof v);
  EXPECT_EQ(v[0], 1.0f);
  EXPECT_EQ(v[4], 0.25f);
  EXPECT_EQ(v[5], 4.0f);
  // No temporary file left behind.
  int files = 0;
  for (auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(SimOutput, SceneSimWritesByteIdenticalFilesForASeed) {
  const fs::path a = test::scratch_dir() / "a", b = test::scratch_dir() / "b",
                 c = test::scratch_dir() / "c";
  const std::string args = " --random --seed 4 --rooms 2 --step-deg 1 --3dtk --sector-deg 120 -q";
  ASSERT_EQ(test::run_app("scene-sim", args + " -o " + a.string()).exit_code, 0);
  ASSERT_EQ(test::run_app("scene-sim", args + " -o " + b.string()).exit_code, 0);
  ASSERT_EQ(
      test::run_app("scene-sim", " --random --seed 5 --rooms 2 --step-deg 1 -q -o " + c.string())
          .exit_code,
      0);
  int compared = 0;
  for (const auto& e : fs::recursive_directory_iterator(a)) {
    if (!e.is_regular_file() || e.path().filename() == "summary.json" ||  // holds timings
        e.path().filename() == "report.html" ||                           // shows them
        e.path().filename() == ".indoormap-outputs")                      // the manifest
      continue;
    const fs::path rel = fs::relative(e.path(), a);
    EXPECT_EQ(test::read_text(e.path()), test::read_text(b / rel)) << rel;
    ++compared;
  }
  EXPECT_EQ(compared,
            7 + 2 * 3 * 3);  // cloud, truth json, pgm, png, yaml, seen pgm + yaml; 3 positions x
                             // 3 sectors x 2
  EXPECT_NE(test::read_text(a / "cloud.pcd"), test::read_text(c / "cloud.pcd"));
}

TEST(SimOutput, OfficeSceneMatchesTheAcceptance) {
  const fs::path dir = test::scratch_dir();
  const auto r = test::run_app("scene-sim", office_yaml() + " -q -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto size = fs::file_size(dir / "cloud.pcd");
  EXPECT_LT(size, 10u * 1000 * 1000);
  const formats::TruthFile t = formats::read_truth_json(dir / "ground_truth.json");
  ASSERT_EQ(t.rooms.size(), 2u);
  const auto [lo, hi] = bounds(t.rooms[0].polygon);
  EXPECT_NEAR(hi.x() - lo.x(), 8.5, 1e-9);
  EXPECT_NEAR(hi.y() - lo.y(), 6.0, 1e-9);
  // The committed default cloud is what the committed scene file gives.
  const fs::path committed = fs::path(INDOORMAP_SOURCE_DIR) / "clouds" / "office";
  if (fs::exists(committed / "cloud.pcd")) {
    for (const char* f :
         {"cloud.pcd", "ground_truth.json", "ground_truth_layout.pgm", "ground_truth_layout.yaml"})
      EXPECT_EQ(test::read_text(dir / f), test::read_text(committed / f))
          << f << " differs from clouds/office: regenerate it";
  }
}

TEST(SimOutput, BadSceneFilesGetAClearErrorAndExitCode2) {
  const fs::path dir = test::scratch_dir();
  struct Case {
    std::string yaml, expect;
  };
  const std::vector<Case> cases = {
      {"rooms: [\n  {polygon: [[0,0],[4,0]]\n", "bad.yaml:"},  // YAML syntax error
      {"scanners: [{position: [1, 1, 1]}]\n", "key 'rooms': missing"},
      {"rooms:\n  - polygon: [[0,0],[4,0],[4,3],[0,3]]\n    heigth_m: 3\nscanners: [{position: "
       "[1,1,1]}]\n",
       "bad.yaml:3: key 'rooms[0].heigth_m': unknown key"},
      {"rooms:\n  - polygon: [[0,0],[4,0],[4,3],[0,3]]\n    doors: [{edge: 0, at_m: "
       "3.9}]\nscanners: [{position: [1,1,1]}]\n",
       "bad.yaml:3: key 'rooms[0].doors[0].at_m'"},
      {"rooms:\n  - polygon: [[0,0],[4,0],[4,3],[0,3]]\nfurniture:\n  - {type: sofa, center: "
       "[1,1], size: [1,1]}\n"
       "scanners: [{position: [1,1,1]}]\n",
       "bad.yaml:4: key 'furniture[0].type'"},
      {"rooms:\n  - polygon: [[0,0],[4,0],[4,3],[0,3]]\nscanners: [{position: [1, one, 1]}]\n",
       "bad.yaml:3: key 'scanners[0].position[1]': expected a number"},
  };
  for (const auto& c : cases) {
    test::write_text(dir / "bad.yaml", c.yaml);
    const auto r =
        test::run_app("scene-sim", (dir / "bad.yaml").string() + " -o " + (dir / "out").string());
    EXPECT_EQ(r.exit_code, 2) << c.yaml;
    EXPECT_NE(r.err.find("scene-sim: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos)
        << "expected '" << c.expect << "' in: " << r.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "cloud.pcd"));
  }
  EXPECT_EQ(
      test::run_app("scene-sim", (dir / "missing.yaml").string() + " -o " + (dir / "out").string())
          .exit_code,
      2);
  EXPECT_EQ(test::run_app("scene-sim", "--random --rooms 0 -o " + (dir / "out").string()).exit_code,
            2);
  EXPECT_EQ(test::run_app("scene-sim", "-o " + (dir / "out").string()).exit_code, 2);  // no scene
  const auto pc = test::run_app("scene-sim", office_yaml() + " --print-config");
  EXPECT_EQ(pc.exit_code, 0);
  EXPECT_NE(pc.out.find("azimuth_step_deg: 0.25"), std::string::npos) << pc.out;
}

// The 3DTK export read back by pcd-to-map's loader gives the PCD's points (same order: scan by
// scan), to within the 0.01 mm of the 3DTK text's three decimals in cm.
TEST(SimOutput, TdtkExportReadsBackAsTheSamePoints) {
  const fs::path dir = test::scratch_dir();
  const auto r = test::run_app(
      "scene-sim",
      "--random --seed 9 --rooms 2 --step-deg 0.8 --3dtk --sector-deg 40 -q -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto pcd = cloud_io::load_cloud((dir / "cloud.pcd").string());
  const auto tdtk = cloud_io::load_cloud((dir / "3dtk").string());
  ASSERT_EQ(pcd.cloud.points.size(), tdtk.cloud.points.size());
  ASSERT_GT(pcd.cloud.points.size(), 1000u);
  for (std::size_t i = 0; i < pcd.cloud.points.size(); ++i)
    ASSERT_LT((pcd.cloud.points[i] - tdtk.cloud.points[i]).norm(), 2e-4f) << "point " << i;
  EXPECT_EQ(tdtk.inputs.front().scans, 3 * 9);  // 3 positions x 9 sectors of 40 degrees
  // Scanner positions: the PCD's VIEWPOINT and every .pose are the tilted scanner positions.
  const auto truth = nlohmann::json::parse(test::read_text(dir / "ground_truth.json"));
  const auto& s0 = truth["scanners"][0]["position_cloud_m"];
  const Eigen::Vector3d first(s0[0].get<double>(), s0[1].get<double>(), s0[2].get<double>());
  ASSERT_FALSE(pcd.cloud.scanners.empty());
  EXPECT_LT((pcd.cloud.scanners.front() - first).norm(), 1e-6);
  ASSERT_FALSE(tdtk.cloud.scanners.empty());
  EXPECT_LT((tdtk.cloud.scanners.front() - first).norm(), 1e-4);
}
