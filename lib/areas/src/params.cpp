#include "indoormap/areas/params.hpp"

#include <cmath>
#include <string>

#include "indoormap/core/errors.hpp"

namespace indoormap::areas {
namespace {

void positive(double v, const char* key) {
  if (!std::isfinite(v) || v <= 0.0)
    throw UsageError(std::string(key) + " must be a positive number, got " + std::to_string(v));
}
void at_least(double v, double lo, const char* key) {
  if (!std::isfinite(v) || v < lo)
    throw UsageError(std::string(key) + " must be at least " + std::to_string(lo) + ", got " +
                     std::to_string(v));
}

}  // namespace

void validate(const FootprintParams& p) {
  positive(p.robot_width_m, "footprint.robot_width_m");
  positive(p.robot_length_m, "footprint.robot_length_m");
  at_least(p.turning_radius_m, 0.0, "footprint.turning_radius_m");
}

void validate(const RoomParams& p) {
  positive(p.door_max_width_m, "rooms.door_max_width_m");
  at_least(p.neck_ratio, 1.0, "rooms.neck_ratio");
  at_least(p.min_core_area_m2, 0.0, "rooms.min_core_area_m2");
  at_least(p.min_room_area_m2, 0.0, "rooms.min_room_area_m2");
  at_least(p.clutter_max_area_m2, 0.0, "rooms.clutter_max_area_m2");
}

void validate(const CorridorParams& p) {
  positive(p.max_width_m, "corridors.max_width_m");
  at_least(p.min_elongation, 1.0, "corridors.min_elongation");
  at_least(p.corner_min_deg, 1.0, "corridors.corner_min_deg");
  if (!(p.corner_min_deg < 180.0)) throw UsageError("corridors.corner_min_deg must be below 180");
  positive(p.fan_step_deg, "corridors.fan_step_deg");
  if (!(p.fan_min_deg <= p.fan_max_deg) || p.fan_min_deg < -180.0 || p.fan_max_deg > 180.0)
    throw UsageError("corridors.fan_min_deg .. fan_max_deg must be an interval within -180..180");
  positive(p.fan_travel_m, "corridors.fan_travel_m");
  at_least(p.side_turn_min_deg, 0.0, "corridors.side_turn_min_deg");
  at_least(p.crossing_margin_m, 0.0, "corridors.crossing_margin_m");
}

void validate(const AreasParams& p) {
  validate(p.footprint);
  validate(p.rooms);
  validate(p.corridors);
}

}  // namespace indoormap::areas
