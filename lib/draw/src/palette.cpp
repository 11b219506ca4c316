#include "indoormap/draw/palette.hpp"

#include <array>

namespace indoormap::draw {

namespace {

using Bgr = std::array<double, 3>;
// Indexed by [set][Cell value]: unknown, wall, furniture, free.
constexpr std::array<std::array<Bgr, 4>, 2> kCellBgr = {{
    {{{170, 170, 170}, {100, 40, 20}, {0, 140, 255}, {255, 255, 255}}},  // kMap
    {{{128, 128, 128}, {40, 40, 40}, {40, 120, 230}, {255, 255, 255}}},  // kTruth
}};

}  // namespace

cv::Scalar cell_colour(Cell c, CellColours set) {
  const auto v = static_cast<std::size_t>(c);
  if (v >= 4) return {255, 0, 255};
  const Bgr& bgr = kCellBgr[static_cast<std::size_t>(set)][v];
  return {bgr[0], bgr[1], bgr[2]};
}

}  // namespace indoormap::draw
