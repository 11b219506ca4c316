#pragma once
// Shared fixtures of the map-reading tests (test_formats.cpp, test_robustness.cpp): small map
// image files built in memory.
#include <cstdint>
#include <string>

namespace map_fixtures {

/// A valid 2 x 2 binary PGM (P5, maxval 255).
inline const std::string kPgm = "P5\n2 2\n255\n" + std::string("\0\xfe\xcd\0", 4);

/// The signature and IHDR chunk of a w x h 8-bit grey PNG, with no image data after it.
inline std::string png_header(std::uint32_t w, std::uint32_t h) {
  std::string s("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
  for (std::uint32_t v : {w, h})
    for (int sh = 24; sh >= 0; sh -= 8) s += static_cast<char>((v >> sh) & 0xff);
  return s + std::string("\x08\0\0\0\0", 5) + std::string(8, '\0');
}

}  // namespace map_fixtures
