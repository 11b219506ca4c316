#pragma once
// 3D voxel grid geometry: the one place that owns the world <-> voxel conversion, as GridGeometry
// does in 2D. No algorithm recomputes floor((p - origin) / cell) or the voxel index by itself.
//
// Conventions: voxel (ix, iy, iz) covers [origin + i * cell_m, + cell_m) per axis; layer iz is
// the horizontal slice of voxels with that iz, layer 0 the lowest. The voxels are stored layer
// by layer, rows of x: index(ix, iy, iz) = (iz * ny + iy) * nx + ix.
#include <Eigen/Core>
#include <cstdint>

#include "indoormap/core/grid.hpp"

namespace indoormap {

struct VoxelIndex {
  std::int64_t ix = 0;
  std::int64_t iy = 0;
  std::int64_t iz = 0;
  friend bool operator==(const VoxelIndex&, const VoxelIndex&) = default;
};

struct VoxelGeometry {
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();  ///< map-frame corner of voxel (0, 0, 0)
  double cell_m = 0.05;                                ///< voxel edge
  std::int64_t nx = 0, ny = 0, nz = 0;

  std::int64_t layer_size() const { return nx * ny; }
  std::int64_t voxel_count() const { return nx * ny * nz; }
  /// Storage index of a voxel inside the grid: (iz * ny + iy) * nx + ix.
  std::int64_t index(std::int64_t ix, std::int64_t iy, std::int64_t iz) const {
    return (iz * ny + iy) * nx + ix;
  }
  std::int64_t index(const VoxelIndex& v) const { return index(v.ix, v.iy, v.iz); }
  bool contains(std::int64_t ix, std::int64_t iy, std::int64_t iz) const {
    return ix >= 0 && iy >= 0 && iz >= 0 && ix < nx && iy < ny && iz < nz;
  }
  bool contains(const VoxelIndex& v) const { return contains(v.ix, v.iy, v.iz); }

  /// Continuous voxel coordinates of a map-frame point: (0, 0, 0) is the corner of voxel
  /// (0, 0, 0), (0.5, 0.5, 0.5) its centre; voxel_of(p) == floor(to_voxel_coords(p)).
  Eigen::Vector3d to_voxel_coords(const Eigen::Vector3d& p_m) const {
    return (p_m - origin_m) / cell_m;
  }
  /// Continuous layer coordinate of a map-frame height (the z of to_voxel_coords).
  double to_layer_coord(double z_m) const { return (z_m - origin_m.z()) / cell_m; }
  /// A length in metres as a (fractional) number of voxels.
  double to_cells(double length_m) const { return length_m / cell_m; }

  /// Voxel containing a map-frame point (may lie outside the grid; check contains()). Far-away
  /// and non-finite coordinates saturate to an index outside every grid.
  VoxelIndex voxel_of(const Eigen::Vector3d& p_m) const;
  /// Layer containing a map-frame height (may lie outside the grid), saturating like voxel_of.
  std::int64_t layer_of(double z_m) const;

  /// Map-frame height of the bottom / the centre of layer iz.
  double layer_bottom_m(std::int64_t iz) const { return origin_m.z() + iz * cell_m; }
  double layer_center_m(std::int64_t iz) const { return origin_m.z() + (iz + 0.5) * cell_m; }
  /// The 2D grid of one layer (x, y) in map metres.
  GridGeometry geometry2d() const;

  friend bool operator==(const VoxelGeometry&, const VoxelGeometry&) = default;
};

/// The voxelisation's own binning, in float arithmetic for its hot loop: one multiply-add per
/// axis and a range check that also rejects NaN. At a voxel boundary it may differ from the
/// double-precision voxel_of by one voxel; every count of a VoxelGrid comes from this one.
class VoxelBinner {
 public:
  explicit VoxelBinner(const VoxelGeometry& g)
      : inv_(static_cast<float>(1.0 / g.cell_m)),
        ox_(static_cast<float>(g.origin_m.x())),
        oy_(static_cast<float>(g.origin_m.y())),
        oz_(static_cast<float>(g.origin_m.z())),
        fnx_(static_cast<float>(g.nx)),
        fny_(static_cast<float>(g.ny)),
        fnz_(static_cast<float>(g.nz)),
        nx_(g.nx),
        nxy_(g.nx * g.ny) {}

  /// Storage index of the voxel holding p, or -1 when p lies outside the grid or is not finite.
  std::int64_t index_of(const Eigen::Vector3f& p) const {
    const float fx = (p.x() - ox_) * inv_, fy = (p.y() - oy_) * inv_, fz = (p.z() - oz_) * inv_;
    if (!(fx >= 0.f && fx < fnx_ && fy >= 0.f && fy < fny_ && fz >= 0.f && fz < fnz_)) return -1;
    return static_cast<std::int64_t>(fz) * nxy_ + static_cast<std::int64_t>(fy) * nx_ +
           static_cast<std::int64_t>(fx);
  }

 private:
  float inv_, ox_, oy_, oz_, fnx_, fny_, fnz_;
  std::int64_t nx_, nxy_;
};

}  // namespace indoormap
