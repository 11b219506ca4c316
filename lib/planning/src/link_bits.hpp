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
/// [-pad_r, height + pad_r) can be read without bounds checks (outside the map: zero).
class BitRows {
 public:
  BitRows() = default;
  BitRows(int width, int height, int pad_c, int pad_r)
      : pad_c_(pad_c),
        pad_r_(pad_r),
        words_(static_cast<std::size_t>((width + 2 * pad_c + 63) / 64 + 1)),
        bits_(words_ * static_cast<std::size_t>(height + 2 * pad_r), 0) {}

  void set(int c, int r) {
    const auto p = bit(c, r);
    bits_[p >> 6] |= std::uint64_t{1} << (p & 63);
  }
  void reset(int c, int r) {
    const auto p = bit(c, r);
    bits_[p >> 6] &= ~(std::uint64_t{1} << (p & 63));
  }
  /// Bit b: cell (c + b, r).
  std::uint64_t window(int c, int r) const {
    const auto p = bit(c, r);
    const std::uint64_t* q = &bits_[p >> 6];
    const unsigned s = p & 63;
    return s == 0 ? q[0] : (q[0] >> s) | (q[1] << (64 - s));
  }
  /// Clears cell (c + b, r) for every set bit b of `mask`.
  void clear_window(int c, int r, std::uint64_t mask) {
    const auto p = bit(c, r);
    std::uint64_t* q = &bits_[p >> 6];
    const unsigned s = p & 63;
    q[0] &= ~(mask << s);
    if (s != 0) q[1] &= ~(mask >> (64 - s));
  }

 private:
  std::size_t bit(int c, int r) const {
    return static_cast<std::size_t>(r + pad_r_) * words_ * 64 +
           static_cast<std::size_t>(c + pad_c_);
  }
  int pad_c_ = 0, pad_r_ = 0;
  std::size_t words_ = 0;
  std::vector<std::uint64_t> bits_;
};

}  // namespace indoormap::planning::detail
