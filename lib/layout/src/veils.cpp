// Furniture-band columns the navigation map calls free over seen floor (docs/pipeline.md, step 5,
// "Veils of mixed pixels in the furniture band").
#include "indoormap/layout/layout.hpp"

namespace indoormap::layout {

Grid<std::uint8_t> without_veils(const Grid<std::uint8_t>& furniture,
                                 const Grid<std::uint8_t>& walls, const Grid<Cell>& nav,
                                 const Grid<std::uint8_t>& observed_free, std::int64_t* dropped) {
  Grid<std::uint8_t> out = furniture;
  std::int64_t n = 0;
  if (walls.size() == out.size() && nav.size() == out.size() && observed_free.size() == out.size())
    for (std::size_t i = 0; i < out.size(); ++i)
      if (out.data[i] && !walls.data[i] && nav.data[i] == Cell::kFree && observed_free.data[i])
        out.data[i] = 0, ++n;
  if (dropped) *dropped = n;
  return out;
}

}  // namespace indoormap::layout
