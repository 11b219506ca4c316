#pragma once
// Small hand-built voxel grids for the navigation map's tests (test_nav_map.cpp,
// test_nav_rays.cpp).
#include <cstdint>

#include "indoormap/cloud/voxel.hpp"
#include "indoormap/layout/nav_map.hpp"

namespace indoormap::test {

// nx x ny cells of cell_m, 30 layers; by default 40 x 20 cells of 0.1 m, floor at z 0.05
// (layer 0).
inline cloud::VoxelGrid room(double cell_m = 0.1, int nx = 40, int ny = 20) {
  cloud::VoxelGrid g;
  g.cell_m = cell_m;
  g.nx = nx;
  g.ny = ny;
  g.nz = 30;
  g.counts.assign(static_cast<std::size_t>(g.voxel_count()), 0);
  return g;
}

inline void put(cloud::VoxelGrid& g, int x, int y, int z, std::uint16_t n = 5) {
  g.counts[static_cast<std::size_t>(g.index(x, y, z))] = n;
}

// room() with its whole floor seen (a point in layer 0 of every column).
inline cloud::VoxelGrid room_with_seen_floor(double cell_m, int nx, int ny) {
  cloud::VoxelGrid g = room(cell_m, nx, ny);
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) put(g, x, y, 0);
  return g;
}

inline Cell at(const layout::NavResult& r, int c, int row) {
  return r.map.at(c, row);
}

}  // namespace indoormap::test
