#pragma once
// Alignment of two 2D laser scans: Procrustes (the SVD solution of the paired rigid transform,
// Barbre 2021 section 2.3) iterated with nearest neighbours (point-to-point ICP), and the
// point-to-line variant (each pair's error measured along the reference's surface normal,
// solved by Gauss-Newton), which converges in fewer iterations on walls.
//
// Frames: the result maps points of the current scan's laser frame into the reference scan's
// laser frame; it is the current laser pose relative to the reference one.
#include <Eigen/Core>
#include <span>
#include <vector>

#include "indoormap/laser/scan.hpp"

namespace indoormap::scan_features {

enum class IcpKind { kPointToPoint, kPointToLine };
const char* icp_kind_name(IcpKind k);

struct IcpParams {
  IcpKind kind = IcpKind::kPointToLine;
  int max_iterations = 60;
  double max_pair_m = 0.5;        ///< pairs farther apart are no pairs
  double trim_factor = 3.0;       ///< ... and so are pairs beyond this times the median distance
  double min_trim_m = 0.05;       ///< (never below this)
  double converged_m = 1e-5;      ///< stop when a step moves less than this
  double converged_rad = 1e-6;    ///< ... and turns less than this
  int min_pairs = 10;             ///< fewer: the alignment failed
  double normal_radius_m = 0.25;  ///< neighbours (in scan order) for a point's normal
  double max_range_m = 0.0;       ///< points at or beyond are left out; 0: the scan's maximum
  /// A pair within this after convergence is an inlier; the share of cur's points that are
  /// inliers scores a start (align_scans keeps the best start).
  double inlier_m = 0.05;
  void validate() const;  ///< throws UsageError naming the field
};

struct IcpResult {
  laser::Pose2d transform;  ///< current laser frame -> reference laser frame
  double rms_m = 0.0;       ///< RMS pair error (point distance, or distance to the line)
  int pairs = 0;
  int iterations = 0;
  bool converged = false;     ///< false: max_iterations reached or too few pairs (see pairs)
  double inlier_share = 0.0;  ///< of the current scan's points, within inlier_m after the last step
  int starts = 1;             ///< starts tried by align_scans
};

/// The starts align_scans tries: each guess turned by each rotation offset, in order, until one
/// ends with inlier_share >= accept_inlier_share. Consecutive scans of a log may be a metre and
/// tens of degrees apart (the corrected logs keep a scan per step), beyond what ICP from one
/// start reaches.
struct AlignSearch {
  std::vector<double> rotation_offsets_rad = {0.0, 0.1745, -0.1745, 0.349, -0.349, 0.5236, -0.5236};
  double accept_inlier_share = 0.8;
  void validate() const;
};

/// The rigid transform T minimising sum |T(src_i) - dst_i|^2 (pairs by index; >= 2 pairs): the
/// centroids matched and the rotation from the SVD of the cross-covariance.
laser::Pose2d procrustes(std::span<const Eigen::Vector2d> src,
                         std::span<const Eigen::Vector2d> dst);

/// a^-1 composed with b: pose b expressed in the frame of pose a.
laser::Pose2d relative_pose(const laser::Pose2d& a, const laser::Pose2d& b);

/// The hits of a scan as laser-frame points, in beam order (max_range_m 0: the scan's).
std::vector<Eigen::Vector2d> scan_points_laser(const laser::LaserScan& scan,
                                               double max_range_m = 0);

/// ICP of cur onto ref (laser-frame points, in scan order: the normals of point-to-line come from
/// scan-order neighbours), starting from guess.
IcpResult align_points(const std::vector<Eigen::Vector2d>& ref,
                       const std::vector<Eigen::Vector2d>& cur, const laser::Pose2d& guess,
                       const IcpParams& params);

/// align_points on two scans' hits from every start of search around the guesses (no guess:
/// the identity); the result of the start with the highest inlier share.
IcpResult align_scans(const laser::LaserScan& ref, const laser::LaserScan& cur,
                      const IcpParams& params, const AlignSearch& search = {},
                      std::span<const laser::Pose2d> guesses = {});

}  // namespace indoormap::scan_features
