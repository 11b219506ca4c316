#pragma once
// YAML configuration of grid-areas (config/grid-areas.yaml): sections footprint.*, rooms.*,
// corridors.*, speed.* and map.*, mirroring areas::FootprintParams, RoomParams, CorridorParams,
// the Nav2 speed limits and the plain-map reading. One visit table serves the file reader,
// --print-config and summary.json.
#include <nlohmann/json.hpp>
#include <string>

#include "indoormap/areas/params.hpp"
#include "indoormap/formats/costmap_masks.hpp"

namespace indoormap::app {

struct GridAreasConfig {
  areas::AreasParams areas;
  /// Speed limits (percent of the maximum speed) written to the Nav2 speed mask.
  double room_speed_percent = 100.0;
  double corridor_speed_percent = 80.0;
  double crossing_speed_percent = 40.0;
  /// Plain PNG / PGM maps: grey level >= free_min is free (the shared maps: 250).
  int free_min = 250;
};

template <class C, class F>
void visit_grid_areas(C& c, F&& f) {
  f("footprint", "robot_width_m", c.areas.footprint.robot_width_m);
  f("footprint", "robot_length_m", c.areas.footprint.robot_length_m);
  f("footprint", "turning_radius_m", c.areas.footprint.turning_radius_m);
  f("rooms", "door_max_width_m", c.areas.rooms.door_max_width_m);
  f("rooms", "neck_ratio", c.areas.rooms.neck_ratio);
  f("rooms", "min_core_area_m2", c.areas.rooms.min_core_area_m2);
  f("rooms", "min_room_area_m2", c.areas.rooms.min_room_area_m2);
  f("rooms", "clutter_max_area_m2", c.areas.rooms.clutter_max_area_m2);
  f("corridors", "max_width_m", c.areas.corridors.max_width_m);
  f("corridors", "min_elongation", c.areas.corridors.min_elongation);
  f("corridors", "corner_min_deg", c.areas.corridors.corner_min_deg);
  f("corridors", "fan_min_deg", c.areas.corridors.fan_min_deg);
  f("corridors", "fan_max_deg", c.areas.corridors.fan_max_deg);
  f("corridors", "fan_step_deg", c.areas.corridors.fan_step_deg);
  f("corridors", "fan_travel_m", c.areas.corridors.fan_travel_m);
  f("corridors", "side_turn_min_deg", c.areas.corridors.side_turn_min_deg);
  f("corridors", "crossing_margin_m", c.areas.corridors.crossing_margin_m);
  f("speed", "room_percent", c.room_speed_percent);
  f("speed", "corridor_percent", c.corridor_speed_percent);
  f("speed", "crossing_percent", c.crossing_speed_percent);
  f("map", "free_min", c.free_min);
}

/// Reads a YAML file over config; unknown sections and keys are errors (InputError naming the
/// file, key and line).
void merge_grid_areas_config_file(GridAreasConfig& config, const std::string& path);
/// Throws UsageError naming the field.
void validate(const GridAreasConfig& config);
formats::SpeedPercents speed_percents(const GridAreasConfig& config);
std::string to_yaml(const GridAreasConfig& config);
nlohmann::json to_json(const GridAreasConfig& config);

}  // namespace indoormap::app
