#pragma once
// Shared helpers of the test_layout*.cpp files: grids drawn as text pictures.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "indoormap/layout/layout.hpp"

using namespace indoormap;
using namespace indoormap::layout;

namespace layout_fixtures {

// Parses a picture: '#' = 1, anything else 0. The first text line is the TOP row (highest y),
// as printed; grid row 0 is the bottom line.
inline Grid<std::uint8_t> parse(const std::vector<std::string>& rows, char mark = '#') {
  const int h = static_cast<int>(rows.size()), w = static_cast<int>(rows[0].size());
  Grid<std::uint8_t> g(w, h, 0);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) g.at(c, h - 1 - r) = rows[r][c] == mark;
  return g;
}

inline std::string render(const Grid<Cell>& g) {
  std::string s;
  for (int r = g.height - 1; r >= 0; --r) {
    for (int c = 0; c < g.width; ++c) s += " WF."[static_cast<int>(g.at(c, r))];
    s += '\n';
  }
  return s;
}

// A 0/1 grid as parse() reads it: '#' = 1, '.' = 0, top row first.
inline std::string render01(const Grid<std::uint8_t>& g) {
  std::string s;
  for (int r = g.height - 1; r >= 0; --r) {
    for (int c = 0; c < g.width; ++c) s += g.at(c, r) ? '#' : '.';
    s += '\n';
  }
  return s;
}

inline GridGeometry geo_for(const Grid<std::uint8_t>& g) {
  return GridGeometry({0.0, 0.0}, 1.0, g.width, g.height);
}

}  // namespace layout_fixtures

using namespace layout_fixtures;
