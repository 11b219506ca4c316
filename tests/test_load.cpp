// Loaders: every format on small hand-written files with known points, 3DTK poses against
// hand-computed numbers and the real Jacobs data, and bad input with the message checked.
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/core/errors.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using indoormap::BudgetError;
using indoormap::InputError;
using indoormap::cloud_io::load_cloud;
using indoormap::cloud_io::load_clouds;
using indoormap::cloud_io::LoadOptions;
using indoormap::cloud_io::UpAxis;
using indoormap::test::scratch_dir;
using indoormap::test::write_text;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

void expect_point(const Eigen::Vector3f& p, double x, double y, double z, double tol = 1e-5) {
  EXPECT_NEAR(p.x(), x, tol);
  EXPECT_NEAR(p.y(), y, tol);
  EXPECT_NEAR(p.z(), z, tol);
}

template <typename T>
void append(std::string& s, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  s.append(b, sizeof(T));
}

// Runs f, expects it to throw E, and returns the message.
template <typename E, typename F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type: " << e.what();
    return {};
  }
  ADD_FAILURE() << "no exception thrown";
  return {};
}

#define EXPECT_CONTAINS(haystack, needle) \
  EXPECT_NE(std::string(haystack).find(needle), std::string::npos) << (haystack)

std::string pcd_header(const std::string& fields, const std::string& sizes,
                       const std::string& types, const std::string& counts, std::uint64_t n,
                       const std::string& data) {
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS " + fields + "\nSIZE " +
         sizes + "\nTYPE " + types + "\nCOUNT " + counts + "\nWIDTH " + std::to_string(n) +
         "\nHEIGHT 1\nVIEWPOINT 0.5 -1 2 1 0 0 0\nPOINTS " + std::to_string(n) + "\nDATA " + data +
         "\n";
}

// Three points (1,2,3) (4,5,6) (NaN...) as binary PCD with x y float, z double, plus a byte.
std::string binary_pcd() {
  std::string s = pcd_header("x y z label", "4 4 8 1", "F F F U", "1 1 1 1", 3, "binary");
  const float xy[3][2] = {{1, 2}, {4, 5}, {kNaN, kNaN}};
  const double z[3] = {3, 6, std::nan("")};
  for (int i = 0; i < 3; ++i) {
    append(s, xy[i][0]);
    append(s, xy[i][1]);
    append(s, z[i]);
    append(s, std::uint8_t{7});
  }
  return s;
}

// LZF stream made of literal runs only (control byte < 32: copy the next control+1 bytes),
// which is valid input for PCL's lzf_decompress.
std::string lzf_literals(const std::string& raw) {
  std::string out;
  for (std::size_t i = 0; i < raw.size(); i += 32) {
    const std::size_t n = std::min<std::size_t>(32, raw.size() - i);
    out.push_back(static_cast<char>(n - 1));
    out.append(raw, i, n);
  }
  return out;
}

// binary_compressed PCD of (1,2,3) (4,5,6) (-1,0.5,8): PCL stores the fields one after the
// other (all x, then all y, then all z) before compressing.
std::string compressed_pcd(std::uint32_t* bad_uncompressed = nullptr) {
  std::string s = pcd_header("x y z", "4 4 4", "F F F", "1 1 1", 3, "binary_compressed");
  std::string raw;
  for (float v : {1.0f, 4.0f, -1.0f, 2.0f, 5.0f, 0.5f, 3.0f, 6.0f, 8.0f}) append(raw, v);
  const std::string packed = lzf_literals(raw);
  append(s, static_cast<std::uint32_t>(packed.size()));
  append(s, bad_uncompressed ? *bad_uncompressed : static_cast<std::uint32_t>(raw.size()));
  return s + packed;
}

const char* kAsciiPcd =
    "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\n"
    "WIDTH 3\nHEIGHT 1\nVIEWPOINT 1 2 3 1 0 0 0\nPOINTS 3\nDATA ascii\n"
    "1 2 3 0\n-4.5 5 6e1 0\nnan nan nan 0\n";

std::string binary_ply(bool truncate = false) {
  std::string s =
      "ply\nformat binary_little_endian 1.0\ncomment made by hand\nelement vertex 2\n"
      "property float x\nproperty float y\nproperty double z\nproperty uchar red\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  append(s, 1.5f);
  append(s, -2.0f);
  append(s, 3.25);
  append(s, std::uint8_t{255});
  append(s, 10.0f);
  append(s, 20.0f);
  append(s, 30.0);
  append(s, std::uint8_t{0});
  if (truncate) return s.substr(0, s.size() - 5);
  append(s, std::uint8_t{3});
  for (int i : {0, 1, 0}) append(s, i);
  return s;
}

}  // namespace

// ---------------------------------------------------------------------------------------- PCD

TEST(LoadPcd, AsciiPointsViewpointAndDroppedNaN) {
  const auto f = scratch_dir() / "a.pcd";
  write_text(f, kAsciiPcd);
  const auto r = load_cloud(f.string());
  ASSERT_EQ(r.cloud.points.size(), 2u);
  expect_point(r.cloud.points[0], 1, 2, 3);
  expect_point(r.cloud.points[1], -4.5, 5, 60);
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

  // Centimetres, y up: (x, y, z) cm -> (x, -z, y) / 100 m; the VIEWPOINT converts the same way.
  LoadOptions o;
  o.unit_m = 0.01;
  o.up_axis = UpAxis::kY;
  r = load_cloud(f.string(), o);
  ASSERT_EQ(r.cloud.points.size(), 2u);
  expect_point(r.cloud.points[0], 0.01, -0.03, 0.02);
  expect_point(r.cloud.points[1], 0.04, -0.06, 0.05);
  ASSERT_EQ(r.cloud.scanners.size(), 1u);
  EXPECT_NEAR(r.cloud.scanners[0].x(), 0.005, 1e-12);
  EXPECT_NEAR(r.cloud.scanners[0].y(), -0.02, 1e-12);
  EXPECT_NEAR(r.cloud.scanners[0].z(), -0.01, 1e-12);
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

// ---------------------------------------------------------------------------------- bad input

TEST(LoadErrors, MissingFileDirectoryAndUnknownExtension) {
  const auto dir = scratch_dir();
  auto msg = message_of<InputError>([&] { load_cloud((dir / "nope.pcd").string()); });
  EXPECT_CONTAINS(msg, "nope.pcd");
  EXPECT_CONTAINS(msg, "no such file");
  msg = message_of<InputError>([&] { load_cloud((dir / "nope.las").string()); });
  EXPECT_CONTAINS(msg, "no such file");

  fs::create_directories(dir / "d.pcd");
  msg = message_of<InputError>([&] { load_cloud((dir / "d.pcd").string()); });
  EXPECT_CONTAINS(msg, "d.pcd");
  EXPECT_CONTAINS(msg, "is a directory");

  write_text(dir / "x.las", "whatever");
  msg = message_of<InputError>([&] { load_cloud((dir / "x.las").string()); });
  EXPECT_CONTAINS(msg, "x.las");
  EXPECT_CONTAINS(msg, "unknown file type '.las'");
  EXPECT_CONTAINS(msg, ".pcd, .ply, .xyz");

  fs::create_directories(dir / "empty_dir");
  msg = message_of<InputError>([&] { load_cloud((dir / "empty_dir").string()); });
  EXPECT_CONTAINS(msg, "empty_dir");
  EXPECT_CONTAINS(msg, "no 3DTK scan files (scanNNN.3d)");
}

TEST(LoadErrors, EmptyFiles) {
  const auto dir = scratch_dir();
  for (const char* name : {"e.pcd", "e.ply", "e.xyz", "e.3d"}) {
    write_text(dir / name, "");
    const auto msg = message_of<InputError>([&] { load_cloud((dir / name).string()); });
    EXPECT_CONTAINS(msg, name);
    EXPECT_CONTAINS(msg, "empty");
  }
  write_text(dir / "comments.xyz", "# nothing\n\n");
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "comments.xyz").string()); }),
                  "empty cloud: no points");
}

TEST(LoadErrors, PcdHeaderProblemsNameFileAndLine) {
  const auto dir = scratch_dir();
  struct Case {
    std::string text, needle;
  };
  const std::string tail = "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n";
  const std::string head = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  const std::vector<Case> cases = {
      {"VERSION 0.7\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n" + tail, ":8: PCD header: no FIELDS"},
      {"VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 65536\n"
       "HEIGHT 65536\nPOINTS 0\nDATA binary\n",
       ":8: PCD header: WIDTH 65536 x HEIGHT 65536 does not equal POINTS 0"},
      {head + "WIDTH 2\nHEIGHT 2\nPOINTS 3\nDATA ascii\n1 2 3\n", ":8: PCD header: WIDTH 2 x"},
      {head + "WIDTH 0\nHEIGHT 1\nPOINTS 0\nDATA ascii\n", ":8: PCD header: POINTS is 0: empty"},
      {"VERSION 0.7\nFIELDS x y\nSIZE 4 4\nTYPE F F\nCOUNT 1 1\n" + tail,
       ":2: PCD header: FIELDS has no 'z'"},
      {"VERSION 0.7\nFIELDS x y z\nSIZE 4 4\nTYPE F F F\nCOUNT 1 1 1\n" + tail,
       ":3: PCD header: SIZE has 2 values but FIELDS has 3"},
      {head + "WIDTH 1\nHEIGHT 1\nPOINTS 1\n", ":8: PCD header: ends without a DATA line"},
      {head + "WIDTH one\n", ":6: PCD header: WIDTH value 'one'"},
      {head + "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA zip\n", ":9: PCD header: DATA 'zip'"},
      // 4e9 points promised, a few bytes present: refused before anyone allocates.
      {head + "WIDTH 4000000000\nHEIGHT 1\nPOINTS 4000000000\nDATA binary\nabcdefghijkl",
       ":9: PCD data section too short for POINTS 4000000000"},
      {head + "WIDTH 4000000000\nHEIGHT 1\nPOINTS 4000000000\nDATA ascii\n1 2 3\n",
       ":9: PCD data section too short for POINTS 4000000000"},
      {head + "WIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA binary\n" + std::string(35, 'a'),
       ":9: PCD data section too short for POINTS 3"},
      // ASCII bodies are checked line by line (PCL would silently read zeros).
      {head + "WIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n1 2 3\n4 5 6\n7       8\n",
       ":12: PCD data line has 2 values, expected 3"},
      {head + "WIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n1 2 3\n4 five 6\n7 8 9\n",
       ":11: PCD value 'five' of field y is not a number"},
      {head + "WIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n1 2 3\n4 5 6\n\n\n\n\n\n\n",
       ": PCD data has 2 points but POINTS says 3"},
      {head + "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n4 5 6\n",
       ":11: more data lines than POINTS 1"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    // Appending (not "h" + to_string) avoids GCC 12's false -Wrestrict (GCC bug 105651).
    std::string name = "h";
    name += std::to_string(i);
    const auto f = dir / (name + ".pcd");
    write_text(f, cases[i].text);
    const auto msg = message_of<InputError>([&] { load_cloud(f.string()); });
    EXPECT_CONTAINS(msg, f.string() + cases[i].needle);
  }
}

TEST(LoadErrors, PcdCompressedSizesChecked) {
  const auto dir = scratch_dir();
  std::uint32_t wrong = 1000;
  write_text(dir / "u.pcd", compressed_pcd(&wrong));
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "u.pcd").string()); }),
                  "uncompressed size 1000 does not match");
  const std::string good = compressed_pcd();
  write_text(dir / "t.pcd", good.substr(0, good.size() - 4));
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "t.pcd").string()); }),
                  "too short");
}

// Every prefix of a valid file is either refused with InputError or (when only the final
// newline is missing) loaded in full: never a crash, never another exception, never a
// silently shortened or zero-filled cloud.
TEST(LoadErrors, TruncatedFilesNeverCrash) {
  const auto dir = scratch_dir();
  const std::vector<std::pair<std::string, std::string>> files = {{"a.pcd", kAsciiPcd},
                                                                  {"b.pcd", binary_pcd()},
                                                                  {"c.pcd", compressed_pcd()},
                                                                  {"b.ply", binary_ply()}};
  for (const auto& [name, bytes] : files) {
    for (std::size_t n = 0; n < bytes.size(); ++n) {
      const auto f = dir / name;
      write_text(f, bytes.substr(0, n));
      try {
        const auto r = load_cloud(f.string());
        const auto full = dir / ("full_" + name);
        write_text(full, bytes);
        EXPECT_EQ(r.cloud.points, load_cloud(full.string()).cloud.points)
            << name << " cut at " << n;
      } catch (const InputError& e) {
        EXPECT_CONTAINS(e.what(), f.string());
      } catch (const std::exception& e) {
        ADD_FAILURE() << name << " cut at " << n << ": " << e.what();
      }
    }
  }
}

TEST(LoadErrors, PlyProblems) {
  const auto dir = scratch_dir();
  write_text(dir / "t.ply", binary_ply(true));
  auto msg = message_of<InputError>([&] { load_cloud((dir / "t.ply").string()); });
  EXPECT_CONTAINS(msg, "t.ply");
  EXPECT_CONTAINS(msg, "truncated");

  write_text(dir / "h.ply",
             "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
             "property float x\nproperty float y\nproperty float z\nend_header\n0123456789ab");
  msg = message_of<InputError>([&] { load_cloud((dir / "h.ply").string()); });
  EXPECT_CONTAINS(msg, "h.ply:3: PLY data section too short for 4000000000 'vertex'");

  write_text(dir / "n.ply",
             "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
             "property float y\nend_header\n1 2\n");
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "n.ply").string()); }),
                  "n.ply:3: PLY header: vertex has no property 'z'");

  write_text(dir / "m.ply", "plx\n");
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "m.ply").string()); }),
                  "m.ply:1: PLY header: the file does not start with 'ply'");

  write_text(dir / "e.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n");
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "e.ply").string()); }),
                  "ends without end_header");

  write_text(dir / "v.ply",
             "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
             "property float y\nproperty float z\nend_header\n1 2 3\n4 five 6\n");
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "v.ply").string()); }),
                  "v.ply:9: PLY value 'five' is not a number");
}

TEST(LoadErrors, MalformedXyzLineNamesLine) {
  const auto dir = scratch_dir();
  write_text(dir / "m.xyz", "# header\n1 2 3\n4 5\n");
  auto msg = message_of<InputError>([&] { load_cloud((dir / "m.xyz").string()); });
  EXPECT_CONTAINS(msg, "m.xyz:3: malformed line");
  EXPECT_CONTAINS(msg, "'4 5'");
  write_text(dir / "n.txt", "1 2 3\r\n1 2 3x\r\n");
  msg = message_of<InputError>([&] { load_cloud((dir / "n.txt").string()); });
  EXPECT_CONTAINS(msg, "n.txt:2: malformed line");
  write_text(dir / "scan000.3d", "1 2 3\nabc\n");
  msg = message_of<InputError>([&] { load_cloud((dir / "scan000.3d").string()); });
  EXPECT_CONTAINS(msg, "scan000.3d:2: malformed line");
  fs::create_directories(dir / "s");
  write_text(dir / "s" / "scan000.3d", "1 2 3\n");
  write_text(dir / "s" / "scan000.pose", "1 2 3\n4 5\n");
  msg = message_of<InputError>([&] { load_cloud((dir / "s").string()); });
  EXPECT_CONTAINS(msg, "scan000.pose:2: pose line 2 must be the Euler angles");
}

TEST(LoadErrors, AllNaN) {
  const auto dir = scratch_dir();
  write_text(dir / "n.xyz", "nan nan nan\ninf 0 0\n");
  const auto msg = message_of<InputError>([&] { load_cloud((dir / "n.xyz").string()); });
  EXPECT_CONTAINS(msg, "n.xyz");
  EXPECT_CONTAINS(msg, "all 2 points are non-finite");
}

TEST(LoadErrors, BudgetExceeded) {
  const auto dir = scratch_dir();
  write_text(dir / "a.pcd", kAsciiPcd);
  write_text(dir / "b.xyz", "1 2 3\n4 5 6\n7 8 9\n");
  write_text(dir / "c.ply", binary_ply());
  LoadOptions o;
  o.max_points = 2;
  auto msg = message_of<BudgetError>([&] { load_cloud((dir / "a.pcd").string(), o); });
  EXPECT_CONTAINS(msg, "a.pcd: 3 points exceed the point budget (max_points 2)");
  msg = message_of<BudgetError>([&] { load_cloud((dir / "b.xyz").string(), o); });
  EXPECT_CONTAINS(msg, "b.xyz");
  EXPECT_CONTAINS(msg, "max_points 2");
  // The running total counts: 2 PLY points fit alone, not after the 3 PCD points.
  o.max_points = 4;
  EXPECT_EQ(load_cloud((dir / "c.ply").string(), o).cloud.points.size(), 2u);
  msg = message_of<BudgetError>([&] {
    load_clouds({(dir / "a.pcd").string(), (dir / "c.ply").string()}, o);
  });
  EXPECT_CONTAINS(msg, "c.ply: 2 points exceed the point budget (max_points 4, 3 already loaded)");
}
