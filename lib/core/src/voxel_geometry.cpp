#include "indoormap/core/voxel_geometry.hpp"

#include <cmath>

namespace indoormap {

namespace {
// Saturates far-away and non-finite coordinates to an index that is outside every grid (grids
// are far smaller than 2^40 voxels per axis), so the conversion never overflows.
std::int64_t to_voxel_index(double v) {
  constexpr double kLimit = static_cast<double>(std::int64_t{1} << 40);
  if (!(v > -kLimit)) return -(std::int64_t{1} << 40);
  if (!(v < kLimit)) return std::int64_t{1} << 40;
  return static_cast<std::int64_t>(std::floor(v));
}
}  // namespace

VoxelIndex VoxelGeometry::voxel_of(const Eigen::Vector3d& p_m) const {
  return {to_voxel_index((p_m.x() - origin_m.x()) / cell_m),
          to_voxel_index((p_m.y() - origin_m.y()) / cell_m),
          to_voxel_index((p_m.z() - origin_m.z()) / cell_m)};
}

std::int64_t VoxelGeometry::layer_of(double z_m) const {
  return to_voxel_index(to_layer_coord(z_m));
}

GridGeometry VoxelGeometry::geometry2d() const {
  return GridGeometry({origin_m.x(), origin_m.y()}, cell_m, static_cast<int>(nx),
                      static_cast<int>(ny));
}

}  // namespace indoormap
