#pragma once
// Simulated 2D laser scans with known geometry, for the accuracy of scan_features: random rooms
// (rectangular or L-shaped, an optional pillar) with doors opening onto closets, ray-cast
// analytically against the wall segments with Gaussian range noise.
//
// Frames: every scene coordinate is in the map frame (metres). Walls are directed segments with
// the free side (the room's interior, or the closet's) on their left.
#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <vector>

#include "indoormap/laser/scan.hpp"

namespace indoormap::sim {

struct ScanSegment {
  Eigen::Vector2d a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero();
};

enum class TrueCornerType { kInner, kOuter };

struct TrueCorner {
  Eigen::Vector2d p_map = Eigen::Vector2d::Zero();
  TrueCornerType type = TrueCornerType::kInner;  ///< as seen from the free side
};

struct ScanScene {
  std::vector<ScanSegment> walls;  ///< free side on the left
  std::vector<ScanSegment> doors;  ///< the openings, jamb a to jamb b (along the room wall)
  std::vector<TrueCorner> corners;
  std::vector<Eigen::Vector2d> room;    ///< the room's outline (counter-clockwise), doors closed
  std::vector<Eigen::Vector2d> pillar;  ///< the pillar's outline, or empty
};

struct ScanSceneParams {
  double min_side_m = 4.0, max_side_m = 9.0;
  double l_shape_share = 0.5;  ///< rooms that lose a rectangular notch at one corner
  double pillar_share = 0.5;
  double door_share = 0.8;  ///< each long enough room side gets a door with this probability
  double min_door_m = 0.6, max_door_m = 1.1;
  void validate() const;  ///< throws UsageError naming the field
};

/// A deterministic random scene.
ScanScene random_scan_scene(std::uint64_t seed, const ScanSceneParams& params = {});

struct LaserModel {
  int beams = 720;
  double fov_rad = 6.283185307179586;  ///< 2 pi: a full circle (beam i at i * fov / beams)
  double max_range_m = 30.0;
  double sigma_r_m = 0.01;
  void validate() const;
};

/// Distance from origin along unit dir to the first wall (infinity when none).
double cast_ray(const ScanScene& scene, const Eigen::Vector2d& origin, const Eigen::Vector2d& dir);
/// True when the straight line from `from` to `to` crosses no wall (to within tol_m of `to`).
bool line_of_sight(const ScanScene& scene, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                   double tol_m = 1e-3);
/// A scan of the scene from the laser pose (map frame); robot pose = laser pose, no offset.
laser::LaserScan cast_scan(const ScanScene& scene, const laser::Pose2d& laser_map,
                           const LaserModel& model, std::mt19937_64& rng);
/// A random laser pose inside the room, at least clearance_m from every wall and the pillar.
laser::Pose2d random_pose(const ScanScene& scene, double clearance_m, std::mt19937_64& rng);

}  // namespace indoormap::sim
