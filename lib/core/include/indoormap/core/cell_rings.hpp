#pragma once
// Exact outlines of a set of grid cells, along the cells' edges.
//
// The rings follow the cell edges between member and non-member cells, so the polygons of two
// areas share their borders exactly: no overlap, no gap, and each polygon covers exactly its
// cells. Two member cells that touch only at a corner are not joined there (4-connectivity): the
// ring turns around each cell's corner, and that vertex, which the rings would visit twice, is
// moved by pinch_offset cells into the cell it turns around, so every ring is simple and no two
// rings touch.
#include <vector>

#include "indoormap/core/polygon.hpp"

namespace indoormap {

/// A ring in continuous cell coordinates (GridGeometry::to_cell_coords: (0, 0) is the lower-left
/// corner of cell (0, 0)); no closing vertex, no collinear vertices.
using CellRing = Polygon;

struct CellRings {
  std::vector<CellRing> outer;  ///< counter-clockwise: member cells on the left
  std::vector<CellRing> holes;  ///< clockwise: member cells on the left
};

/// The rings around the cells where member(col, row) is true, inside the box [col0, col0 + w) x
/// [row0, row0 + h); cells outside the box are non-members.
template <class Member>
CellRings trace_cell_rings(int col0, int row0, int w, int h, const Member& member);

/// Implementation on a mask of w x h bytes (row-major, row 0 first), offset by (col0, row0).
CellRings trace_mask_rings(const std::vector<unsigned char>& mask, int col0, int row0, int w, int h,
                           double pinch_offset = 0.01);

template <class Member>
CellRings trace_cell_rings(int col0, int row0, int w, int h, const Member& member) {
  std::vector<unsigned char> mask(static_cast<std::size_t>(w) * h, 0);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      mask[static_cast<std::size_t>(r) * w + c] = member(col0 + c, row0 + r);
  return trace_mask_rings(mask, col0, row0, w, h);
}

}  // namespace indoormap
