#pragma once
// PGM files of raw grid values (8-bit binary, P5), writer and reader side by side; the layout PGM
// (layout.pgm, ground_truth_layout.pgm) holds the Cell values 0..3. Images are north up: image
// row 0 holds grid row height-1 (the highest y).
#include <cstdint>
#include <filesystem>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::formats {

/// Writes a P5 PGM of the raw values (north up), atomically.
void write_pgm(const std::filesystem::path& path, const Grid<std::uint8_t>& grid);
/// Reads a PGM, binary (P5) or plain (P2), maxval up to 65535: values as they are when maxval is
/// 255, else scaled to 0..255 (a 16-bit map image); flip_rows_to_y_up: image row 0 becomes grid
/// row height-1. Throws InputError naming the file; the pixels must be in the file before the
/// grid is allocated (at most 100,000 x 100,000 and 4 x 10^8 pixels).
Grid<std::uint8_t> read_pgm(const std::filesystem::path& path, bool flip_rows_to_y_up = true);

/// The layout as a PGM of its Cell values (0 unknown, 1 wall, 2 furniture, 3 free).
void write_layout_pgm(const std::filesystem::path& path, const Grid<Cell>& layout);
/// Reads a layout PGM (values must be 0..3). expected: when its width is > 0, the image must
/// have its size. Throws InputError naming the file.
Grid<Cell> read_layout_pgm(const std::filesystem::path& path, const GridGeometry& expected);

}  // namespace indoormap::formats
