#pragma once
// Internal to im_planning (link_layers.cpp): a grid of cells as padded rows of bits, read and
// cleared 64 cells at a time at any column, for the bit-parallel template walk of the layered
// search.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace indoormap::planning::detail {

/// Cells (c, r) of a width x height map, one bit each, with margins of zero bits so that a window
/// of 64 cells starting at any column in [-pad_c, width + pad_c - 64] and any row in
/// [-pad_r, height + pad_r) can be read without bounds checks (outside the map: zero). Stored by
/// word columns (the words of one column of 64 cells, row after row), so that the windows of
/// consecutive rows at one column are consecutive words (column()).
class BitRows {
 public:
  BitRows() = default;
  BitRows(int width, int height, int pad_c, int pad_r)
      : pad_c_(pad_c),
        pad_r_(pad_r),
        rows_(static_cast<std::size_t>(height + 2 * pad_r)),
        bits_(rows_ * static_cast<std::size_t>((width + 2 * pad_c + 63) / 64 + 1), 0) {}

  /// The windows at column c of rows r, r + 1, ...: window(c, r + j) is
  /// (a[j] >> s) | (b[j] << (64 - s)) when s > 0, else a[j].
  struct Column {
    const std::uint64_t *a, *b;
    unsigned s;
  };
  Column column(int c, int r) const {
    const auto p = static_cast<std::size_t>(c + pad_c_);
    const std::uint64_t* a = &bits_[(p >> 6) * rows_ + static_cast<std::size_t>(r + pad_r_)];
    return {a, a + rows_, static_cast<unsigned>(p & 63)};
  }

  void set(int c, int r) {
    const auto p = static_cast<std::size_t>(c + pad_c_);
    bits_[word(p, r)] |= std::uint64_t{1} << (p & 63);
  }
  void reset(int c, int r) {
    const auto p = static_cast<std::size_t>(c + pad_c_);
    bits_[word(p, r)] &= ~(std::uint64_t{1} << (p & 63));
  }
  /// Bit b: cell (c + b, r).
  std::uint64_t window(int c, int r) const {
    const auto [a, b, s] = column(c, r);
    return s == 0 ? a[0] : (a[0] >> s) | (b[0] << (64 - s));
  }
  /// Clears cell (c + b, r) for every set bit b of `mask`.
  void clear_window(int c, int r, std::uint64_t mask) {
    const auto p = static_cast<std::size_t>(c + pad_c_);
    const unsigned s = p & 63;
    bits_[word(p, r)] &= ~(mask << s);
    if (s != 0) bits_[word(p + 64, r)] &= ~(mask >> (64 - s));
  }

 private:
  /// The word holding padded bit column p of row r.
  std::size_t word(std::size_t p, int r) const {
    return (p >> 6) * rows_ + static_cast<std::size_t>(r + pad_r_);
  }
  int pad_c_ = 0, pad_r_ = 0;
  std::size_t rows_ = 0;
  std::vector<std::uint64_t> bits_;
};

}  // namespace indoormap::planning::detail
