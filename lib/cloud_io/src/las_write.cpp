// LAS writer (1.2-1.4, point formats 0-10, no VLRs), by hand; read back by load_cloud.
#include <cmath>
#include <cstring>
#include <string>

#include "indoormap/cloud_io/las.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::cloud_io {

namespace {

void put_le(std::string& s, std::size_t at, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) s[at + i] = static_cast<char>((v >> (8 * i)) & 0xFF);
}

void put_f64(std::string& s, std::size_t at, double d) {
  std::uint64_t u;
  std::memcpy(&u, &d, sizeof u);
  put_le(s, at, u, 8);
}

void check_options(const LasWriteOptions& o, std::size_t points) {
  if (o.version_minor < 2 || o.version_minor > 4)
    throw UsageError("write_las: version 1." + std::to_string(o.version_minor) +
                     " (1.2, 1.3 or 1.4)");
  if (o.point_format < 0 || o.point_format > 10)
    throw UsageError("write_las: point format " + std::to_string(o.point_format) + " (0-10)");
  if (o.point_format >= 6 && o.version_minor < 4)
    throw UsageError("write_las: point formats 6-10 need LAS 1.4");
  if (!(o.scale.array() > 0).all() || !o.scale.allFinite() || !o.offset.allFinite() ||
      !o.origin_m.allFinite())
    throw UsageError("write_las: scale must be > 0 and finite, offset and origin finite");
  if (kLasRecordBytes[static_cast<std::size_t>(o.point_format)] + o.extra_bytes > 0xFFFF)
    throw UsageError("write_las: record length above 65535 bytes");
  if (o.version_minor < 4 && points > 0xFFFFFFFFu)
    throw UsageError("write_las: more than 2^32 - 1 points need LAS 1.4");
}

}  // namespace

void write_las(const std::string& path, const std::vector<Eigen::Vector3f>& points,
               const LasWriteOptions& o) {
  check_options(o, points.size());
  const std::size_t block = o.version_minor == 2 ? 227 : o.version_minor == 3 ? 235 : 375;
  const std::size_t rec_bytes =
      kLasRecordBytes[static_cast<std::size_t>(o.point_format)] + o.extra_bytes;
  std::string recs(points.size() * rec_bytes, '\0');
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d src = points[i].cast<double>() + o.origin_m;
    for (int a = 0; a < 3; ++a) {
      const double q = std::round((src[a] - o.offset[a]) / o.scale[a]);
      if (!(q >= -2147483648.0 && q <= 2147483647.0))
        throw OutputError(path, "point " + std::to_string(i) +
                                    " does not fit a LAS int32 at this scale and offset");
      const auto v = static_cast<std::int32_t>(q);
      put_le(recs, i * rec_bytes + 4 * a, static_cast<std::uint32_t>(v), 4);
      const double back = v * o.scale[a] + o.offset[a];
      lo[a] = std::min(lo[a], back);
      hi[a] = std::max(hi[a], back);
    }
    recs[i * rec_bytes + 14] = o.point_format >= 6 ? 0x11 : 0x09;  // return 1 of 1
  }
  if (points.empty()) lo = hi = Eigen::Vector3d::Zero();

  std::string h(block, '\0');
  h.replace(0, 4, "LASF");
  h[24] = 1;
  h[25] = static_cast<char>(o.version_minor);
  h.replace(26, 9, "indoormap");
  h.replace(58, 9, "indoormap");
  put_le(h, 94, block, 2);
  put_le(h, 96, block, 4);
  h[104] = static_cast<char>(o.point_format);
  put_le(h, 105, rec_bytes, 2);
  const bool legacy = o.version_minor < 4 ||
                      (o.legacy_count && o.point_format <= 5 && points.size() <= 0xFFFFFFFFu);
  if (legacy) {
    put_le(h, 107, points.size(), 4);
    put_le(h, 111, points.size(), 4);  // all first returns
  }
  for (int a = 0; a < 3; ++a) {
    put_f64(h, 131 + 8 * a, o.scale[a]);
    put_f64(h, 155 + 8 * a, o.offset[a]);
    put_f64(h, 179 + 16 * a, hi[a]);
    put_f64(h, 187 + 16 * a, lo[a]);
  }
  if (o.version_minor == 4) {
    put_le(h, 247, points.size(), 8);
    put_le(h, 255, points.size(), 8);
  }
  write_stream_atomic(path, [&](std::ostream& out) {
    out.write(h.data(), static_cast<std::streamsize>(h.size()));
    out.write(recs.data(), static_cast<std::streamsize>(recs.size()));
  });
}

}  // namespace indoormap::cloud_io
