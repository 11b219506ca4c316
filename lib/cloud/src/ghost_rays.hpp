#pragma once
// The rays of one scanner position, indexed by direction, for the ghost filter: which rays pass
// through a given voxel, found by looking only at the rays whose direction falls in the voxel's
// angular footprint, so that the cost does not grow with the length of the rays.
//
// Directions are binned by two pseudo-angles, each monotone in the true angle, so a box's range
// is the range over its corners and no trigonometry is needed: the diamond angle of (dx, dy) in
// [0, 4) for the azimuth, and q = dz / (r + |dz|) in (-1, 1), r = |(dx, dy)|, for the elevation.
// The bin edges are quantiles of the rays' own values (from a sample), so that bins hold about
// the same number of rays however the directions spread: a scanner far outside the cloud, whose
// rays all point one way, does not put every ray into one bin.
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "indoormap/cloud/voxel.hpp"

namespace indoormap::cloud::detail {

class RayFan {
 public:
  /// Every stride-th point of `points` (grid frame) as a ray from `scanner` (grid frame), with
  /// its last skip_cells left out; rays whose end lies outside the grid, or shorter than the
  /// skip, are dropped (as the traversal did).
  RayFan(const VoxelGrid& g, std::span<const Eigen::Vector3f> points,
         const Eigen::Vector3d& scanner, std::size_t stride, double skip_cells);
  std::size_t size() const { return rays_.size(); }
  /// The rays whose kept stretch passes through voxel (ix, iy, iz) and that end at least
  /// min_layer_offset layers above or below it, or (far_end_cells > 0) whose end lies at least
  /// far_end_cells from the voxel's centre, counted up to cap.
  int passes(std::int64_t ix, std::int64_t iy, std::int64_t iz, int min_layer_offset,
             double far_end_cells, int cap) const;

 private:
  /// 16 bytes: the index is scanned in bin order, and float keeps 1e-4 voxel at 2000 voxels.
  struct Ray {
    Eigen::Vector3f
        d;  ///< end of the kept stretch - scanner, voxel units: scanner + t d, t in [0, 1]
    std::int32_t end_layer;
  };
  /// Bins of equal shares of some values: bin k holds [edges[k-1], edges[k]). A uniform table
  /// over the values' range narrows each look-up to the few edges inside one table cell.
  class Bins {
   public:
    Bins() = default;
    Bins(std::vector<double> edges, double lo, double hi);
    int of(double v) const;

   private:
    std::vector<double> edges_;
    std::vector<std::uint32_t> table_;  ///< first bin of each table cell; one more at the end
    double lo_ = 0.0, inv_width_ = 0.0;
  };
  int bin_a(double a) const { return a_bins_.of(a); }
  int bin_q(double q) const { return q_bins_.of(q); }
  Eigen::Vector3d s_;  ///< the scanner, voxel coordinates
  double skip_ = 0.0;  ///< the left-out end of every ray, voxel units
  int na_ = 1, nq_ = 1;
  Bins a_bins_, q_bins_;
  std::vector<Ray> rays_;  ///< sorted by bin
  std::vector<std::uint32_t>
      offsets_;  ///< rays of bin (iq * na_ + ia): [offsets_[b], offsets_[b+1])
};

}  // namespace indoormap::cloud::detail
