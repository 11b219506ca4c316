#pragma once
// Bresenham's line between two cells: the cells a beam passes, 8-connected, both ends included.
#include <cstdlib>
#include <vector>

#include "indoormap/core/grid.hpp"

namespace indoormap::laser {

/// Visits the cells of the Bresenham line from a to b in order, a and b included:
/// max(|dx|, |dy|) + 1 cells, each within half a cell of the straight line between the centres
/// along the minor axis. visit(CellIndex) returns false to stop early. Coordinates must fit in
/// +-2^30 (GridGeometry::cell_of saturates there), so the error term never overflows.
template <class Visit>
void bresenham(CellIndex a, CellIndex b, Visit&& visit) {
  const long long dx = std::llabs(static_cast<long long>(b.col) - a.col);
  const long long dy = -std::llabs(static_cast<long long>(b.row) - a.row);
  const int sx = a.col < b.col ? 1 : -1, sy = a.row < b.row ? 1 : -1;
  long long err = dx + dy;
  CellIndex c = a;
  while (true) {
    if (!visit(c)) return;
    if (c == b) return;
    const long long e2 = 2 * err;
    if (e2 >= dy) {
      err += dy;
      c.col += sx;
    }
    if (e2 <= dx) {
      err += dx;
      c.row += sy;
    }
  }
}

/// The cells of bresenham(a, b) as a list.
inline std::vector<CellIndex> bresenham_line(CellIndex a, CellIndex b) {
  std::vector<CellIndex> out;
  bresenham(a, b, [&](CellIndex c) {
    out.push_back(c);
    return true;
  });
  return out;
}

}  // namespace indoormap::laser
