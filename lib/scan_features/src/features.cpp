#include "indoormap/scan_features/features.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "indoormap/core/errors.hpp"

namespace indoormap::scan_features {

const char* corner_type_name(CornerType t) {
  switch (t) {
    case CornerType::kInner:
      return "inner";
    case CornerType::kOuter:
      return "outer";
    case CornerType::kPotential:
      return "potential";
  }
  return "?";
}

const char* door_kind_name(DoorKind k) {
  return k == DoorKind::kCollinear ? "collinear" : "breakpoint";
}

namespace {

void check(bool ok, const std::string& key, double v, const char* what) {
  if (!ok || !std::isfinite(v))
    throw UsageError(key + " must be " + what + ", got " + std::to_string(v));
}

constexpr double kHalfPi = std::numbers::pi / 2;

/// The robot- and map-frame copies of every laser-frame point of the features.
void fill_frames(const laser::LaserScan& scan, ScanFeatures& f) {
  const laser::Pose2d& robot = scan.laser_offset;
  const laser::Pose2d map = scan.laser_pose_map();
  for (Wall& w : f.walls) {
    w.start_robot = robot.transform(w.start_laser);
    w.end_robot = robot.transform(w.end_laser);
    w.start_map = map.transform(w.start_laser);
    w.end_map = map.transform(w.end_laser);
  }
  for (Door& d : f.doors) {
    d.a_robot = robot.transform(d.a_laser);
    d.b_robot = robot.transform(d.b_laser);
    d.a_map = map.transform(d.a_laser);
    d.b_map = map.transform(d.b_laser);
  }
  for (Corner& c : f.corners) {
    c.p_robot = robot.transform(c.p_laser);
    c.p_map = map.transform(c.p_laser);
  }
}

}  // namespace

void DoorParams::validate() const {
  check(min_width_m > 0.0, "doors.min_width_m", min_width_m, "positive");
  check(max_width_m >= min_width_m, "doors.max_width_m", max_width_m, ">= doors.min_width_m");
  check(max_angle_rad > 0.0 && max_angle_rad < kHalfPi, "doors.max_angle_rad", max_angle_rad,
        "in (0, pi/2)");
  check(max_offset_m > 0.0, "doors.max_offset_m", max_offset_m, "positive");
  check(min_depth_m >= 0.0, "doors.min_depth_m", min_depth_m, ">= 0");
}

void CornerParams::validate() const {
  check(min_angle_rad > 0.0 && min_angle_rad < std::numbers::pi, "corners.min_angle_rad",
        min_angle_rad, "in (0, pi)");
  check(max_gap_m > 0.0, "corners.max_gap_m", max_gap_m, "positive");
  check(potential_max_gap_m >= 0.0, "corners.potential_max_gap_m", potential_max_gap_m, ">= 0");
}

void CorridorParams::validate() const {
  check(min_wall_length_m > 0.0, "corridors.min_wall_length_m", min_wall_length_m, "positive");
  check(min_width_m > 0.0, "corridors.min_width_m", min_width_m, "positive");
  check(max_width_m >= min_width_m, "corridors.max_width_m", max_width_m,
        ">= corridors.min_width_m");
  check(max_angle_rad > 0.0 && max_angle_rad < kHalfPi, "corridors.max_angle_rad", max_angle_rad,
        "in (0, pi/2)");
  check(min_overlap_m >= 0.0, "corridors.min_overlap_m", min_overlap_m, ">= 0");
  check(side_offset_m > 0.0, "corridors.side_offset_m", side_offset_m, "positive");
}

void FeatureParams::validate() const {
  segments.validate();
  lines.validate();
  doors.validate();
  corners.validate();
  corridors.validate();
}

CornerType corner_type_three_distances(const Eigen::Vector2d& s, const Eigen::Vector2d& a,
                                       const Eigen::Vector2d& c, const Eigen::Vector2d& b,
                                       double* d_rc, double* d_rl, double* d_cl) {
  const Eigen::Vector2d ab = b - a;
  const double len = std::max(ab.norm(), 1e-12);
  auto side = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2d ap = p - a;
    return (ab.x() * ap.y() - ab.y() * ap.x()) / len;  // signed distance to the leg's line
  };
  const double rs = side(s), cs = side(c);
  const double rc = (c - s).norm(), rl = std::abs(rs), cl = std::abs(cs);
  if (d_rc) *d_rc = rc;
  if (d_rl) *d_rl = rl;
  if (d_cl) *d_cl = cl;
  // The leg's side alone separates "corner beyond the leg" (inner) from "corner in front of it";
  // in front, the robot is either beyond the corner (outer: r-l > c-l) or between the leg and the
  // corner, inside the triangle (inner: r-l <= c-l). The paper's unsigned comparisons cannot tell
  // the first case from the others, hence the side.
  if (rs * cs <= 0.0) return CornerType::kInner;
  return rl > cl ? CornerType::kOuter : CornerType::kInner;
}

ScanFeatures extract_features(const laser::LaserScan& scan, const FeatureParams& params) {
  ScanFeatures f;
  const Segmentation seg = segment_scan(scan, params.segments);
  f.returns = static_cast<int>(seg.points.size());
  f.ruptures = seg.ruptures;
  f.breakpoints = seg.breakpoints;
  const std::vector<Line> lines = extract_lines(seg, params.lines);
  f.walls = make_walls(scan, seg, lines);
  f.corners = find_corners(f.walls, seg.full_circle, params.corners);
  f.doors = find_doors(scan, seg, f.walls, params.doors);
  f.corridors = find_corridors(f.walls, params.corridors);
  fill_frames(scan, f);
  return f;
}

}  // namespace indoormap::scan_features
