// cloud_io's writers, read back by its readers, and the loader's option checks. The readers
// themselves are tested in test_load.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/cloud_io/write.hpp"
#include "indoormap/core/errors.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace indoormap;

namespace {

std::vector<Eigen::Vector3f> some_points(int n, const Eigen::Vector3f& offset) {
  std::vector<Eigen::Vector3f> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back(offset + Eigen::Vector3f(0.1f * i, -0.05f * i, 0.3f + 0.01f * (i % 7)));
  return pts;
}

}  // namespace

TEST(WritePcd, BinaryReadsBackExactlyWithItsViewpoint) {
  const fs::path dir = test::scratch_dir();
  const auto pts = some_points(50, {1.f, 2.f, 0.f});
  cloud_io::write_pcd_binary((dir / "c.pcd").string(), pts, {0.5, -1.5, 1.25});
  const auto r = cloud_io::load_cloud((dir / "c.pcd").string());
  ASSERT_EQ(r.cloud.points.size(), pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) EXPECT_EQ(r.cloud.points[i], pts[i]);
  ASSERT_EQ(r.cloud.scanners.size(), 1u);
  EXPECT_LT((r.cloud.scanners[0] - Eigen::Vector3d(0.5, -1.5, 1.25)).norm(), 1e-9);
}

// Each scan in its local frame, 3DTK units; the loader's .pose puts it back at its scanner.
TEST(Write3dtk, ScansReadBackAtTheirScannersWithinTheTextPrecision) {
  const fs::path dir = test::scratch_dir() / "scans";
  const auto a = some_points(30, {1.f, 2.f, 0.f}), b = some_points(20, {-3.f, 0.5f, 0.2f});
  const Eigen::Vector3d sa(1.5, 2.5, 1.2), sb(-2.0, 0.0, 1.4);
  const auto files = cloud_io::write_3dtk_scans(dir, {{a, sa}, {b, sb}});
  EXPECT_EQ(files,
            (std::vector<std::string>{"scan000.3d", "scan000.pose", "scan001.3d", "scan001.pose"}));
  EXPECT_EQ(test::read_text(dir / "scan000.pose"), "-250.000 120.000 150.000\n0 0 0\n");
  const auto r = cloud_io::load_cloud(dir.string());
  EXPECT_EQ(r.inputs.front().scans, 2);
  ASSERT_EQ(r.cloud.points.size(), a.size() + b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_LT((r.cloud.points[i] - a[i]).norm(), 2e-5f);
  for (std::size_t i = 0; i < b.size(); ++i)
    EXPECT_LT((r.cloud.points[a.size() + i] - b[i]).norm(), 2e-5f);
  ASSERT_EQ(r.cloud.scanners.size(), 2u);
  EXPECT_LT((r.cloud.scanners[0] - sa).norm(), 1e-9);
  EXPECT_LT((r.cloud.scanners[1] - sb).norm(), 1e-9);
}

TEST(Write3dtk, UnwritableDirectoryIsAnOutputError) {
  const fs::path dir = test::scratch_dir();
  test::write_text(dir / "file", "x");
  const auto pts = some_points(3, {0.f, 0.f, 0.f});
  EXPECT_THROW(cloud_io::write_3dtk_scans(dir / "file" / "sub", {{pts, {0, 0, 0}}}), OutputError);
}

TEST(LoadOptions, ValidateNamesTheKeyAndLoadCloudsCallsIt) {
  cloud_io::LoadOptions o;
  EXPECT_NO_THROW(cloud_io::validate(o));
  o.unit_m = 0;
  try {
    cloud_io::load_clouds({"whatever.pcd"}, o);
    FAIL() << "no UsageError";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), "invalid parameter input.unit_m: must be > 0");
  }
  o.unit_m = std::numeric_limits<double>::infinity();
  EXPECT_THROW(cloud_io::validate(o), UsageError);
  o = {};
  o.max_points = 0;
  try {
    cloud_io::validate(o);
    FAIL() << "no UsageError";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), "invalid parameter input.max_points: must be > 0");
  }
}
