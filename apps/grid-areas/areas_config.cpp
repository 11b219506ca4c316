#include "areas_config.hpp"

#include "config_reader.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::app {

void merge_grid_areas_config_file(GridAreasConfig& config, const std::string& path) {
  read_config_file(path, [&](auto&& f) { visit_grid_areas(config, f); });
}

void validate(const GridAreasConfig& c) {
  areas::validate(c.areas);
  for (const auto& [v, key] : {std::pair{c.room_speed_percent, "speed.room_percent"},
                               std::pair{c.corridor_speed_percent, "speed.corridor_percent"},
                               std::pair{c.crossing_speed_percent, "speed.crossing_percent"}})
    if (!(v >= 1.0 && v <= 100.0))
      throw UsageError(std::string(key) + " must be within 1..100 (percent of the maximum speed)");
  if (c.free_min < 1 || c.free_min > 255) throw UsageError("map.free_min must be within 1..255");
}

formats::SpeedPercents speed_percents(const GridAreasConfig& c) {
  return {c.room_speed_percent, c.corridor_speed_percent, c.crossing_speed_percent};
}

std::string to_yaml(const GridAreasConfig& config) {
  GridAreasConfig c = config;
  return config_to_yaml([&](auto&& f) { visit_grid_areas(c, f); });
}

nlohmann::json to_json(const GridAreasConfig& config) {
  GridAreasConfig c = config;
  return config_to_json([&](auto&& f) { visit_grid_areas(c, f); });
}

}  // namespace indoormap::app
