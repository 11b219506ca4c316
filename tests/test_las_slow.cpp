// LAS input end to end (issue 19): pcd-to-map on a LAS file made from the default office cloud
// at UTM-like coordinates (scale 0.001, near 500,000 / 5,000,000 m) against the PCD. App-level,
// over 1 s: labelled slow.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "indoormap/cloud_io/las.hpp"
#include "indoormap/cloud_io/load.hpp"
#include "json_support.hpp"
#include "test_support.hpp"

using namespace indoormap;
using nlohmann::json;
using test::read_json;
using test::run_app;

namespace {

namespace fs = std::filesystem;

const Eigen::Vector3d kUtm(500000.0, 5000000.0, 0.0);

// map.yaml without its comment lines.
std::string yaml_keys(const fs::path& p) {
  std::istringstream in(test::read_text(p));
  std::string line, out;
  while (std::getline(in, line))
    if (!line.starts_with("#")) out += line + "\n";
  return out;
}

std::string scanner_arg(const Eigen::Vector3d& v) {
  char b[128];
  std::snprintf(b, sizeof b, " --scanner %.9g,%.9g,%.9g", v.x(), v.y(), v.z());
  return b;
}

struct Fixture {
  fs::path dir, las, pcd;
  Eigen::Vector3d viewpoint;
  std::vector<Eigen::Vector3f> points;
  fs::path las_out;  ///< pcd-to-map's outputs on the LAS file
  test::RunResult las_run;
};

// The office cloud as LAS at UTM coordinates (header offset kUtm, millimetre integers). The
// default office records at 1 mm (scenes/office.yaml, scanner.coordinate_step_m 0.001), so the
// LAS of scale 0.001 holds exactly its points.
const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture x;
    x.dir = test::scratch_dir();
    x.pcd = fs::path(INDOORMAP_SOURCE_DIR) / "clouds" / "office" / "cloud.pcd";
    const auto cloud = cloud_io::load_cloud(x.pcd.string());
    x.viewpoint = cloud.cloud.scanners.at(0);
    x.points = cloud.cloud.points;
    cloud_io::LasWriteOptions o;
    o.origin_m = kUtm;  // source = point + kUtm, in double
    o.offset = kUtm;    // the header offset a writer picks near the data
    o.scale = Eigen::Vector3d::Constant(0.001);
    x.las = x.dir / "office.las";
    cloud_io::write_las(x.las.string(), cloud.cloud.points, o);
    // A LAS file has no scanner position: the PCD's VIEWPOINT is given (local frame = PCD frame).
    x.las_out = x.dir / "las";
    x.las_run = run_app("pcd-to-map",
                        x.las.string() + scanner_arg(x.viewpoint) + " -q -o " + x.las_out.string());
    return x;
  }();
  return f;
}

}  // namespace

TEST(LasSlow, OfficeAsUtmLasGivesThePcdMapCellForCell) {
  const auto& f = fixture();
  ASSERT_EQ(f.las_run.exit_code, 0) << f.las_run.err;
  // The premise: every coordinate of the default cloud is a whole number of millimetres (to
  // float precision), so the LAS integers lose nothing.
  ASSERT_GT(f.points.size(), 100000u);
  for (const auto& p : f.points)
    for (int i = 0; i < 3; ++i) {
      const double mm = static_cast<double>(p[i]) * 1000.0;
      ASSERT_LT(std::abs(mm - std::round(mm)), 1e-3) << p.transpose();
    }
  const fs::path pcd_out = f.dir / "pcd";
  const auto r = run_app("pcd-to-map", f.pcd.string() + " -q -o " + pcd_out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Every byte of map.pgm and layout.pgm, and map.yaml's keys (origin, resolution), are equal:
  // the reader's offset and scale handling (in double) adds no error of its own.
  for (const char* name : {"map.pgm", "layout.pgm"})
    EXPECT_EQ(test::read_text(f.las_out / name), test::read_text(pcd_out / name)) << name;
  EXPECT_EQ(yaml_keys(f.las_out / "map.yaml"), yaml_keys(pcd_out / "map.yaml"));
  const json lj = read_json(f.las_out / "objects.json"), pj = read_json(pcd_out / "objects.json");
  EXPECT_EQ(lj["objects"].size(), pj["objects"].size());
}

TEST(LasSlow, SummaryAndMapYamlSayHowToGoBackToTheSourceFrame) {
  const auto& f = fixture();
  const fs::path& out = f.las_out;
  ASSERT_EQ(f.las_run.exit_code, 0) << f.las_run.err;
  const json s = read_json(out / "summary.json");
  ASSERT_TRUE(s["source_frame"].is_object()) << s.dump(2);
  const auto off = s["source_frame"]["offset"].get<std::vector<double>>();
  EXPECT_EQ(Eigen::Vector3d(off[0], off[1], off[2]), kUtm);
  EXPECT_EQ(s["inputs"][0]["format"], "las");
  EXPECT_EQ(s["inputs"][0]["source_offset"], s["source_frame"]["offset"]);
  // The recipe: source = offset + transpose(map_from_input) * p_map / unit_m (up axis z). The
  // scanner, in the map frame in the summary, goes back to the PCD viewpoint + kUtm.
  Eigen::Matrix3d rot;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rot(i, j) = s["levelling"]["map_from_input"][i][j];
  const auto sc = s["scanners_map_m"][0].get<std::vector<double>>();
  const Eigen::Vector3d back = kUtm + rot.transpose() * Eigen::Vector3d(sc[0], sc[1], sc[2]) /
                                          s["source_frame"]["unit_m"].get<double>();
  EXPECT_LT((back - (f.viewpoint + kUtm)).norm(), 1e-5);
  const std::string yaml = test::read_text(out / "map.yaml");
  EXPECT_NE(yaml.find("# source_offset: [500000.000, 5000000.000, 0.000]"), std::string::npos)
      << yaml;
  EXPECT_NE(yaml.find("# map frame = map_from_input * ((source frame - source_offset)"),
            std::string::npos)
      << yaml;
}
