#pragma once
// Rupture and breakpoint detection (Borges and Aldon 2004, as in Barbre 2021 section 2.2): the
// returns of a 2D laser scan as laser-frame points, cut into runs of connected points.
//
// A rupture is a beam without a usable return (no return, zero, non-finite, at or beyond the
// maximum range): the valid points on either side of it are flagged and never joined. A
// breakpoint is a jump between two consecutive returns larger than the adaptive threshold
//   D_max = r_prev * sin(dphi) / sin(lambda - dphi) + 3 sigma_r
// (dphi the angle between the two beams, lambda the most grazing incidence angle at which a
// surface still counts as continuous, sigma_r the range noise).
//
// Frames: points are in the laser frame (the sensor at the origin, x along beam angle 0).
#include <Eigen/Core>
#include <vector>

#include "indoormap/laser/scan.hpp"

namespace indoormap::scan_features {

/// What ends a run of points or a line at one side.
enum class Boundary {
  kScanEnd,     ///< the first or last beam of the scan
  kRupture,     ///< the next beam has no usable return
  kBreakpoint,  ///< the next return jumps by more than D_max
  kSplit,       ///< split-and-merge cut the run here: the next line is connected (a corner)
};
const char* boundary_name(Boundary b);

struct SegmentParams {
  double lambda_rad = 0.1745329251994;  ///< 10 degrees, Borges and Aldon's value
  double sigma_r_m = 0.01;              ///< range noise of the laser (1 sigma)
  /// Readings at or beyond this are ruptures; 0: the scan's own max_range_m.
  double max_range_m = 0.0;
  void validate() const;  ///< throws UsageError naming the field
};

struct ScanPoint {
  Eigen::Vector2d p_laser = Eigen::Vector2d::Zero();
  double range_m = 0.0;
  int beam = 0;  ///< index of the beam in the scan
};

/// Points [first, last] (indices into Segmentation::points, inclusive), connected.
struct PointRun {
  int first = 0;
  int last = 0;
  Boundary start = Boundary::kScanEnd;
  Boundary end = Boundary::kScanEnd;
  int size() const { return last - first + 1; }
};

struct Segmentation {
  std::vector<ScanPoint> points;  ///< valid returns in scan order (rotated for a full circle)
  std::vector<PointRun> runs;     ///< in scan order, covering every point once
  int ruptures = 0;               ///< beams without a usable return
  int breakpoints = 0;            ///< jumps above D_max
  bool full_circle = false;       ///< the beams cover 360 degrees: last and first are neighbours
};

/// Borges and Aldon's D_max for a previous range r_prev_m and beam spacing dphi_rad (radians,
/// positive). 0 when dphi >= lambda: then every jump is a breakpoint.
double breakpoint_threshold_m(double r_prev_m, double dphi_rad, const SegmentParams& params);

/// Flags ruptures and breakpoints and returns the runs between them. For a full-circle scan the
/// point list starts after a boundary so that no run is cut by the seam. Expects a scan that
/// laser::validate accepts.
Segmentation segment_scan(const laser::LaserScan& scan, const SegmentParams& params);

}  // namespace indoormap::scan_features
