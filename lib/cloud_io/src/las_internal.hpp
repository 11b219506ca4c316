#pragma once
// Private to im_cloud_io: little-endian field access for the LAS reader and writer.
#include <cstdint>
#include <cstring>
#include <string>

namespace indoormap::cloud_io::detail {

inline std::uint16_t las_u16(const unsigned char* p) {
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
inline std::uint32_t las_u32(const unsigned char* p) {
  return std::uint32_t{p[0]} | (std::uint32_t{p[1]} << 8) | (std::uint32_t{p[2]} << 16) |
         (std::uint32_t{p[3]} << 24);
}
inline std::uint64_t las_u64(const unsigned char* p) {
  return std::uint64_t{las_u32(p)} | (std::uint64_t{las_u32(p + 4)} << 32);
}
inline std::int32_t las_i32(const unsigned char* p) {
  return static_cast<std::int32_t>(las_u32(p));
}
inline double las_f64(const unsigned char* p) {
  const std::uint64_t u = las_u64(p);
  double d;
  std::memcpy(&d, &u, sizeof d);
  return d;
}

/// The conversion advice for compressed clouds (LAZ), shared by the messages that need it.
std::string las_laz_hint();

}  // namespace indoormap::cloud_io::detail
