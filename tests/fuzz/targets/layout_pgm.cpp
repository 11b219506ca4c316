// map-eval's layout image (RESULT_DIR/layout.pgm, and the truth layout named by
// ground_truth.json), the way map-eval reads it: read_pgm, then read_layout_pgm against the
// geometry of the result (same size) and against a truth geometry of another size (refused).
#include <stdexcept>

#include "fuzz_target.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/formats/pgm.hpp"

INDOORMAP_FUZZ_TARGET(layout_pgm) {
  using namespace indoormap;
  const auto file = fuzz::write_file(fuzz::fresh_dir(), "layout.pgm", bytes);
  const Grid<std::uint8_t> raw = formats::read_pgm(file);
  if (raw.width <= 0 || raw.height <= 0 ||
      raw.size() != static_cast<std::size_t>(raw.width) * static_cast<std::size_t>(raw.height))
    throw std::logic_error("read_pgm returned a grid inconsistent with its size");
  const GridGeometry rg({-1.0, 2.0}, 0.05, raw.width, raw.height);
  const Grid<Cell> layout = formats::read_layout_pgm(file, rg);
  if (layout.width != raw.width || layout.height != raw.height)
    throw std::logic_error("read_layout_pgm returned another size than read_pgm");
  for (const Cell c : layout.data)
    if (static_cast<int>(c) > 3) throw std::logic_error("layout cell outside 0..3");
  try {
    (void)formats::read_layout_pgm(file, GridGeometry({0.0, 0.0}, 0.05, raw.width, raw.height + 1));
  } catch (const InputError&) {
    return;
  }
  throw std::logic_error("read_layout_pgm accepted an image of the wrong size");
}
