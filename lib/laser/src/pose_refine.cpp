#include "indoormap/laser/pose_refine.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "indoormap/core/errors.hpp"
#include "indoormap/laser/raycast.hpp"

namespace indoormap::laser {

void PoseRefineParams::validate() const {
  if (passes < 0 || passes > 10) throw UsageError("pose_refine.passes must be in 0..10");
  if (!(field_sigma_m > 0.0 && field_sigma_m <= 1.0))
    throw UsageError("pose_refine.field_sigma_m must be in (0, 1] m");
  if (iterations < 1 || iterations > 100)
    throw UsageError("pose_refine.iterations must be in 1..100");
  if (!(max_shift_m > 0.0 && max_shift_m <= 5.0))
    throw UsageError("pose_refine.max_shift_m must be in (0, 5] m");
  if (!(max_turn_deg > 0.0 && max_turn_deg <= 45.0))
    throw UsageError("pose_refine.max_turn_deg must be in (0, 45] degrees");
  if (min_hits < 3) throw UsageError("pose_refine.min_hits must be >= 3");
}

MatchField::MatchField(const Grid<Cell>& cells, const GridGeometry& geometry, double sigma_m)
    : geometry_(geometry), value_(cells.width, cells.height, 0.0f) {
  for (std::size_t i = 0; i < cells.data.size(); ++i)
    value_.data[i] = is_obstacle(cells.data[i]) ? 1.0f : 0.0f;
  if (value_.data.empty()) return;
  cv::Mat m(value_.height, value_.width, CV_32F, value_.data.data());
  const double sigma_cells = geometry.to_cells(sigma_m);
  cv::GaussianBlur(m, m, cv::Size(0, 0), sigma_cells, sigma_cells, cv::BORDER_CONSTANT);
  // Scaled so that the middle of a straight wall one cell thick reads 1 (its peak after the blur
  // is 1 / (sqrt(2 pi) sigma) for sigma in cells); thicker bands are clipped to 1.
  const double line_peak = std::min(1.0, 1.0 / (std::sqrt(2.0 * std::numbers::pi) * sigma_cells));
  m *= 1.0 / line_peak;
  cv::min(m, 1.0, m);
}

double MatchField::sample(const Eigen::Vector2d& p_map, Eigen::Vector2d* grad_m) const {
  // Values live at cell centres: shift by half a cell so that (0, 0) is cell (0, 0)'s centre.
  const Eigen::Vector2d v = geometry_.to_cell_coords(p_map) - Eigen::Vector2d(0.5, 0.5);
  if (grad_m) grad_m->setZero();
  if (!(v.x() >= 0.0 && v.y() >= 0.0 && v.x() < value_.width - 1 && v.y() < value_.height - 1))
    return 0.0;
  const int c = static_cast<int>(v.x()), r = static_cast<int>(v.y());
  const double fx = v.x() - c, fy = v.y() - r;
  const double v00 = value_.at(c, r), v10 = value_.at(c + 1, r);
  const double v01 = value_.at(c, r + 1), v11 = value_.at(c + 1, r + 1);
  if (grad_m) {
    const double inv = 1.0 / geometry_.cell_m();
    *grad_m = Eigen::Vector2d(((v10 - v00) * (1 - fy) + (v11 - v01) * fy) * inv,
                              ((v01 - v00) * (1 - fx) + (v11 - v10) * fx) * inv);
  }
  return (v00 * (1 - fx) + v10 * fx) * (1 - fy) + (v01 * (1 - fx) + v11 * fx) * fy;
}

namespace {

/// The scan's hits in the robot frame (laser offset applied), within max_range_m.
std::vector<Eigen::Vector2d> hits_robot_frame(const LaserScan& scan, double max_range_m) {
  std::vector<Eigen::Vector2d> pts;
  pts.reserve(scan.size());
  for (std::size_t i = 0; i < scan.size(); ++i) {
    if (!scan.is_hit(i) || scan.ranges_m[i] >= max_range_m) continue;
    const double a = scan.beam_angle_rad(i), r = scan.ranges_m[i];
    pts.push_back(scan.laser_offset.transform({r * std::cos(a), r * std::sin(a)}));
  }
  return pts;
}

/// One Gauss-Newton step on sum (1 - M(T p))^2; returns false when the system is singular.
bool gauss_newton_step(const std::vector<Eigen::Vector2d>& pts, const MatchField& field,
                       Pose2d& pose, int& used) {
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  const double cs = std::cos(pose.theta_rad), sn = std::sin(pose.theta_rad);
  used = 0;
  for (const auto& p : pts) {
    Eigen::Vector2d grad;
    const double m = field.sample(pose.transform(p), &grad);
    if (m <= 0.0) continue;
    ++used;
    // d(T p)/d(x, y, theta)
    const Eigen::Vector2d dtheta(-sn * p.x() - cs * p.y(), cs * p.x() - sn * p.y());
    const Eigen::Vector3d j(grad.x(), grad.y(), grad.dot(dtheta));  // dM/dxi = -dr/dxi
    h += j * j.transpose();
    g += j * (1.0 - m);
  }
  if (h.determinant() < 1e-9) return false;
  const Eigen::Vector3d d = h.ldlt().solve(g);  // r = 1 - M: xi += (J^T J)^-1 J^T (1 - M)
  if (!d.allFinite()) return false;
  pose.x_m += d.x();
  pose.y_m += d.y();
  pose.theta_rad = wrap_angle(pose.theta_rad + d.z());
  return true;
}

}  // namespace

PoseCorrection refine_pose(const LaserScan& scan, const MatchField& field, double max_range_m,
                           const PoseRefineParams& params) {
  PoseCorrection out;
  out.robot_pose_map = scan.robot_pose_map;
  const auto pts = hits_robot_frame(scan, max_range_m);
  if (static_cast<int>(pts.size()) < params.min_hits) return out;
  Pose2d pose = scan.robot_pose_map;
  int used = 0;
  for (int it = 0; it < params.iterations; ++it)
    if (!gauss_newton_step(pts, field, pose, used) || used < params.min_hits) return out;
  const double shift = (pose.position_m() - scan.robot_pose_map.position_m()).norm();
  const double turn = std::abs(wrap_angle(pose.theta_rad - scan.robot_pose_map.theta_rad));
  if (shift > params.max_shift_m || turn > params.max_turn_deg * std::numbers::pi / 180.0)
    return out;
  out = {pose, true, shift, turn};
  return out;
}

}  // namespace indoormap::laser
