#pragma once
// Named cell classes of the room layout M_r (paper, section 3.2.A). The numeric values are the
// paper's and are what layout.pgm stores raw, so they are part of the file format.
#include <cstdint>
#include <string_view>

namespace indoormap {

enum class Cell : std::uint8_t {
  kUnknown = 0,    ///< virgin area: never observed, or outside the room
  kWall = 1,       ///< wall border (obstacle in the wall band)
  kFurniture = 2,  ///< interior object (obstacle in the furniture band, or enclosed by one)
  kFree = 3,       ///< free space reachable from a scanner position
};

inline constexpr std::string_view to_string(Cell c) {
  switch (c) {
    case Cell::kUnknown: return "unknown";
    case Cell::kWall: return "wall";
    case Cell::kFurniture: return "furniture";
    case Cell::kFree: return "free";
  }
  return "invalid";
}

}  // namespace indoormap
