#pragma once
// Shared fixtures of the test_objects_*.cpp files: flat layers and hand-filled voxel grids.
#include <gtest/gtest.h>

#include <map>
#include <opencv2/imgproc.hpp>
#include <random>
#include <set>

#include "indoormap/core/errors.hpp"
#include "indoormap/objects/objects.hpp"

using namespace indoormap;
using namespace indoormap::objects;

namespace objects_fixtures {

// Floor at layer 0, ceiling far above, wall band out of reach: heights as drawn.
inline cloud::LayerAnalysis flat_layers() {
  cloud::LayerAnalysis a;
  a.floor_layer = 0;
  a.ceiling_layer = 1000;
  a.wall_band.lo_layer = 999;
  a.wall_band.hi_layer = 1000;
  return a;
}

// Voxel grid of w x h columns, cell 0.05 m, floor layer 0 (z in [0, 0.05)), nz layers.
inline cloud::VoxelGrid voxels(int w, int h, int nz) {
  cloud::VoxelGrid g;
  g.cell_m = 0.05;
  g.nx = w;
  g.ny = h;
  g.nz = nz;
  g.counts.assign(static_cast<std::size_t>(w) * h * nz, 0);
  return g;
}
// A layout of w x h free cells with walls on its border.
inline Grid<Cell> walled_room(int w, int h) {
  Grid<Cell> L(w, h, Cell::kFree);
  for (int c = 0; c < w; ++c) L.at(c, 0) = L.at(c, h - 1) = Cell::kWall;
  for (int r = 0; r < h; ++r) L.at(0, r) = L.at(w - 1, r) = Cell::kWall;
  return L;
}

inline void fill_column(cloud::VoxelGrid& g, int c, int r, double z0, double z1,
                        std::uint16_t n = 2) {
  for (std::int64_t z = static_cast<std::int64_t>(z0 / g.cell_m);
       z < static_cast<std::int64_t>(z1 / g.cell_m); ++z)
    g.counts[(z * g.ny + r) * g.nx + c] = n;
}

// Furniture cells c0..c1 x r0..r1 in the layout, each column filled from the floor to `top`.
inline void put_block(Grid<Cell>& L, cloud::VoxelGrid& g, int c0, int c1, int r0, int r1,
                      double top) {
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      L.at(c, r) = Cell::kFurniture;
      fill_column(g, c, r, 0.0, top);
    }
}

}  // namespace objects_fixtures
