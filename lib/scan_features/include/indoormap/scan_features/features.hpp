#pragma once
// Walls, doors, corners and corridors of one 2D laser scan (Barbre 2021): the semantic features a
// robot needs for "down the hallway, second door on the right".
//
// Frames: every feature is given in the robot frame (x forward, y left; the laser's mounting
// offset applied) and in the map frame (the scan's robot pose applied). The detection itself runs
// in the laser frame, where the sensor is the origin.
#include <Eigen/Core>
#include <vector>

#include "indoormap/laser/scan.hpp"
#include "indoormap/scan_features/lines.hpp"
#include "indoormap/scan_features/segments.hpp"

namespace indoormap::scan_features {

enum class CornerType { kInner, kOuter, kPotential };
const char* corner_type_name(CornerType t);
enum class DoorKind {
  kCollinear,   ///< a gap between two collinear walls
  kBreakpoint,  ///< a gap at a breakpoint whose far jamb lies on the near wall's line
};
const char* door_kind_name(DoorKind k);

struct DoorParams {
  double min_width_m = 0.5;
  double max_width_m = 1.2;
  double max_angle_rad = 0.1745329252;  ///< walls (or wall and gap) collinear within 10 deg
  double max_offset_m = 0.1;            ///< a jamb lies this close to the other wall's line
  /// Beams through the gap must end at least this far behind the door line (or not return).
  double min_depth_m = 0.1;
  void validate() const;
};

struct CornerParams {
  double min_angle_rad = 0.5235987756;  ///< 30 deg: flatter joints are no corner
  double max_gap_m = 0.15;  ///< connected walls: their lines meet this close to both ends
  /// Walls separated by a breakpoint or rupture whose lines meet within this of both ends give
  /// a potential corner (the vertex itself is not seen).
  double potential_max_gap_m = 1.0;
  void validate() const;
};

struct CorridorParams {
  double min_wall_length_m = 1.5;  ///< both sides have a wall at least this long
  double min_width_m = 0.8;
  double max_width_m = 4.0;
  double max_angle_rad = 0.1745329252;  ///< the two sides parallel within 10 deg
  double min_overlap_m = 1.0;           ///< the sides overlap along the axis by this much
  double side_offset_m = 0.15;          ///< further collinear walls join a side within this
  void validate() const;
};

struct FeatureParams {
  SegmentParams segments;
  LineParams lines;
  DoorParams doors;
  CornerParams corners;
  CorridorParams corridors;
  void validate() const;  ///< every part's validate()
};

/// A wall as a directed segment: the free side (where the sensor is) on its left.
struct Wall {
  Eigen::Vector2d start_laser = Eigen::Vector2d::Zero(), end_laser = Eigen::Vector2d::Zero();
  Eigen::Vector2d start_robot = Eigen::Vector2d::Zero(), end_robot = Eigen::Vector2d::Zero();
  Eigen::Vector2d start_map = Eigen::Vector2d::Zero(), end_map = Eigen::Vector2d::Zero();
  Boundary start = Boundary::kScanEnd, end = Boundary::kScanEnd;
  int points = 0;
  int first_beam = 0, last_beam = 0;
  double rms_m = 0.0;  ///< of the TLS fit
  double length_m() const { return (end_laser - start_laser).norm(); }
  /// Unit vector from start to end, laser frame.
  Eigen::Vector2d direction_laser() const { return (end_laser - start_laser).normalized(); }
};

/// A door as the gap between its jambs a and b (a first in wall order).
struct Door {
  Eigen::Vector2d a_laser = Eigen::Vector2d::Zero(), b_laser = Eigen::Vector2d::Zero();
  Eigen::Vector2d a_robot = Eigen::Vector2d::Zero(), b_robot = Eigen::Vector2d::Zero();
  Eigen::Vector2d a_map = Eigen::Vector2d::Zero(), b_map = Eigen::Vector2d::Zero();
  int wall_before = -1, wall_after = -1;  ///< indices into ScanFeatures::walls
  DoorKind kind = DoorKind::kCollinear;
  double width_m() const { return (b_laser - a_laser).norm(); }
};

/// Where wall_in (ending there) meets wall_out (starting there), with the three distances of
/// the paper's corner typing (sensor to corner, sensor to the missing leg, corner to the leg).
struct Corner {
  Eigen::Vector2d p_laser = Eigen::Vector2d::Zero(), p_robot = Eigen::Vector2d::Zero(),
                  p_map = Eigen::Vector2d::Zero();
  int wall_in = -1, wall_out = -1;
  CornerType type = CornerType::kPotential;
  double angle_rad = 0.0;  ///< between the walls' directions, (0, pi)
  double d_rc_m = 0.0, d_rl_m = 0.0, d_cl_m = 0.0;
};

/// Two long, parallel, facing sides; each a list of collinear walls.
struct Corridor {
  std::vector<int> side_a, side_b;  ///< indices into ScanFeatures::walls
  double width_m = 0.0;
  double overlap_m = 0.0;  ///< of the two longest walls along the axis
};

struct ScanFeatures {
  std::vector<Wall> walls;  ///< in scan order
  std::vector<Door> doors;
  std::vector<Corner> corners;
  std::vector<Corridor> corridors;
  int returns = 0, ruptures = 0, breakpoints = 0;
};

/// The paper's three-distance corner typing of a corner c between legs ending at a (start of the
/// first wall) and b (end of the second), seen from the sensor s (all in one frame): inner when
/// the corner lies beyond the missing leg a-b as seen from s, or s lies between the leg and the
/// corner (d_rl < d_cl on the corner's side); outer when the corner lies between s and the leg.
CornerType corner_type_three_distances(const Eigen::Vector2d& s, const Eigen::Vector2d& a,
                                       const Eigen::Vector2d& c, const Eigen::Vector2d& b,
                                       double* d_rc = nullptr, double* d_rl = nullptr,
                                       double* d_cl = nullptr);

// The steps of extract_features, in order; they work in the laser frame (the robot- and map-frame
// fields are filled by extract_features at the end). find_corners moves the end points of
// connected walls onto their corner.
/// Walls from the lines of a scan, oriented free side left, in wall order (end of wall i next to
/// the start of wall i + 1).
std::vector<Wall> make_walls(const laser::LaserScan& scan, const Segmentation& seg,
                             const std::vector<Line>& lines);
std::vector<Corner> find_corners(std::vector<Wall>& walls, bool full_circle,
                                 const CornerParams& params);
std::vector<Door> find_doors(const laser::LaserScan& scan, const Segmentation& seg,
                             const std::vector<Wall>& walls, const DoorParams& params);
std::vector<Corridor> find_corridors(const std::vector<Wall>& walls, const CorridorParams& params);

/// Everything above for one scan. Expects a scan that laser::validate accepts.
ScanFeatures extract_features(const laser::LaserScan& scan, const FeatureParams& params);

}  // namespace indoormap::scan_features
