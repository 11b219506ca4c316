// Loaders: every format on small hand-written files with known points, 3DTK poses against
// hand-computed numbers and the real Jacobs data, and merging.
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/core/errors.hpp"
#include "load_fixtures.hpp"
#include "test_support.hpp"

using namespace load_fixtures;

// ---------------------------------------------------------------------------------------- PCD

TEST(LoadPcd, AsciiPointsViewpointAndDroppedNaN) {
  const auto f = scratch_dir() / "a.pcd";
  write_text(f, kAsciiPcd);
  const auto r = load_cloud(f.string());
  ASSERT_EQ(r.cloud.points.size(), 2u);
  expect_point(r.cloud.points[0], 1, 2, 3);
  expect_point(r.cloud.points[1], -4.5, 5, 60);
  EXPECT_EQ(r.lo_m, Eigen::Vector3f(-4.5f, 2, 3)) << "the NaN point counts not";
  EXPECT_EQ(r.hi_m, Eigen::Vector3f(1, 5, 60));
  ASSERT_EQ(r.inputs.size(), 1u);
  EXPECT_EQ(r.inputs[0].format, "pcd");
  EXPECT_EQ(r.inputs[0].points_read, 3u);
  EXPECT_EQ(r.inputs[0].points_dropped, 1u);
  EXPECT_TRUE(r.inputs[0].scanner_known);
  ASSERT_EQ(r.cloud.scanners.size(), 1u);
  EXPECT_EQ(r.cloud.scanners[0], Eigen::Vector3d(1, 2, 3));
}

TEST(LoadPcd, BinaryWithDoubleFieldAndUnitAxisConversion) {
  const auto f = scratch_dir() / "b.pcd";
  write_text(f, binary_pcd());
  auto r = load_cloud(f.string());
  ASSERT_EQ(r.cloud.points.size(), 2u);
  expect_point(r.cloud.points[0], 1, 2, 3);
  expect_point(r.cloud.points[1], 4, 5, 6);
  EXPECT_EQ(r.inputs[0].points_dropped, 1u);
  EXPECT_EQ(r.lo_m, Eigen::Vector3f(1, 2, 3)) << "bounds of the kept points, taken while loading";
  EXPECT_EQ(r.hi_m, Eigen::Vector3f(4, 5, 6));

  // Centimetres, y up: (x, y, z) cm -> (x, -z, y) / 100 m; the VIEWPOINT converts the same way.
  LoadOptions o;
  o.unit_m = 0.01;
  o.up_axis = UpAxis::kY;
  r = load_cloud(f.string(), o);
  ASSERT_EQ(r.cloud.points.size(), 2u);
  expect_point(r.cloud.points[0], 0.01, -0.03, 0.02);
  expect_point(r.cloud.points[1], 0.04, -0.06, 0.05);
  EXPECT_NEAR(r.lo_m.y(), -0.06, 1e-6) << "bounds in the output frame";
  EXPECT_NEAR(r.hi_m.y(), -0.03, 1e-6);
  ASSERT_EQ(r.cloud.scanners.size(), 1u);
  EXPECT_NEAR(r.cloud.scanners[0].x(), 0.005, 1e-12);
  EXPECT_NEAR(r.cloud.scanners[0].y(), -0.02, 1e-12);
  EXPECT_NEAR(r.cloud.scanners[0].z(), -0.01, 1e-12);
}

// The binary body reader: fields before x with COUNT > 1, more points than one read chunk
// (4 MiB), every point where it was written, in order.
TEST(LoadPcd, BinaryManyPointsAcrossChunksWithLeadingArrayField) {
  const std::size_t n = 300'000;  // 15 bytes each: 4.5 MB, two chunks
  std::string bytes =
      "# .PCD v0.7\nVERSION 0.7\nFIELDS tag x y z\nSIZE 1 4 4 4\nTYPE U F F F\n"
      "COUNT 3 1 1 1\nWIDTH " +
      std::to_string(n) + "\nHEIGHT 1\nPOINTS " + std::to_string(n) + "\nDATA binary\n";
  auto coord = [](std::size_t i, int a) { return static_cast<float>(i) * 0.001f + 10.0f * a; };
  for (std::size_t i = 0; i < n; ++i) {
    bytes.append(3, static_cast<char>(i & 0x7f));
    for (int a = 0; a < 3; ++a) {
      const float v = coord(i, a);
      char b[4];
      std::memcpy(b, &v, 4);
      bytes.append(b, 4);
    }
  }
  const auto f = scratch_dir() / "many.pcd";
  write_text(f, bytes);
  const auto r = load_cloud(f.string());
  ASSERT_EQ(r.cloud.points.size(), n);
  for (std::size_t i = 0; i < n; i += 997)
    for (int a = 0; a < 3; ++a) ASSERT_EQ(r.cloud.points[i][a], coord(i, a)) << i << " " << a;
  EXPECT_EQ(r.cloud.points.back(),
            Eigen::Vector3f(coord(n - 1, 0), coord(n - 1, 1), coord(n - 1, 2)));
}

TEST(LoadPcd, BinaryCompressed) {
  const auto f = scratch_dir() / "c.pcd";
  write_text(f, compressed_pcd());
  const auto r = load_cloud(f.string());
  ASSERT_EQ(r.cloud.points.size(), 3u);
  expect_point(r.cloud.points[0], 1, 2, 3);
  expect_point(r.cloud.points[1], 4, 5, 6);
  expect_point(r.cloud.points[2], -1, 0.5, 8);
  EXPECT_EQ(r.cloud.scanners.at(0), Eigen::Vector3d(0.5, -1, 2));
}

TEST(LoadPcd, HeaderParsedAndValidated) {
  const std::string bytes = binary_pcd();
  const auto h = indoormap::cloud_io::read_pcd_header(bytes, "b.pcd", 1000);
  EXPECT_EQ(h.fields, (std::vector<std::string>{"x", "y", "z", "label"}));
  EXPECT_EQ(h.sizes, (std::vector<int>{4, 4, 8, 1}));
  EXPECT_EQ(h.types, (std::vector<char>{'F', 'F', 'F', 'U'}));
  EXPECT_EQ(h.points, 3u);
  EXPECT_EQ(h.point_size, 17u);
  EXPECT_EQ(h.data, "binary");
  EXPECT_TRUE(h.has_viewpoint);
  EXPECT_EQ(h.viewpoint[0], 0.5);
  EXPECT_EQ(h.data_offset, bytes.size() - 3 * 17);
  EXPECT_THROW(indoormap::cloud_io::read_pcd_header(bytes, "b.pcd", 2), BudgetError);
}

// ---------------------------------------------------------------------------------------- PLY

TEST(LoadPly, AsciiWithFaces) {
  const auto f = scratch_dir() / "a.ply";
  write_text(
      f,
      "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\n"
      "property float z\r\nproperty uchar red\r\nelement face 1\r\n"
      "property list uchar int vertex_indices\r\nend_header\r\n"
      "1 2 3 255\r\n-1.5 0 2e2 0\r\nnan 1 1 0\r\n3 0 1 2\r\n");
  const auto r = load_cloud(f.string());
  ASSERT_EQ(r.cloud.points.size(), 2u);
  expect_point(r.cloud.points[0], 1, 2, 3);
  expect_point(r.cloud.points[1], -1.5, 0, 200);
  EXPECT_EQ(r.inputs[0].format, "ply");
  EXPECT_EQ(r.inputs[0].points_read, 3u);
  EXPECT_EQ(r.inputs[0].points_dropped, 1u);
  EXPECT_FALSE(r.inputs[0].scanner_known);
}

TEST(LoadPly, BinaryLittleEndian) {
  const auto f = scratch_dir() / "b.ply";
  write_text(f, binary_ply());
  const auto r = load_cloud(f.string());
  ASSERT_EQ(r.cloud.points.size(), 2u);
  expect_point(r.cloud.points[0], 1.5, -2, 3.25);
  expect_point(r.cloud.points[1], 10, 20, 30);
}

TEST(LoadPly, BinaryBigEndian) {
  std::string s =
      "ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n";
  for (float v : {1.0f, -2.0f, 0.5f}) {
    char b[4];
    std::memcpy(b, &v, 4);
    std::reverse(b, b + 4);
    s.append(b, 4);
  }
  const auto f = scratch_dir() / "be.ply";
  write_text(f, s);
  const auto r = load_cloud(f.string());
  ASSERT_EQ(r.cloud.points.size(), 1u);
  expect_point(r.cloud.points[0], 1, -2, 0.5);
}

// ---------------------------------------------------------------------------------------- XYZ

TEST(LoadXyz, CommentsCommasCrlfExtraColumnsAndNaN) {
  const auto f = scratch_dir() / "p.xyz";
  write_text(f,
             "# a comment\r\n// another\r\n\r\n1 2 3\r\n4,5,6,7,8\r\n  7\t8\t9 extra words\n"
             "+1e2 -2.5e-1 .5\nnan 1 2\n1 inf 2\n  -1 , 2 ,3");
  const auto r = load_cloud(f.string());
  ASSERT_EQ(r.cloud.points.size(), 5u);
  expect_point(r.cloud.points[0], 1, 2, 3);
  expect_point(r.cloud.points[1], 4, 5, 6);
  expect_point(r.cloud.points[2], 7, 8, 9);
  expect_point(r.cloud.points[3], 100, -0.25, 0.5);
  expect_point(r.cloud.points[4], -1, 2, 3);
  EXPECT_EQ(r.inputs[0].format, "xyz");
  EXPECT_EQ(r.inputs[0].points_read, 7u);
  EXPECT_EQ(r.inputs[0].points_dropped, 2u);
}

TEST(LoadXyz, UnitAndUpAxis) {
  const auto f = scratch_dir() / "cm.txt";
  write_text(f, "100 200 300\n-50 0 25\n");
  LoadOptions o;
  o.unit_m = 0.01;
  o.up_axis = UpAxis::kY;
  const auto r = load_cloud(f.string(), o);
  ASSERT_EQ(r.cloud.points.size(), 2u);
  expect_point(r.cloud.points[0], 1, -3, 2);
  expect_point(r.cloud.points[1], -0.5, -0.25, 0);
  o.up_axis = UpAxis::kZ;
  expect_point(load_cloud(f.string(), o).cloud.points[0], 1, 2, 3);
}

TEST(LoadXyz, CsvHeaderAndProgress) {
  const auto f = scratch_dir() / "p.csv";
  write_text(f, "x,y,z,intensity\n1,2,3,4\n5,6,7,8\n");
  LoadOptions o;
  std::vector<double> fractions;
  o.progress = [&](const std::string& file, double fraction) {
    EXPECT_EQ(file, f.string());
    fractions.push_back(fraction);
  };
  const auto r = load_cloud(f.string(), o);
  ASSERT_EQ(r.cloud.points.size(), 2u);
  expect_point(r.cloud.points[1], 5, 6, 7);
  ASSERT_FALSE(fractions.empty());
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
}

TEST(LoadXyz, LargeFileAcrossChunks) {
  // More than one 4 MiB read chunk, so lines split across chunk borders are exercised.
  const auto f = scratch_dir() / "big.xyz";
  std::string s;
  const int n = 300000;
  for (int i = 0; i < n; ++i)
    s += std::to_string(i) + " " + std::to_string(-i) + " 0.25 extra-column-padding\n";
  ASSERT_GT(s.size(), 8u << 20);
  write_text(f, s);
  int calls = 0;
  LoadOptions o;
  o.progress = [&](const std::string&, double) { ++calls; };
  const auto r = load_cloud(f.string(), o);
  ASSERT_EQ(r.cloud.points.size(), static_cast<std::size_t>(n));
  for (int i : {0, 1, 123456, n - 1}) expect_point(r.cloud.points[i], i, -i, 0.25);
  EXPECT_GE(calls, 3);
}

// --------------------------------------------------------------------------------------- 3DTK

TEST(Load3dtk, PoseFileHandComputed) {
  const auto dir = scratch_dir();
  write_text(dir / "scan000.3d", "100 50 -200 0 255 0 0 21.5\n0 0 0\n-30 10 40\n");
  // Translation cm, Euler degrees. Expected values from R = Rx(10) Ry(30) Rz(-20) applied in
  // 3DTK's frame, then X = z/100, Y = -x/100, Z = y/100 (computed independently in Python).
  write_text(dir / "scan000.pose", "5 -7 12\n10 30 -20\n");
  const auto r = load_cloud(dir.string());
  ASSERT_EQ(r.cloud.points.size(), 3u);
  expect_point(r.cloud.points[0], -2.1104546, -0.0118967, 0.4530874);
  expect_point(r.cloud.points[1], 0.12, -0.05, -0.07);
  expect_point(r.cloud.points[2], 0.6172536, -0.0354805, 0.0419286);
  ASSERT_EQ(r.cloud.scanners.size(), 1u);
  EXPECT_NEAR(r.cloud.scanners[0].x(), 0.12, 1e-12);
  EXPECT_NEAR(r.cloud.scanners[0].y(), -0.05, 1e-12);
  EXPECT_NEAR(r.cloud.scanners[0].z(), -0.07, 1e-12);
  EXPECT_EQ(r.inputs[0].format, "3dtk");
  EXPECT_EQ(r.inputs[0].scans, 1);
  EXPECT_TRUE(r.inputs[0].scanner_known);
}

TEST(Load3dtk, FramesPreferredOverPoseAndScanRange) {
  const auto dir = scratch_dir();
  write_text(dir / "scan001.3d", "100 50 -200\n");
  // Identity pose, but the last frames line (rotation of 90 degrees about y, translation
  // 10 20 30 cm) wins: x' = z + 10, y' = y + 20, z' = -x + 30.
  write_text(dir / "scan001.pose", "0 0 0\n0 0 0\n");
  write_text(dir / "scan001.frames",
             "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 2\n"
             "0 0 -1 0 0 1 0 0 1 0 0 0 10 20 30 1 3\n\n");
  write_text(dir / "scan002.3d", "1 2 3\n");  // no pose: identity, scanner unknown
  write_text(dir / "notes.txt", "ignored\n");
  LoadOptions o;
  o.scan_first = 1;
  o.scan_last = 1;
  auto r = load_cloud(dir.string(), o);
  ASSERT_EQ(r.cloud.points.size(), 1u);
  expect_point(r.cloud.points[0], -0.70, 1.90, 0.70);
  ASSERT_EQ(r.cloud.scanners.size(), 1u);
  EXPECT_NEAR((r.cloud.scanners[0] - Eigen::Vector3d(0.30, -0.10, 0.20)).norm(), 0, 1e-12);

  o.scan_first = 2;
  o.scan_last = -1;
  r = load_cloud(dir.string(), o);
  ASSERT_EQ(r.cloud.points.size(), 1u);
  expect_point(r.cloud.points[0], 0.03, -0.01, 0.02);
  EXPECT_TRUE(r.cloud.scanners.empty());
  EXPECT_FALSE(r.inputs[0].scanner_known);

  // A single scan file uses the pose beside it; unit_m / up_axis do not apply to 3DTK.
  o = LoadOptions{};
  o.unit_m = 1000;
  o.up_axis = UpAxis::kY;
  r = load_cloud((dir / "scan001.3d").string(), o);
  ASSERT_EQ(r.cloud.points.size(), 1u);
  expect_point(r.cloud.points[0], -0.70, 1.90, 0.70);

  o = LoadOptions{};
  o.scan_first = 5;
  const auto msg = message_of<InputError>([&] { load_cloud(dir.string(), o); });
  EXPECT_CONTAINS(msg, "no 3DTK scan files");
}

TEST(Load3dtk, PoseMatrixConvention) {
  const double t[3] = {1, 2, 3}, zero[3] = {0, 0, 0}, ry[3] = {0, 90, 0};
  auto m = indoormap::cloud_io::tdtk_pose_to_matrix(t, zero);
  const std::array<double, 16> id = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1};
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(m[i], id[i], 1e-15) << i;
  m = indoormap::cloud_io::tdtk_pose_to_matrix(zero, ry);
  const std::array<double, 16> y90 = {0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1};
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(m[i], y90[i], 1e-15) << i;
}

TEST(Load3dtkRealData, PoseEqualsFramesForAllSectors) {
  INDOORMAP_REQUIRE_DATA(data, "jacobs-thermocolorlab");
  for (int s = 0; s <= 8; ++s) {
    const std::string stem = (data / ("scan00" + std::to_string(s))).string();
    std::ifstream pose(stem + ".pose");
    double t[3], e[3];
    ASSERT_TRUE(pose >> t[0] >> t[1] >> t[2] >> e[0] >> e[1] >> e[2]) << stem;
    std::ifstream frames(stem + ".frames");
    std::string line, last;
    while (std::getline(frames, line))
      if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    std::istringstream ls(last);
    std::array<double, 16> f;
    for (auto& v : f) ASSERT_TRUE(ls >> v) << stem;
    const auto m = indoormap::cloud_io::tdtk_pose_to_matrix(t, e);
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(m[i], f[i], 1e-4) << stem << " element " << i;
  }
}

TEST(Load3dtkRealData, JacobsNineSectors) {
  INDOORMAP_REQUIRE_DATA(data, "jacobs-thermocolorlab");
  const auto r = load_cloud(data.string());
  ASSERT_EQ(r.inputs.size(), 1u);
  EXPECT_EQ(r.inputs[0].scans, 9);
  EXPECT_EQ(r.inputs[0].points_read, 516110u);
  EXPECT_EQ(r.cloud.points.size() + r.inputs[0].points_dropped, 516110u);
  // All nine sectors share one scan position: one scanner.
  ASSERT_EQ(r.cloud.scanners.size(), 1u);
  EXPECT_NEAR(r.cloud.scanners[0].x(), -0.135, 1e-9);
  EXPECT_NEAR(r.cloud.scanners[0].y(), 0.0, 1e-9);
  EXPECT_NEAR(r.cloud.scanners[0].z(), 0.4325, 1e-9);
  // The room: about 8.5 m x 6 m, ceiling 2.8 - 3 m above the floor. Most points lie within
  // 6 m of the scanner horizontally and within 3.5 m vertically.
  std::size_t inside = 0;
  for (const auto& p : r.cloud.points)
    if (std::hypot(p.x() + 0.135, p.y()) < 6.0 && std::abs(p.z() - 0.4325) < 3.5) ++inside;
  EXPECT_GT(inside, r.cloud.points.size() * 95 / 100);
}

TEST(Load3dtkRealData, FirstPointOfScan000HandComputed) {
  INDOORMAP_REQUIRE_DATA(data, "jacobs-thermocolorlab");
  LoadOptions o;
  o.scan_first = 0;
  o.scan_last = 0;
  const auto r = load_cloud(data.string(), o);
  EXPECT_EQ(r.inputs[0].scans, 1);
  ASSERT_FALSE(r.cloud.points.empty());
  // scan000.3d line 1: -145.227 -50.8312 175.738 (cm); pose t = (0, 43.25, -13.5) cm,
  // Euler (0, 240, 0) deg; R = Ry(240); then X = z/100, Y = -x/100, Z = y/100 (Python).
  expect_point(r.cloud.points[0], -2.2713927, 0.7958007, -0.0758120, 1e-5);
}

// ------------------------------------------------------------------------------------ merging

TEST(LoadMerge, CountsAddUpAndScannersCollected) {
  const auto dir = scratch_dir();
  write_text(dir / "a.pcd", kAsciiPcd);
  write_text(dir / "b.xyz", "7 8 9\n10 11 12\nnan 0 0\n");
  fs::create_directories(dir / "scans");
  write_text(dir / "scans" / "scan000.3d", "0 0 0\n");
  write_text(dir / "scans" / "scan000.pose", "100 200 300\n0 0 0\n");
  const auto r =
      load_clouds({(dir / "a.pcd").string(), (dir / "b.xyz").string(), (dir / "scans").string()});
  ASSERT_EQ(r.inputs.size(), 3u);
  EXPECT_EQ(r.cloud.points.size(), 2u + 2u + 1u);
  EXPECT_EQ(r.inputs[0].points_read + r.inputs[1].points_read + r.inputs[2].points_read, 7u);
  EXPECT_EQ(r.inputs[0].points_dropped + r.inputs[1].points_dropped, 2u);
  expect_point(r.cloud.points[2], 7, 8, 9);
  expect_point(r.cloud.points[4], 3, -1, 2);
  ASSERT_EQ(r.cloud.scanners.size(), 2u);
  EXPECT_EQ(r.cloud.scanners[0], Eigen::Vector3d(1, 2, 3));
  EXPECT_NEAR((r.cloud.scanners[1] - Eigen::Vector3d(3, -1, 2)).norm(), 0, 1e-12);
}
