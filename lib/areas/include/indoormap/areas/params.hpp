#pragma once
// Parameters of the area split (docs/grid-areas.md), with defaults and units in their names.
// validate() throws UsageError naming the key.
#include <string_view>

namespace indoormap::areas {

/// The robot: a rectangle width x length (metres) turning on arcs of at least turning_radius_m.
struct FootprintParams {
  double robot_width_m = 0.5;
  double robot_length_m = 0.6;
  double turning_radius_m = 0.3;
};

/// Room segmentation: a watershed of the free space's distance transform. Two basins meeting at
/// a neck stay apart (a door) when the neck's clear width is at most door_max_width_m, the
/// smaller basin's peak clearance is at least neck_ratio times the neck's, and the smaller
/// basin's core (the cells above the neck's clearance) holds at least min_core_area_m2.
struct RoomParams {
  double door_max_width_m = 1.5;
  double neck_ratio = 1.4;
  double min_core_area_m2 = 0.6;
  double min_room_area_m2 = 1.5;  ///< smaller pieces are merged into a neighbour
  /// Obstacle blobs (8-connected, not touching the map's edge) up to this area are clutter
  /// (furniture, noise): ignored when finding doors, so that a table is no door.
  double clutter_max_area_m2 = 2.0;
};

/// Corridors: a piece (furniture holes filled) whose estimated width is at most max_width_m and
/// whose area is at least min_elongation times its width squared. Crossings: skeleton points
/// where three or more ways meet or the way bends by at least corner_min_deg, confirmed by the
/// fan-of-turns test (paper: -130..130 degrees in 10 degree steps, travel fan_travel_m; a turn
/// beyond side_turn_min_deg is a turn into another way).
struct CorridorParams {
  double max_width_m = 2.6;
  double min_elongation = 4.0;
  double corner_min_deg = 50.0;
  double fan_min_deg = -130.0;
  double fan_max_deg = 130.0;
  double fan_step_deg = 10.0;
  double fan_travel_m = 1.5;
  double side_turn_min_deg = 30.0;
  double crossing_margin_m = 0.0;  ///< added to the half width when cutting a crossing's arms
};

struct AreasParams {
  FootprintParams footprint;
  RoomParams rooms;
  CorridorParams corridors;
};

void validate(const FootprintParams& p);
void validate(const RoomParams& p);
void validate(const CorridorParams& p);
void validate(const AreasParams& p);

}  // namespace indoormap::areas
