#pragma once
// pcd-to-map --start / --goal: plans a route on the layout M_r just built and writes the route
// outputs next to the map (docs/plan-route.md): route.json, route.png, safe.pgm + safe.yaml.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "cli.hpp"
#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::app {

struct RouteOutputs {
  nlohmann::json summary;  ///< for summary.json: found, best route, files, timings
  bool found = false;
  std::string message;  ///< why there is no route
};

/// nullopt when no --start / --goal was given. Throws the planner's typed errors (start or goal
/// outside the map or unsafe: exit code 2).
std::optional<RouteOutputs> write_route_outputs(const std::filesystem::path& out,
                                                const PipelineCli& cli,
                                                const PipelineConfig& config,
                                                const Grid<Cell>& layout,
                                                const GridGeometry& geometry);

}  // namespace indoormap::app
