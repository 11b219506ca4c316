#pragma once
// The scene description the simulator takes: rooms (polygons with walls, doors, windows, a flat or
// sloped ceiling), furniture, scanner positions, scanner model and a tilt of the whole scan.
//
// Frame: the scene frame is metric, right-handed, z up, floor at z = 0 (every room's floor).
// The tilt is a rotation of the whole scan about the scene origin (see tilt_rotation()).
// YAML is parsed by the app (apps/scene-sim/scene_yaml.cpp); docs/scene-sim.md has the schema.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "indoormap/core/polygon.hpp"

namespace indoormap::sim {

/// A door or window in one edge of a room polygon. The edge runs from polygon[edge] to
/// polygon[(edge + 1) % n]; the opening spans [at_m - width_m/2, at_m + width_m/2] along it and
/// [bottom_m, top_m] in height (a door has bottom_m = 0).
struct Opening {
  int edge = 0;
  double at_m = 0.0;  ///< distance of the opening's centre from the edge's first vertex
  double width_m = 0.9;
  double bottom_m = 0.0;  ///< window sill height; 0 for doors
  double top_m = 2.1;
};

/// Ceiling plane: height_m at the polygon's lowest point along rise_azimuth_deg, rising with
/// slope_deg in that direction (slope 0: flat ceiling at height_m).
struct Ceiling {
  double height_m = 2.9;
  double slope_deg = 0.0;
  double rise_azimuth_deg = 0.0;  ///< direction (counter-clockwise from +x) in which it rises
};

enum class RoomKind { kRoom, kCorridor };

struct Room {
  std::string name;
  RoomKind kind = RoomKind::kRoom;
  Polygon polygon;                ///< inner wall faces, scene frame, metres; either orientation
  double wall_thickness_m = 0.2;  ///< walls are the polygon's boundary extruded outward
  Ceiling ceiling;
  std::vector<Opening> doors;
  std::vector<Opening> windows;
};

enum class FurnitureType { kDesk, kTable, kCabinet, kShelf, kBox, kChair, kBin, kPillar, kLamp };

std::string_view to_string(FurnitureType t);
/// Parses "desk", "table", ...; nullopt when unknown.
std::optional<FurnitureType> parse_furniture_type(std::string_view s);

/// One furniture item. Box-shaped items (desk, table, cabinet, shelf, box, chair, lamp) use
/// size_m along the item's own x / y axes, rotated by yaw_deg; round items (bin, pillar, and a
/// table or lamp with radius_m > 0) use radius_m. A desk / table is a top on four legs (a round
/// table: one central leg), a chair a seat on four legs with a backrest on its local -x side,
/// a lamp a flat body hanging drop_m below the ceiling on thin cords.
struct Furniture {
  std::string id;  ///< unique; generated ("desk_3") when empty
  FurnitureType type = FurnitureType::kBox;
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d size_m = Eigen::Vector2d(1.0, 0.5);
  double radius_m = 0.0;
  double yaw_deg = 0.0;
  double height_m = 0.0;        ///< top above the floor; 0: the type's default (pillar: ceiling)
  double seat_height_m = 0.45;  ///< chair
  double drop_m = 0.5;          ///< lamp: gap between ceiling and lamp top
  double thickness_m = 0.0;     ///< table / desk top, lamp body; 0: type default
};

/// Default height of a type (metres above the floor); 0 for pillar (reaches the ceiling) and lamp.
double default_height_m(FurnitureType t);

struct ScannerPose {
  Eigen::Vector3d position_m = Eigen::Vector3d(0, 0, 1.3);  ///< scene frame (before the tilt)
  double heading_deg = 0.0;  ///< azimuth of the first measured column
};

/// A terrestrial scanner like the Riegl VZ-400: a full turn horizontally, a vertical fan.
struct ScannerParams {
  double azimuth_step_deg = 0.25;
  double elevation_step_deg = 0.25;
  double elevation_min_deg = -40.0;
  double elevation_max_deg = 60.0;
  double range_min_m = 0.5;
  double range_max_m = 100.0;
  double range_sigma_m = 0.005;  ///< Gaussian range noise
  /// Probability that a ray at a depth edge (range jump above mixed_pixel_min_jump_m to its
  /// upper or left neighbour) returns a mixed pixel: a point somewhere between both surfaces.
  double mixed_pixel_probability = 0.3;
  double mixed_pixel_min_jump_m = 0.3;
  /// Recorded coordinates are rounded to multiples of this step in the output (tilted) frame,
  /// as a scanner's export does (a LAS file of scale 0.001 holds 1 mm points exactly); 0: the
  /// full float precision.
  double coordinate_step_m = 0.0;
};

struct Tilt {
  double roll_deg = 0.0;   ///< about the x axis
  double pitch_deg = 0.0;  ///< about the y axis
};

/// R = Ry(pitch) * Rx(roll): scene frame -> written (tilted) frame, about the origin.
Eigen::Matrix3d tilt_rotation(const Tilt& tilt);

struct Scene {
  std::string name = "scene";
  std::vector<Room> rooms;
  std::vector<Furniture> furniture;
  std::vector<ScannerPose> scanners;
  ScannerParams scanner;
  Tilt tilt;
  std::uint64_t seed = 1;  ///< seeds the noise (and nothing else) of a given scene
};

/// A problem found by check_scene: key in the YAML schema's words ("rooms[0].doors[1].width_m").
struct SceneProblem {
  std::string key;
  std::string problem;
};

/// Checks the scene for geometric consistency (simple polygons, openings inside their edges and
/// not overlapping, furniture and scanners inside rooms, sane scanner parameters). Empty when
/// the scene is fine.
std::vector<SceneProblem> check_scene(const Scene& scene);

/// Throws UsageError listing the first problem of check_scene, if any.
void require_valid(const Scene& scene);

/// Fills empty furniture ids ("<type>_<n>") and normalises room polygons to counter-clockwise
/// order (keeping door / window edge references valid). Called by the simulator entry points.
Scene normalised(Scene scene);

/// Ceiling height (z) of a room at a scene-frame point.
double ceiling_z(const Room& room, const Eigen::Vector2d& p_m);

/// Index of the first room whose polygon contains p, or -1.
int room_at(const Scene& scene, const Eigen::Vector2d& p_m);

}  // namespace indoormap::sim
