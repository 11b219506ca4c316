#include "indoormap/formats/route_json.hpp"

#include "indoormap/formats/json.hpp"
#include "indoormap/formats/ros_map.hpp"

namespace indoormap::formats {

using nlohmann::json;
using planning::SafeCell;

namespace {

json pose_json(const planning::Pose2& p, CellIndex cell) {
  return {{"x_m", p.position_map.x()},
          {"y_m", p.position_map.y()},
          {"heading_deg", p.heading_deg ? json(*p.heading_deg) : json(nullptr)},
          {"cell", {cell.col, cell.row}}};
}

}  // namespace

json route_json(const RouteReport& rep) {
  const auto& res = *rep.result;
  json routes = json::array();
  int rank = 1;
  for (const auto& r : res.routes) {
    json cmds = json::array(), wps = json::array();
    for (const auto& c : r.commands)
      cmds.push_back({{"turn_deg", c.turn_deg}, {"move_m", c.move_m}});
    for (const auto& p : r.waypoints_map) wps.push_back({p.x(), p.y()});
    routes.push_back({{"rank", rank++},
                      {"source", r.source},
                      {"moves", r.moves},
                      {"turns", r.turns},
                      {"length_m", r.length_m},
                      {"commands", cmds},
                      {"waypoints_map", wps}});
  }
  return {
      {"found", !res.routes.empty()},
      {"message", res.message},
      {"frame", "map (metres); headings in degrees counter-clockwise from +x; turn_deg > 0 = left"},
      {"start", pose_json(rep.start, res.start_cell)},
      {"goal", pose_json(rep.goal, res.goal_cell)},
      {"routes", routes},
      {"search",
       {{"paper_best_moves", res.paper_best_moves},
        {"exact_best_moves", res.exact_best_moves},
        {"exact_complete", res.exact_complete},
        {"paper_nodes", res.paper_nodes},
        {"exact_nodes", res.exact_nodes}}},
      {"parameters",
       {{"robot",
         {{"width_m", rep.robot.width_m},
          {"length_m", rep.robot.length_m},
          {"extra_m", rep.robot.extra_m}}},
        {"d_save_m", planning::d_save_m(rep.robot)},
        {"d_min_m", rep.params.d_min_m},
        {"d_max_m", rep.params.d_max_m},
        {"cell_m", rep.geometry.cell_m()},
        {"paper_rules", rep.params.paper_rules},
        {"search", planning::to_string(rep.params.search)},
        {"max_routes", rep.params.max_routes},
        {"extra_moves", rep.params.extra_moves},
        {"max_nodes", rep.params.max_nodes}}},
  };
}

void write_route_json(const std::filesystem::path& path, const RouteReport& rep) {
  write_json(path, route_json(rep));
}

void write_safe_map(const std::filesystem::path& dir, const Grid<SafeCell>& safe,
                    const GridGeometry& geometry) {
  Grid<Cell> cells(safe.width, safe.height, Cell::kUnknown);
  for (std::size_t i = 0; i < safe.size(); ++i)
    cells.data[i] = safe.data[i] == SafeCell::kSafe      ? Cell::kFree
                    : safe.data[i] == SafeCell::kOutside ? Cell::kUnknown
                                                         : Cell::kWall;
  write_ros_map(dir, "safe", cells, geometry);
}

}  // namespace indoormap::formats
