#include "indoormap/formats/pgm.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>
#include <vector>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/core/input_file.hpp"

namespace indoormap::formats {

namespace fs = std::filesystem;

void write_pgm(const fs::path& path, const Grid<std::uint8_t>& grid) {
  std::string bytes =
      "P5\n" + std::to_string(grid.width) + " " + std::to_string(grid.height) + "\n255\n";
  const std::size_t header = bytes.size();
  bytes.resize(header + grid.size());
  for (int r = 0; r < grid.height; ++r) {
    const std::size_t dst = header + static_cast<std::size_t>(grid.height - 1 - r) * grid.width;
    std::copy_n(grid.data.begin() + static_cast<std::ptrdiff_t>(r) * grid.width, grid.width,
                bytes.begin() + static_cast<std::ptrdiff_t>(dst));
  }
  write_file_atomic(path, bytes);
}

void write_layout_pgm(const fs::path& path, const Grid<Cell>& layout) {
  Grid<std::uint8_t> raw(layout.width, layout.height);
  for (std::size_t i = 0; i < raw.size(); ++i)
    raw.data[i] = static_cast<std::uint8_t>(layout.data[i]);
  write_pgm(path, raw);
}

Grid<std::uint8_t> read_pgm(const fs::path& path, bool flip) {
  // A directory would read as an empty file, a FIFO would block in open().
  std::ifstream in = open_input_file(path, kNoSizeLimit, "a PGM file");
  // The magic number is two bytes followed by whitespace or a comment (not read as a
  // whitespace-delimited token: that could be as long as the file).
  char magic[2] = {};
  in.read(magic, 2);
  const auto got = in.gcount();  // before peek(), which resets it
  const int after = in.peek();
  const bool ascii = got == 2 && magic[1] == '2';
  if (got < 2 || magic[0] != 'P' || !(magic[1] == '5' || magic[1] == '2') ||
      !(after == '#' || (after != EOF && std::isspace(after))))
    throw InputError(path.string(), "not a PGM (P5 or P2) file");
  long long vals[3];
  for (auto& v : vals) {
    in >> std::ws;
    while (in.peek() == '#') {
      std::string comment;
      std::getline(in, comment);
      in >> std::ws;
    }
    if (!(in >> v)) throw InputError(path.string(), "bad PGM header");
  }
  const long long w = vals[0], h = vals[1], maxval = vals[2];
  if (w <= 0 || h <= 0 || w > 100000 || h > 100000 || w * h > 400'000'000LL)
    throw InputError(path.string(),
                     "PGM size " + std::to_string(w) + " x " + std::to_string(h) + " out of range");
  if (maxval <= 0 || maxval > 65535)
    throw InputError(path.string(), "PGM maxval " + std::to_string(maxval) + " out of 1..65535");
  in.get();  // the single whitespace after maxval
  // The pixels must be in the file before the grid is allocated for them: P5 has one or two
  // bytes per pixel, P2 at least a digit and a separator.
  const long long per_pixel = ascii || maxval > 255 ? 2 : 1;
  const auto data_start = static_cast<long long>(in.tellg());
  std::error_code ec;
  const auto file_size = static_cast<long long>(fs::file_size(path, ec));
  const long long present = !in || ec || data_start < 0 ? 0 : std::max(0LL, file_size - data_start);
  if (present + ascii < w * h * per_pixel)
    throw InputError(path.string(), "PGM data truncated: " + std::to_string(w) + " x " +
                                        std::to_string(h) + " pixels need " +
                                        std::to_string(w * h * per_pixel - ascii) +
                                        " bytes, the file holds " + std::to_string(present));
  // Values other than 0..255 are scaled to it (a 16-bit or a 4-bit map image).
  const auto to8 = [&](long long v) {
    return static_cast<std::uint8_t>(
        maxval == 255 ? v : (std::min(v, maxval) * 255 + maxval / 2) / maxval);
  };
  Grid<std::uint8_t> g(static_cast<int>(w), static_cast<int>(h));
  std::vector<unsigned char> row(static_cast<std::size_t>(w * per_pixel));
  for (long long r = 0; r < h; ++r) {
    const int gr = flip ? static_cast<int>(h - 1 - r) : static_cast<int>(r);
    if (!ascii && !in.read(reinterpret_cast<char*>(row.data()), w * per_pixel))
      throw InputError(path.string(), "PGM data truncated");
    for (long long c = 0; c < w; ++c) {
      long long v = 0;
      if (ascii) {
        if (!(in >> v) || v < 0) throw InputError(path.string(), "bad PGM pixel value");
      } else {
        v = per_pixel == 2 ? (row[2 * c] << 8 | row[2 * c + 1]) : row[c];
      }
      g.at(static_cast<int>(c), gr) = to8(v);
    }
  }
  return g;
}

Grid<Cell> read_layout_pgm(const fs::path& path, const GridGeometry& expected) {
  const Grid<std::uint8_t> raw = read_pgm(path, true);
  if (expected.width() > 0 && (raw.width != expected.width() || raw.height != expected.height()))
    throw InputError(path.string(), "image is " + std::to_string(raw.width) + " x " +
                                        std::to_string(raw.height) + " but " +
                                        std::to_string(expected.width()) + " x " +
                                        std::to_string(expected.height()) + " was expected");
  Grid<Cell> out(raw.width, raw.height);
  for (std::size_t i = 0; i < raw.data.size(); ++i) {
    if (raw.data[i] > 3)
      throw InputError(path.string(),
                       "pixel value " + std::to_string(raw.data[i]) +
                           " is not a layout class 0..3 (is this map.pgm instead of layout.pgm?)");
    out.data[i] = static_cast<Cell>(raw.data[i]);
  }
  return out;
}

}  // namespace indoormap::formats
