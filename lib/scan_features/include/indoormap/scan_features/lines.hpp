#pragma once
// Line extraction from the runs of a segmented scan: iterative end-point fit (split), merging of
// collinear neighbours, and a total-least-squares refit of each line (Barbre 2021 section 2.2.3-4).
#include <Eigen/Core>
#include <span>
#include <vector>

#include "indoormap/scan_features/segments.hpp"

namespace indoormap::scan_features {

struct LineParams {
  double split_distance_m = 0.05;  ///< a run is split at its farthest point beyond this
  double merge_distance_m = 0.05;  ///< neighbours merge when their joint fit stays within this
  int min_points = 5;              ///< lines of fewer points are dropped
  double min_length_m = 0.2;       ///< ... and so are lines shorter than this
  void validate() const;           ///< throws UsageError naming the field
};

/// The total-least-squares line of a point set: through the centroid along the principal axis.
struct LineFit {
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  ///< unit
  double rms_m = 0.0;                                    ///< RMS orthogonal distance
  double max_m = 0.0;                                    ///< largest orthogonal distance
  /// Signed distance of p to the line (positive on the left of direction).
  double signed_distance(const Eigen::Vector2d& p) const {
    const Eigen::Vector2d d = p - centroid;
    return direction.x() * d.y() - direction.y() * d.x();
  }
  Eigen::Vector2d project(const Eigen::Vector2d& p) const {
    return centroid + direction * direction.dot(p - centroid);
  }
};

/// TLS fit of points[first..last] (at least 2 points). direction points from first to last.
LineFit fit_tls(std::span<const ScanPoint> points);

/// Iterative end-point fit of points[first..last]: the inclusive index ranges of the pieces, in
/// order; consecutive pieces share their split point.
std::vector<std::pair<int, int>> split_iepf(std::span<const ScanPoint> points, int first, int last,
                                            double split_distance_m);

/// A fitted line of the scan (laser frame), oriented in scan order.
struct Line {
  int first = 0, last = 0;  ///< indices into Segmentation::points, inclusive
  Boundary start = Boundary::kScanEnd, end = Boundary::kScanEnd;
  LineFit fit;
  Eigen::Vector2d start_laser = Eigen::Vector2d::Zero(),
                  end_laser = Eigen::Vector2d::Zero();  ///< the end points projected onto the fit
  double length_m() const { return (end_laser - start_laser).norm(); }
};

/// Split-and-merge with TLS refit over every run. A line's end is kSplit when the next kept line
/// lies in the same run (the two are connected; dropped short pieces between them do not count).
std::vector<Line> extract_lines(const Segmentation& seg, const LineParams& params);

}  // namespace indoormap::scan_features
