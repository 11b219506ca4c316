#pragma once
// Shared fixtures of the test_load_*.cpp files: point checks, exception messages, and small
// PCD / PLY files built in memory.
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

namespace load_fixtures {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

inline void expect_point(const Eigen::Vector3f& p, double x, double y, double z,
                         double tol = 1e-5) {
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

inline std::string pcd_header(const std::string& fields, const std::string& sizes,
                              const std::string& types, const std::string& counts, std::uint64_t n,
                              const std::string& data) {
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS " + fields + "\nSIZE " +
         sizes + "\nTYPE " + types + "\nCOUNT " + counts + "\nWIDTH " + std::to_string(n) +
         "\nHEIGHT 1\nVIEWPOINT 0.5 -1 2 1 0 0 0\nPOINTS " + std::to_string(n) + "\nDATA " + data +
         "\n";
}

// Three points (1,2,3) (4,5,6) (NaN...) as binary PCD with x y float, z double, plus a byte.
inline std::string binary_pcd() {
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
inline std::string lzf_literals(const std::string& raw) {
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
inline std::string compressed_pcd(std::uint32_t* bad_uncompressed = nullptr) {
  std::string s = pcd_header("x y z", "4 4 4", "F F F", "1 1 1", 3, "binary_compressed");
  std::string raw;
  for (float v : {1.0f, 4.0f, -1.0f, 2.0f, 5.0f, 0.5f, 3.0f, 6.0f, 8.0f}) append(raw, v);
  const std::string packed = lzf_literals(raw);
  append(s, static_cast<std::uint32_t>(packed.size()));
  append(s, bad_uncompressed ? *bad_uncompressed : static_cast<std::uint32_t>(raw.size()));
  return s + packed;
}

inline const char* kAsciiPcd =
    "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\n"
    "WIDTH 3\nHEIGHT 1\nVIEWPOINT 1 2 3 1 0 0 0\nPOINTS 3\nDATA ascii\n"
    "1 2 3 0\n-4.5 5 6e1 0\nnan nan nan 0\n";

inline std::string binary_ply(bool truncate = false) {
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

}  // namespace load_fixtures
