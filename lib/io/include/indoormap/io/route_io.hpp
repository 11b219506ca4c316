#pragma once
// Outputs of the route planner (docs/plan-route.md): route.json, route.png, safe.pgm + safe.yaml.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "indoormap/planning/planner.hpp"

namespace indoormap::io {

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

/// route.png: safe zone, trajectory region, the best route with numbered turns (and the other
/// routes thin), start and goal, a legend and a 1 m scale bar; north up.
void write_route_png(const std::filesystem::path& path, const RouteReport& report);

/// The safe zone as a ROS map: safe cells free (254), unsafe and obstacles occupied (0), outside
/// unknown (205); safe.pgm + safe.yaml with the input map's geometry.
void write_safe_map(const std::filesystem::path& dir, const Grid<planning::SafeCell>& safe,
                    const GridGeometry& geometry);

/// Writes route.json, route.png, safe.pgm and safe.yaml into dir (each atomically); returns the
/// file names written.
std::vector<std::string> write_route_outputs(const std::filesystem::path& dir,
                                             const RouteReport& report);

}  // namespace indoormap::io
