#include "route_outputs.hpp"

#include <chrono>

#include "indoormap/planning/planner.hpp"
#include "route_files.hpp"

namespace indoormap::app {

std::optional<RouteOutputs> write_route_outputs(const std::filesystem::path& out,
                                                const PipelineCli& cli,
                                                const PipelineConfig& config,
                                                const Grid<Cell>& layout,
                                                const GridGeometry& geometry) {
  if (cli.start.empty() && cli.goal.empty()) return std::nullopt;
  const planning::Pose2 start = parse_pose(cli.start, "--start");
  const planning::Pose2 goal = parse_pose(cli.goal, "--goal");
  const auto t0 = std::chrono::steady_clock::now();
  const auto& pc = config.plan;
  const auto templates = planning::make_templates(pc.robot, pc.planner, geometry.cell_m());
  const auto safe = planning::safe_zone(layout, templates.disk, pc.safe_zone);
  const auto result = planning::plan_routes(safe, geometry, start, goal, templates, pc.planner);
  const double plan_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const formats::RouteReport rep{&safe, geometry, start, goal, pc.robot, pc.planner, &result};
  const auto files = write_route_files(out, rep);
  RouteOutputs r;
  r.found = !result.routes.empty();
  r.message = result.message;
  nlohmann::json best = nullptr;
  if (r.found)
    best = {{"moves", result.routes[0].moves},
            {"turns", result.routes[0].turns},
            {"length_m", result.routes[0].length_m}};
  r.summary = {{"found", r.found},
               {"message", r.message},
               {"routes", result.routes.size()},
               {"best", best},
               {"d_save_m", planning::d_save_m(pc.robot)},
               {"plan_ms", plan_ms},
               {"outputs", files}};
  return r;
}

}  // namespace indoormap::app
