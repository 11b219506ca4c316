// LAS public header block: parsing and validation before anything is allocated, and the choice
// of the local-frame offset. Field offsets: ASPRS LAS 1.4 R15, "Public Header Block".
#include <cmath>
#include <cstring>
#include <string>

#include "indoormap/cloud_io/las.hpp"
#include "indoormap/core/errors.hpp"
#include "las_internal.hpp"

namespace indoormap::cloud_io {

namespace detail {

std::string las_laz_hint() {
  return "convert it to uncompressed LAS first, e.g. 'pdal translate in.laz out.las' (PDAL) or "
         "CloudCompare (save as LAS or PLY)";
}

}  // namespace detail

namespace {

using detail::las_f64;
using detail::las_u16;
using detail::las_u32;
using detail::las_u64;

constexpr std::size_t kBlockBytes[3] = {227, 235, 375};  // versions 1.2, 1.3, 1.4

std::string num(std::uint64_t v) {
  return std::to_string(v);
}

}  // namespace

LasHeader read_las_header(std::string_view head, std::uint64_t file_size, const std::string& file) {
  auto fail = [&](const std::string& problem) { throw InputError(file, "LAS: " + problem); };
  if (head.size() < 4 || head.substr(0, 4) != "LASF") fail("not a LAS file (no 'LASF' signature)");
  if (head.size() < kBlockBytes[0])
    fail("file of " + num(file_size) + " bytes is too short for a LAS header (227 bytes)");
  const auto* b = reinterpret_cast<const unsigned char*>(head.data());
  LasHeader h;
  const int major = b[24], minor = b[25];
  if (major != 1 || minor < 2 || minor > 4)
    fail("version " + std::to_string(major) + "." + std::to_string(minor) +
         " is not supported (LAS 1.2, 1.3 and 1.4 are)");
  h.version_minor = minor;
  const std::size_t block = kBlockBytes[minor - 2];
  h.header_bytes = las_u16(b + 94);
  h.point_offset = las_u32(b + 96);
  h.vlr_count = las_u32(b + 100);
  if (h.header_bytes < block)
    fail("header size " + num(h.header_bytes) + " is below the " + num(block) +
         " bytes of a LAS 1." + std::to_string(minor) + " header");
  if (head.size() < block || file_size < block)
    fail("file of " + num(file_size) + " bytes is too short for its LAS 1." +
         std::to_string(minor) + " header (" + num(block) + " bytes)");
  if (h.point_offset < h.header_bytes)
    fail("offset to point data " + num(h.point_offset) + " lies inside the header (" +
         num(h.header_bytes) + " bytes)");
  if (h.point_offset > file_size)
    fail("offset to point data " + num(h.point_offset) + " is past the end of the file (" +
         num(file_size) + " bytes)");
  const int format_byte = b[104];
  if (format_byte & 0xC0)
    fail("the points are compressed (LAZ, point format byte " + std::to_string(format_byte) +
         "): " + detail::las_laz_hint());
  if (format_byte > 10)
    fail("point data format " + std::to_string(format_byte) +
         " is not supported (formats 0-10 are)");
  h.point_format = format_byte;
  h.record_bytes = las_u16(b + 105);
  const auto min_record = kLasRecordBytes[static_cast<std::size_t>(h.point_format)];
  if (h.record_bytes < min_record)
    fail("point record length " + num(h.record_bytes) + " is below the " + num(min_record) +
         " bytes of point format " + std::to_string(h.point_format));
  const std::uint64_t legacy = las_u32(b + 107);
  h.points = legacy;
  if (minor == 4) {
    const std::uint64_t wide = las_u64(b + 247);
    if (legacy != 0 && wide != 0 && legacy != wide)
      fail("legacy point count " + num(legacy) + " and 64-bit point count " + num(wide) +
           " disagree");
    if (wide != 0) h.points = wide;
  }
  for (int a = 0; a < 3; ++a) {
    h.scale[a] = las_f64(b + 131 + 8 * a);
    h.offset[a] = las_f64(b + 155 + 8 * a);
    h.max[a] = las_f64(b + 179 + 16 * a);
    h.min[a] = las_f64(b + 187 + 16 * a);
    if (!std::isfinite(h.scale[a]) || h.scale[a] == 0.0)
      fail(std::string("scale factor of ") + "xyz"[a] + " is zero or not finite");
    if (!std::isfinite(h.offset[a])) fail(std::string("offset of ") + "xyz"[a] + " is not finite");
  }
  // The point data must fit between its offset and the end of the file (EVLRs and 1.3 waveform
  // data, if any, come after it): no count may promise more records than the bytes hold.
  const std::uint64_t avail = file_size - h.point_offset;
  if (h.points > avail / h.record_bytes)
    fail(num(h.points) + " points of " + num(h.record_bytes) + " bytes need more than the " +
         num(avail) + " bytes after the point data offset " + num(h.point_offset) +
         " (truncated file or a lying point count)");
  return h;
}

Eigen::Vector3d choose_las_offset(const LasHeader& h, const Eigen::Vector3d& first) {
  constexpr double kNear = 10'000.0, kRound = 100.0;
  const bool box_ok =
      h.min.allFinite() && h.max.allFinite() && (h.min.array() <= h.max.array()).all();
  Eigen::Vector3d o;
  for (int a = 0; a < 3; ++a) {
    if (!box_ok) {
      o[a] = std::isfinite(first[a]) ? std::floor(first[a] / kRound) * kRound : h.offset[a];
    } else if (std::abs(h.min[a] - h.offset[a]) <= kNear &&
               std::abs(h.max[a] - h.offset[a]) <= kNear) {
      o[a] = h.offset[a];
    } else {
      o[a] = std::floor(h.min[a] / kRound) * kRound;
    }
  }
  return o;
}

}  // namespace indoormap::cloud_io
