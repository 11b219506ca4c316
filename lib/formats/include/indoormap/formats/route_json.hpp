#pragma once
// Outputs of the route planner (docs/plan-route.md): route.json and the safe zone as a ROS map
// (safe.pgm + safe.yaml). route.png is drawn by indoormap/draw/route_png.hpp from the same
// report. Users of this header link im_planning for the value types.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "indoormap/core/grid.hpp"
#include "indoormap/planning/planner.hpp"

namespace indoormap::formats {

/// Everything a route report shows.
struct RouteReport {
  const Grid<planning::SafeCell>* safe = nullptr;
  GridGeometry geometry;
  planning::Pose2 start, goal;
  planning::RobotParams robot;
  planning::PlannerParams params;
  const planning::PlanResult* result = nullptr;
};

/// route.json: the ranked routes (commands, waypoints in map metres, moves, turns, length) and
/// the parameters used (robot size, d_save_m, d_min_m, d_max_m).
nlohmann::json route_json(const RouteReport& report);
void write_route_json(const std::filesystem::path& path, const RouteReport& report);

/// The safe zone as a ROS map: safe cells free (254), unsafe and obstacles occupied (0), outside
/// unknown (205); safe.pgm + safe.yaml with the input map's geometry.
void write_safe_map(const std::filesystem::path& dir, const Grid<planning::SafeCell>& safe,
                    const GridGeometry& geometry);

}  // namespace indoormap::formats
