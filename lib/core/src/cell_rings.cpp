// Crack following: every edge between a member and a non-member cell, directed with the member
// on its left, linked at each vertex into closed rings.
#include "indoormap/core/cell_rings.hpp"

#include <array>
#include <bit>
#include <cstdint>

namespace indoormap {
namespace {

// Directions: 0 +x, 1 +y, 2 -x, 3 -y (counter-clockwise order: left of d is (d + 1) % 4).
constexpr std::array<int, 4> kDx = {1, 0, -1, 0};
constexpr std::array<int, 4> kDy = {0, 1, 0, -1};

struct Tracer {
  const std::vector<unsigned char>& mask;
  int w, h;
  // Per vertex (x, y) in [0, w] x [0, h]: bit d set when an edge leaves it in direction d;
  // a second bit set for it once traced.
  std::vector<std::uint8_t> out, done;

  bool in(int c, int r) const {
    return c >= 0 && r >= 0 && c < w && r < h && mask[static_cast<std::size_t>(r) * w + c];
  }
  std::size_t v(int x, int y) const { return static_cast<std::size_t>(y) * (w + 1) + x; }

  void collect_edges() {
    out.assign(static_cast<std::size_t>(w + 1) * (h + 1), 0);
    done = out;
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) {
        if (!in(c, r)) continue;
        // Counter-clockwise around the cell: bottom, right, top, left edges where the neighbour
        // across is not a member.
        if (!in(c, r - 1)) out[v(c, r)] |= 1 << 0;
        if (!in(c + 1, r)) out[v(c + 1, r)] |= 1 << 1;
        if (!in(c, r + 1)) out[v(c + 1, r + 1)] |= 1 << 2;
        if (!in(c - 1, r)) out[v(c, r + 1)] |= 1 << 3;
      }
  }

  /// The ring's vertex where it turns from d_in to d_out at (x, y); at a pinch (two edges leave
  /// the vertex) moved into the cell the ring turns around.
  Eigen::Vector2d corner(int x, int y, int d_in, int d_out, int col0, int row0,
                         double pinch) const {
    Eigen::Vector2d p(x + col0, y + row0);
    if (std::popcount(out[v(x, y)]) == 2)
      p += pinch * Eigen::Vector2d(kDx[d_out] - kDx[d_in], kDy[d_out] - kDy[d_in]);
    return p;
  }

  /// The ring starting with the edge leaving (x, y) in direction d.
  CellRing trace(int x, int y, int d, int col0, int row0, double pinch) {
    CellRing ring;
    const int x0 = x, y0 = y, d0 = d;
    int d_in = -1;
    do {
      done[v(x, y)] |= static_cast<std::uint8_t>(1 << d);
      if (d_in >= 0 && d != d_in) ring.push_back(corner(x, y, d_in, d, col0, row0, pinch));
      x += kDx[d];
      y += kDy[d];
      d_in = d;
      // Leave by the left turn if there is one (turning around the member cell's corner),
      // then straight on, then right; a back turn is impossible on a member boundary.
      const std::uint8_t o = out[v(x, y)];
      for (int turn : {1, 0, 3})
        if (o & (1 << ((d_in + turn) % 4))) {
          d = (d_in + turn) % 4;
          break;
        }
    } while (!(x == x0 && y == y0 && d == d0));
    if (d != d_in) ring.insert(ring.begin(), corner(x0, y0, d_in, d, col0, row0, pinch));
    return ring;
  }
};

}  // namespace

CellRings trace_mask_rings(const std::vector<unsigned char>& mask, int col0, int row0, int w, int h,
                           double pinch_offset) {
  Tracer t{mask, w, h, {}, {}};
  t.collect_edges();
  CellRings rings;
  for (int y = 0; y <= h; ++y)
    for (int x = 0; x <= w; ++x)
      for (int d = 0; d < 4; ++d) {
        const std::size_t i = t.v(x, y);
        if (!(t.out[i] & (1 << d)) || (t.done[i] & (1 << d))) continue;
        CellRing ring = t.trace(x, y, d, col0, row0, pinch_offset);
        (signed_area(ring) > 0.0 ? rings.outer : rings.holes).push_back(std::move(ring));
      }
  return rings;
}

}  // namespace indoormap
