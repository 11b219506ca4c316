// LAS 1.2-1.4 reader and writer (lib/cloud_io las.hpp): every point format read back, extra bytes
// skipped, 64-bit counts, the local frame, and headers that lie (built in memory) refused with
// the file and the problem named.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "indoormap/cloud_io/las.hpp"
#include "indoormap/cloud_io/load.hpp"
#include "indoormap/core/errors.hpp"
#include "load_fixtures.hpp"
#include "test_support.hpp"

using namespace load_fixtures;
using indoormap::UsageError;
using indoormap::cloud_io::choose_las_offset;
using indoormap::cloud_io::kLasRecordBytes;
using indoormap::cloud_io::LasHeader;
using indoormap::cloud_io::LasWriteOptions;
using indoormap::cloud_io::read_las_header;
using indoormap::cloud_io::write_las;

namespace {

std::vector<Eigen::Vector3f> some_points() {
  return {{1.2344f, -2.5f, 0.0f},
          {10.0f, 20.0f, 3.0f},
          {-0.0006f, 7.0009f, 2.4999f},
          {4.5f, 4.5f, 1.25f}};
}

std::string file_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void put_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

template <typename T>
void patch(std::string& s, std::size_t at, T v) {
  std::memcpy(s.data() + at, &v, sizeof v);
}

// A valid LAS file's bytes (4 points, given version and format), to be patched by a test.
std::string las_bytes(int minor = 2, int format = 0) {
  const auto path = scratch_dir() / "base.las";
  LasWriteOptions o;
  o.version_minor = minor;
  o.point_format = format;
  write_las(path.string(), some_points(), o);
  return file_bytes(path);
}

std::string load_message(const std::string& bytes, const std::string& name = "bad.las") {
  const auto path = scratch_dir() / name;
  put_bytes(path, bytes);
  return message_of<InputError>([&] { load_cloud(path.string()); });
}

// The millimetre each coordinate is quantised to by a writer of scale 0.001 and offset 0.
double mm(float v) {
  return std::round(static_cast<double>(v) * 1000.0) / 1000.0;
}

}  // namespace

TEST(LoadLas, EveryPointFormatReadsBackThePointsWritten) {
  const auto dir = scratch_dir();
  const auto pts = some_points();
  for (int format = 0; format <= 10; ++format) {
    for (int minor : {2, 3, 4}) {
      if (format >= 6 && minor < 4) continue;
      SCOPED_TRACE("format " + std::to_string(format) + ", LAS 1." + std::to_string(minor));
      const auto path = dir / ("f" + std::to_string(format) + "_" + std::to_string(minor) + ".las");
      LasWriteOptions o;
      o.version_minor = minor;
      o.point_format = format;
      write_las(path.string(), pts, o);
      const std::size_t header = minor == 2 ? 227 : minor == 3 ? 235 : 375;
      EXPECT_EQ(fs::file_size(path), header + pts.size() * kLasRecordBytes[format]);
      const auto r = load_cloud(path.string());
      ASSERT_EQ(r.cloud.points.size(), pts.size());
      ASSERT_EQ(r.inputs.size(), 1u);
      EXPECT_EQ(r.inputs[0].format, "las");
      ASSERT_TRUE(r.source_offset.has_value());
      EXPECT_TRUE(r.source_offset->isZero());  // offset 0 and a box near it: the source frame
      for (std::size_t i = 0; i < pts.size(); ++i)
        expect_point(r.cloud.points[i], mm(pts[i].x()), mm(pts[i].y()), mm(pts[i].z()), 1e-6);
    }
  }
}

TEST(LoadLas, ExtraBytesPerRecordAreSkipped) {
  const auto dir = scratch_dir();
  const auto pts = some_points();
  for (int format : {1, 6}) {
    const auto path = dir / ("extra" + std::to_string(format) + ".las");
    LasWriteOptions o;
    o.version_minor = 4;
    o.point_format = format;
    o.extra_bytes = 13;
    write_las(path.string(), pts, o);
    std::string b = file_bytes(path);
    const std::size_t rec = kLasRecordBytes[format] + 13u;
    ASSERT_EQ(b.size(), 375 + pts.size() * rec);
    // Fill every extra byte with junk: a reader that took them as the next record would see it.
    for (std::size_t i = 0; i < pts.size(); ++i)
      std::memset(b.data() + 375 + i * rec + kLasRecordBytes[format], 0x7F, 13);
    put_bytes(path, b);
    const auto r = load_cloud(path.string());
    ASSERT_EQ(r.cloud.points.size(), pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i)
      expect_point(r.cloud.points[i], mm(pts[i].x()), mm(pts[i].y()), mm(pts[i].z()), 1e-6);
  }
}

TEST(LoadLas, Las14SixtyFourBitCount) {
  const auto dir = scratch_dir();
  const auto path = dir / "wide.las";
  LasWriteOptions o;
  o.version_minor = 4;
  o.point_format = 1;
  o.legacy_count = false;
  write_las(path.string(), some_points(), o);
  const std::string b = file_bytes(path);
  std::uint32_t legacy = 1;
  std::uint64_t wide = 0;
  std::memcpy(&legacy, b.data() + 107, 4);
  std::memcpy(&wide, b.data() + 247, 8);
  EXPECT_EQ(legacy, 0u);
  EXPECT_EQ(wide, 4u);
  EXPECT_EQ(load_cloud(path.string()).cloud.points.size(), 4u);
  // Both counts given and different: one of them lies.
  std::string lying = b;
  patch<std::uint32_t>(lying, 107, 3);
  EXPECT_CONTAINS(load_message(lying), "legacy point count 3 and 64-bit point count 4 disagree");
  // The legacy count alone in a 1.4 file (the 64-bit one 0) is read too.
  std::string old = b;
  patch<std::uint32_t>(old, 107, 4);
  patch<std::uint64_t>(old, 247, 0);
  put_bytes(dir / "legacy.las", old);
  EXPECT_EQ(load_cloud((dir / "legacy.las").string()).cloud.points.size(), 4u);
}

TEST(LoadLas, GeoreferencedCloudIsMovedToALocalFrameInDouble) {
  const auto dir = scratch_dir();
  const auto pts = some_points();
  const Eigen::Vector3d utm(512345.678, 5234567.891, 312.5);
  // Header offset 0 (a common writer's choice): the box is far from it in x and y, so the local
  // origin is the box minimum rounded down to 100 m; z stays (within 10 km of 0). With offset 0,
  // a northing needs a centimetre scale to fit an int32.
  LasWriteOptions o;
  o.origin_m = utm;
  o.scale = Eigen::Vector3d(0.01, 0.01, 0.01);
  write_las((dir / "far.las").string(), pts, o);
  auto r = load_cloud((dir / "far.las").string());
  ASSERT_TRUE(r.source_offset.has_value());
  EXPECT_EQ(*r.source_offset, Eigen::Vector3d(512300.0, 5234500.0, 0.0));
  EXPECT_EQ(*r.inputs[0].source_offset, *r.source_offset);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector3d src = pts[i].cast<double>() + utm;
    const Eigen::Vector3d local = src - *r.source_offset;
    // Centimetre quantisation plus float rounding at ~100 m: a float at 5e6 m is 0.5 m off.
    expect_point(r.cloud.points[i], local.x(), local.y(), local.z(), 5.1e-3);
  }
  // A header offset near the data is the local origin itself: local = integer * scale exactly.
  o.offset = Eigen::Vector3d(512000, 5234000, 0);
  o.scale = Eigen::Vector3d(0.001, 0.001, 0.001);
  write_las((dir / "near.las").string(), pts, o);
  r = load_cloud((dir / "near.las").string());
  EXPECT_EQ(*r.source_offset, o.offset);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector3d local = pts[i].cast<double>() + utm - o.offset;
    expect_point(r.cloud.points[i], std::round(local.x() * 1000) / 1000,
                 std::round(local.y() * 1000) / 1000, std::round(local.z() * 1000) / 1000, 1e-4);
  }
  // A second LAS input shares the first one's frame (tiles of one site stay aligned).
  LasWriteOptions o2 = o;
  o2.origin_m = utm + Eigen::Vector3d(250.0, 0.0, 0.0);
  o2.offset = Eigen::Vector3d(512300, 5234100, 0);  // its own header offset, not used
  write_las((dir / "tile2.las").string(), pts, o2);
  r = load_clouds({(dir / "near.las").string(), (dir / "tile2.las").string()});
  ASSERT_EQ(r.cloud.points.size(), 2 * pts.size());
  EXPECT_EQ(*r.inputs[1].source_offset, o.offset);
  expect_point(r.cloud.points[pts.size()], r.cloud.points[0].x() + 250.0, r.cloud.points[0].y(),
               r.cloud.points[0].z(), 1e-3);
}

TEST(LoadLas, OffsetChoiceDistrustsAnInvalidBox) {
  LasHeader h;
  h.offset = Eigen::Vector3d(0, 0, 0);
  h.min = Eigen::Vector3d(10, 10, 10);
  h.max = Eigen::Vector3d(0, 0, 0);  // inverted: not trusted, the first point decides
  EXPECT_EQ(choose_las_offset(h, Eigen::Vector3d(500123.4, -5000001.0, 12.0)),
            Eigen::Vector3d(500100.0, -5000100.0, 0.0));
  h.min = Eigen::Vector3d(NAN, 0, 0);
  EXPECT_EQ(choose_las_offset(h, Eigen::Vector3d(250.0, 0, 0)), Eigen::Vector3d(200.0, 0, 0));
}

TEST(LoadLas, LyingHeadersAreRefusedNamingTheProblem) {
  const std::string good = las_bytes(2, 1);  // 227 + 4 x 28 bytes
  struct Case {
    const char* what;
    std::string bytes;
    const char* needle;
  };
  std::vector<Case> cases;
  auto with = [&](const char* what, auto edit, const char* needle, const std::string& base) {
    std::string b = base;
    edit(b);
    cases.push_back({what, b, needle});
  };
  with(
      "signature", [](std::string& b) { b[0] = 'X'; }, "not a LAS file (no 'LASF' signature)",
      good);
  with(
      "truncated header", [](std::string& b) { b.resize(100); },
      "too short for a LAS header (227 bytes)", good);
  with(
      "version 1.1", [](std::string& b) { b[25] = 1; }, "version 1.1 is not supported", good);
  with(
      "version 2.0",
      [](std::string& b) {
        b[24] = 2;
        b[25] = 0;
      },
      "version 2.0 is not supported", good);
  with(
      "header size", [](std::string& b) { patch<std::uint16_t>(b, 94, 200); },
      "header size 200 is below the 227 bytes", good);
  with(
      "1.4 header size", [](std::string& b) { b[25] = 4; },
      "header size 227 is below the 375 bytes of a LAS 1.4 header", good);
  with(
      "offset past end", [](std::string& b) { patch<std::uint32_t>(b, 96, 100000); },
      "offset to point data 100000 is past the end of the file (339 bytes)", good);
  with(
      "offset in header", [](std::string& b) { patch<std::uint32_t>(b, 96, 100); },
      "offset to point data 100 lies inside the header", good);
  with(
      "format 11", [](std::string& b) { b[104] = 11; },
      "point data format 11 is not supported (formats 0-10 are)", good);
  with(
      "LAZ bit", [](std::string& b) { b[104] = static_cast<char>(0x81); },
      "compressed (LAZ, point format byte 129): convert it to uncompressed LAS first, e.g. "
      "'pdal translate in.laz out.las'",
      good);
  with(
      "short record", [](std::string& b) { patch<std::uint16_t>(b, 105, 20); },
      "point record length 20 is below the 28 bytes of point format 1", good);
  with(
      "lying count", [](std::string& b) { patch<std::uint32_t>(b, 107, 5); },
      "5 points of 28 bytes need more than the 112 bytes after the point data offset 227", good);
  with(
      "huge count", [](std::string& b) { patch<std::uint32_t>(b, 107, 0xFFFFFFFFu); },
      "4294967295 points of 28 bytes need more than", good);
  with(
      "truncated points", [](std::string& b) { b.resize(b.size() - 1); },
      "4 points of 28 bytes need more than the 111 bytes", good);
  with(
      "zero scale", [](std::string& b) { patch<double>(b, 139, 0.0); },
      "scale factor of y is zero or not finite", good);
  with(
      "NaN offset", [](std::string& b) { patch<double>(b, 171, NAN); }, "offset of z is not finite",
      good);
  with(
      "VLR count", [](std::string& b) { patch<std::uint32_t>(b, 100, 3); },
      "3 variable length records do not fit in the 0 bytes before the point data", good);
  // A header area with room for one VLR of 10 bytes, whose length says 4000.
  std::string vlr = good.substr(0, 227) + std::string(64, '\0') + good.substr(227);
  patch<std::uint32_t>(vlr, 96, 227 + 64);
  patch<std::uint32_t>(vlr, 100, 1);
  patch<std::uint16_t>(vlr, 227 + 20, 10);
  cases.push_back({"VLR fits (control)", vlr, ""});
  with(
      "VLR length", [](std::string& b) { patch<std::uint16_t>(b, 227 + 20, 4000); },
      "variable length record 1 of 1 (4000 bytes at byte 281) runs past the point data offset "
      "291",
      vlr);
  with(
      "two VLRs", [](std::string& b) { patch<std::uint32_t>(b, 100, 2); },
      "2 variable length records do not fit in the 64 bytes before the point data", vlr);
  with(
      "LASzip VLR",
      [](std::string& b) {
        std::memcpy(b.data() + 227 + 2, "laszip encoded", 14);
        patch<std::uint16_t>(b, 227 + 18, 22204);
      },
      "compressed (a LASzip record): convert it", vlr);
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    const auto path = scratch_dir() / "case.las";
    put_bytes(path, c.bytes);
    if (std::string(c.needle).empty()) {
      EXPECT_EQ(load_cloud(path.string()).cloud.points.size(), 4u);
      continue;
    }
    const std::string msg = load_message(c.bytes, "case.las");
    EXPECT_CONTAINS(msg, "case.las: LAS: ");
    EXPECT_CONTAINS(msg, c.needle);
  }
}

TEST(LoadLas, BudgetIsCheckedBeforeAllocating) {
  const auto path = scratch_dir() / "b.las";
  put_bytes(path, las_bytes(4, 6));
  LoadOptions o;
  o.max_points = 3;
  const auto msg = message_of<BudgetError>([&] { load_cloud(path.string(), o); });
  EXPECT_CONTAINS(msg, "b.las: 4 points exceed the point budget");
}

TEST(LoadLas, ExtensionsCaseInsensitiveAndLazE57GetAConversionHint) {
  const auto dir = scratch_dir();
  put_bytes(dir / "UPPER.LAS", las_bytes());
  EXPECT_EQ(load_cloud((dir / "UPPER.LAS").string()).cloud.points.size(), 4u);
  put_bytes(dir / "c.laz", las_bytes());
  auto msg = message_of<InputError>([&] { load_cloud((dir / "c.laz").string()); });
  EXPECT_CONTAINS(msg, "c.laz: compressed LAS (LAZ) is not read");
  EXPECT_CONTAINS(msg, "pdal translate in.laz out.las");
  EXPECT_CONTAINS(msg, "CloudCompare");
  write_text(dir / "s.E57", "ASTM-E57");
  msg = message_of<InputError>([&] { load_cloud((dir / "s.E57").string()); });
  EXPECT_CONTAINS(msg, "s.E57: E57 is not read: convert it to LAS or PLY first");
  // An empty LAS file (a header, no points) is an empty cloud.
  const auto empty = dir / "empty.las";
  write_las(empty.string(), {});
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud(empty.string()); }),
                  "empty cloud: no points");
}

TEST(LoadLas, WriterRefusesWhatLasCannotHold) {
  const auto path = (scratch_dir() / "w.las").string();
  LasWriteOptions o;
  o.point_format = 6;
  EXPECT_THROW(write_las(path, some_points(), o), UsageError);  // format 6 needs LAS 1.4
  o = {};
  o.scale = Eigen::Vector3d(1e-6, 1e-6, 1e-6);
  o.origin_m = Eigen::Vector3d(500000, 0, 0);  // 5e11 units: beyond int32
  EXPECT_THROW(write_las(path, some_points(), o), indoormap::OutputError);
  EXPECT_FALSE(fs::exists(path));
}
