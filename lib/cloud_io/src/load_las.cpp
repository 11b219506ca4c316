// LAS (.las) point reader: header (las_header.cpp) and VLRs validated before any allocation, then
// the records streamed in fixed-size chunks; x, y, z scaled and moved to the local frame in
// double precision, everything else in a record (and any extra bytes) skipped.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "indoormap/cloud_io/las.hpp"
#include "indoormap/core/errors.hpp"
#include "las_internal.hpp"
#include "load_internal.hpp"

namespace indoormap::cloud_io::detail {

namespace {

constexpr std::size_t kVlrHeaderBytes = 54;
constexpr std::size_t kChunkRecords = 16384;

void las_seek(std::FILE* f, std::uint64_t at, const std::string& file) {
  if (at > static_cast<std::uint64_t>(std::numeric_limits<long>::max()) ||
      std::fseek(f, static_cast<long>(at), SEEK_SET) != 0)
    throw InputError(file, "LAS: cannot seek to byte " + std::to_string(at));
}

void las_read(std::FILE* f, unsigned char* buf, std::size_t n, const std::string& file,
              const char* what) {
  if (std::fread(buf, 1, n, f) != n)
    throw InputError(file,
                     std::string("LAS: ") + (std::ferror(f) ? "read error in " : "short ") + what);
}

// Walks the VLRs between the header and the point data: each must end before the point data
// starts (a lying count or length is refused), and a LASzip VLR means compressed points.
void check_vlrs(std::FILE* f, const LasHeader& h, const std::string& file) {
  const std::uint64_t room = h.point_offset - h.header_bytes;
  if (h.vlr_count > room / kVlrHeaderBytes)
    throw InputError(file, "LAS: " + std::to_string(h.vlr_count) +
                               " variable length records do not fit in the " +
                               std::to_string(room) + " bytes before the point data");
  std::uint64_t at = h.header_bytes;
  for (std::uint32_t k = 0; k < h.vlr_count; ++k) {
    if (h.point_offset - at < kVlrHeaderBytes)
      throw InputError(file, "LAS: variable length record " + std::to_string(k + 1) + " of " +
                                 std::to_string(h.vlr_count) + " (byte " + std::to_string(at) +
                                 ") runs past the point data offset " +
                                 std::to_string(h.point_offset));
    unsigned char v[kVlrHeaderBytes];
    las_seek(f, at, file);
    las_read(f, v, sizeof v, file, "variable length record");
    const std::uint16_t record_id = las_u16(v + 18), length = las_u16(v + 20);
    const std::string user(reinterpret_cast<const char*>(v + 2),
                           strnlen(reinterpret_cast<const char*>(v + 2), 16));
    if (user == "laszip encoded" || record_id == 22204)
      throw InputError(file, "LAS: the points are compressed (a LASzip record): " + las_laz_hint());
    at += kVlrHeaderBytes;
    if (h.point_offset - at < length)
      throw InputError(file, "LAS: variable length record " + std::to_string(k + 1) + " of " +
                                 std::to_string(h.vlr_count) + " (" + std::to_string(length) +
                                 " bytes at byte " + std::to_string(at) +
                                 ") runs past the point data offset " +
                                 std::to_string(h.point_offset));
    at += length;
  }
}

Eigen::Vector3d source_point(const unsigned char* rec, const LasHeader& h) {
  return {las_i32(rec) * h.scale.x() + h.offset.x(), las_i32(rec + 4) * h.scale.y() + h.offset.y(),
          las_i32(rec + 8) * h.scale.z() + h.offset.z()};
}

// The header's box (when it is sane) reaches more than 10 km from the offset.
bool far_from(const LasHeader& h, const Eigen::Vector3d& offset) {
  if (!h.min.allFinite() || !h.max.allFinite()) return false;
  return ((h.min - offset).cwiseAbs().array() > 1e4).any() ||
         ((h.max - offset).cwiseAbs().array() > 1e4).any();
}

}  // namespace

ReadInfo read_las(const std::string& file, const Budget& budget,
                  const std::optional<Eigen::Vector3d>& shared_offset,
                  std::vector<Eigen::Vector3f>& out) {
  const std::uint64_t size = checked_file_size(file);
  const std::string head = read_file_prefix(file, 375);
  const LasHeader h = read_las_header(head, size, file);
  FilePtr f(std::fopen(file.c_str(), "rb"));
  if (!f) throw InputError(file, std::string("cannot open: ") + std::strerror(errno));
  check_vlrs(f.get(), h, file);
  check_budget(file, h.points, budget);

  ReadInfo info;
  info.points = h.points;
  if (h.point_format >= 6 && h.version_minor < 4)
    info.warnings.push_back(file + ": point format " + std::to_string(h.point_format) +
                            " in a LAS 1." + std::to_string(h.version_minor) +
                            " file (the standard allows it from 1.4 on); read anyway");
  if (h.points == 0) return info;  // load.cpp reports the empty cloud

  las_seek(f.get(), h.point_offset, file);
  const std::size_t chunk =
      static_cast<std::size_t>(std::min<std::uint64_t>(h.points, kChunkRecords));
  std::vector<unsigned char> buf(chunk * h.record_bytes);
  reserve_more(out, h.points);
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  for (std::uint64_t done = 0; done < h.points;) {
    const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(h.points - done, chunk));
    las_read(f.get(), buf.data(), n * h.record_bytes, file, "point data");
    if (done == 0) {
      offset = shared_offset ? *shared_offset : choose_las_offset(h, source_point(buf.data(), h));
      info.source_offset = offset;
      if (shared_offset && far_from(h, offset))
        info.warnings.push_back(file +
                                ": more than 10 km from the local frame of the first LAS "
                                "input; its coordinates keep less precision");
    }
    // integer * scale + (header offset - local offset): the large terms cancel in double first,
    // so a header offset chosen as the local origin gives integer * scale exactly.
    const Eigen::Vector3d shift = h.offset - offset;
    for (std::size_t i = 0; i < n; ++i) {
      const unsigned char* rec = buf.data() + i * h.record_bytes;
      out.emplace_back(static_cast<float>(las_i32(rec) * h.scale.x() + shift.x()),
                       static_cast<float>(las_i32(rec + 4) * h.scale.y() + shift.y()),
                       static_cast<float>(las_i32(rec + 8) * h.scale.z() + shift.z()));
    }
    done += n;
  }
  return info;
}

}  // namespace indoormap::cloud_io::detail
