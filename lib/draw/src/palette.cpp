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

// Indexed by ObjectKind: furniture, hanging, lamp, pillar, column, installation. Chosen for a
// large smallest pairwise CIEDE2000 distance (32.0, lamp - column) with every colour 27 or more
// from the orange, white and grey cells below it and 30 or more from rooms.png's green doors,
// and dark enough for its ids to read on their white halo (contrast with white 3.6 or more,
// WCAG's 3 for large text); furniture keeps its purple.
constexpr std::array<std::array<std::uint8_t, 3>, 6> kKindRgb = {{
    {150, 0, 160},   // furniture: purple
    {15, 135, 240},  // hanging: blue
    {0, 105, 90},    // lamp: dark teal
    {210, 0, 0},     // pillar: red
    {20, 20, 20},    // column: near-black
    {135, 105, 15},  // installation: olive
}};

}  // namespace

std::array<std::uint8_t, 3> kind_rgb(ObjectKind kind) {
  const auto v = static_cast<std::size_t>(kind);
  return v < kKindRgb.size() ? kKindRgb[v] : std::array<std::uint8_t, 3>{255, 0, 255};
}

cv::Scalar kind_colour(ObjectKind kind) {
  const auto rgb = kind_rgb(kind);
  return {static_cast<double>(rgb[2]), static_cast<double>(rgb[1]), static_cast<double>(rgb[0])};
}

cv::Scalar cell_colour(Cell c, CellColours set) {
  const auto v = static_cast<std::size_t>(c);
  if (v >= 4) return {255, 0, 255};
  const Bgr& bgr = kCellBgr[static_cast<std::size_t>(set)][v];
  return {bgr[0], bgr[1], bgr[2]};
}

}  // namespace indoormap::draw
