#pragma once
// Levelling (pipeline step 2): real scans are not level, so the floor and the ceiling smear over
// several voxel layers. We fit the floor and ceiling planes robustly (RANSAC over near-horizontal
// planes, then least squares on the inliers) and rotate the cloud so that they are horizontal.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "indoormap/cloud/align.hpp"
#include "indoormap/core/cloud.hpp"

namespace indoormap::cloud {

struct LevelParams {
  bool enabled = true;
  /// Planes tilted more than this are not floor / ceiling, and no larger correction is made: a
  /// real scanner on a tripod stands within a few degrees of level; a steeper "floor" is a
  /// nearby object's face or a slope seen from one side.
  double max_tilt_deg = 5.0;
  /// The plane a tilt rests on must hold this much area (0.25 m cells with inliers) ...
  double min_support_area_m2 = 4.0;
  /// ... and, when the scanner positions are known, reach round a scanner: this share of the
  /// 10 degree sectors round it hold inliers. Fitted to one side only, a plane tilts with that
  /// side's unevenness and the scanner's own errors (a 40 degree sector of the Jacobs scan:
  /// 2.63 degrees where the whole scan says 2.13); such a tilt is refused.
  double min_support_surround = 0.75;
  /// A scan covering less of the horizon round every scanner than this gets a warning.
  double warn_horizon_share = 0.9;
  /// A cloud whose levelling plane holds less than this share of the cloud's area (both on
  /// 0.25 m cells) gets a warning: its floor is nearly all unseen.
  double warn_floor_share = 0.2;
  double band_m = 0.6;         ///< search band around the floor / ceiling histogram peak
  double peak_fraction = 0.2;  ///< floor / ceiling: lowest / highest 0.1 m height bin with this
                               ///< share of the fullest bin
  double inlier_m = 0.03;      ///< RANSAC inlier distance
  int iterations = 1000;       ///< RANSAC iterations per plane
  std::size_t sample_points = 200000;  ///< points used for the fit (evenly strided)
  std::size_t min_inliers = 200;       ///< fewer inliers: plane not found
  /// The inliers must cover this share of their bounding box (on a 0.25 m grid): a floor or a
  /// ceiling is an area, the top edges of the walls of a ceiling-less scan are only a ring.
  double min_fill = 0.1;
  double max_normal_disagreement_deg = 2.0;  ///< floor/ceiling normals further apart: floor only
  std::uint64_t seed = 1;
};

/// Throws UsageError naming the key (level.band_m, ...) for a parameter out of its range.
void validate(const LevelParams& params);

struct PlaneFit {
  bool found = false;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit, pointing up (z > 0)
  double offset_m = 0.0;                              ///< plane: normal . p = offset_m
  std::size_t inliers = 0;                            ///< among the sampled points
  double rms_m = 0.0;                                 ///< RMS distance of the inliers
  double extent_m = 0.0;  ///< the diagonal of the inliers' 2nd-98th percentile x / y box
};

/// What a levelling plane rests on (level_support).
struct LevelSupport {
  double plane_area_m2 = 0.0;         ///< 0.25 m cells holding the plane's inliers
  double cloud_area_m2 = 0.0;         ///< 0.25 m cells holding >= 1/20 of the median count
  double plane_surround_share = 0.0;  ///< best over the scanners; 1 without scanners
  double horizon_share = 0.0;         ///< of all points, best over the scanners; 1 without
};

/// The support of `plane` among `sample` (inliers: within inlier_m), round the scanners.
LevelSupport level_support(const std::vector<Eigen::Vector3d>& sample, const PlaneFit& plane,
                           double inlier_m, const std::vector<Eigen::Vector3d>& scanners);

struct LevelResult {
  bool levelled = false;  ///< false: no tilt corrected (disabled or no plane found)
  /// Rotation about the origin: map = map_from_input * input; its inverse is its transpose.
  /// estimate_level sets the tilt only; layout::level_cloud composes the wall alignment's yaw
  /// into it (align.rotation * tilt), so the map frame is levelled and, when applied, aligned.
  Eigen::Matrix3d map_from_input = Eigen::Matrix3d::Identity();
  double tilt_deg = 0.0;  ///< angle between the measured up direction and z
  Eigen::Vector3d up_input = Eigen::Vector3d::UnitZ();  ///< measured up direction, input frame
  PlaneFit floor;                                       ///< in the input frame
  PlaneFit ceiling;                                     ///< in the input frame
  std::string note;                   ///< why not levelled, or which planes were used
  LevelSupport support;               ///< of the plane the tilt rests on (the floor if found)
  std::vector<std::string> warnings;  ///< partial horizon, floor nearly unseen, refused tilt
  WallAlignResult align;  ///< the yaw about +z after the tilt (layout::level_cloud), if asked
};

/// Estimates the levelling rotation. Deterministic for a fixed seed. Never throws on data it
/// cannot level: the result says so (levelled = false) and why. Throws UsageError for invalid
/// params.
/// With the scanner positions (input frame), a tilt is refused (levelled = false, a warning) when
/// the plane it rests on holds less than min_support_area_m2 or reaches round no scanner
/// (min_support_surround); a scan covering less than warn_horizon_share of the horizon, or a
/// floor holding less than warn_floor_share of the cloud's area, gets a warning naming the share.
LevelResult estimate_level(const std::vector<Eigen::Vector3f>& points, const LevelParams& params,
                           const std::vector<Eigen::Vector3d>& scanners = {});

/// Rotates points and scanner positions in place: p <- R p.
void rotate(PointCloud& cloud, const Eigen::Matrix3d& rotation);

/// Least-squares plane (normal up) through points; nullopt-like result (found = false) for < 3.
PlaneFit fit_plane_least_squares(const std::vector<Eigen::Vector3d>& points);

}  // namespace indoormap::cloud
