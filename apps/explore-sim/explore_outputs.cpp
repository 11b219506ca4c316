#include "explore_outputs.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "indoormap/core/errors.hpp"
#include "indoormap/draw/explore_png.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/formats/ros_map.hpp"

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace indoormap::app {

namespace {

double deg(double rad) {
  return rad * 180.0 / std::numbers::pi;
}

/// Rounds to 6 decimals so that the JSON stays short and identical across runs.
double r6(double v) {
  return std::round(v * 1e6) / 1e6;
}

ordered_json optional_number(const std::optional<double>& v) {
  return v ? ordered_json(r6(*v)) : ordered_json(nullptr);
}

/// The driven path, the start first.
std::vector<Eigen::Vector2d> path_points(const exploration::ExploreResult& r,
                                         const laser::Pose2d& start, std::size_t count) {
  std::vector<Eigen::Vector2d> pts{start.position_m()};
  for (std::size_t i = 0; i < count && i < r.path.size(); ++i)
    pts.push_back(r.path[i].position_m());
  return pts;
}

void write_path_geojson(const fs::path& file, const exploration::ExploreResult& r,
                        const ExploreRunInfo& info) {
  ordered_json line = ordered_json::array();
  for (const auto& p : path_points(r, info.start, r.path.size()))
    line.push_back({r6(p.x()), r6(p.y())});
  const ordered_json j = {
      {"type", "FeatureCollection"},
      {"features",
       {{{"type", "Feature"},
         {"properties", {{"name", "path"}, {"frame", "map"}, {"distance_m", r6(r.distance_m)}}},
         {"geometry", {{"type", "LineString"}, {"coordinates", line}}}},
        {{"type", "Feature"},
         {"properties", {{"name", "start"}, {"heading_deg", r6(deg(info.start.theta_rad))}}},
         {"geometry",
          {{"type", "Point"}, {"coordinates", {r6(info.start.x_m), r6(info.start.y_m)}}}}}}},
  };
  formats::write_json(file, j);
}

std::string caption(double t, double d, double share) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.0f s, %.0f m, %.0f %%", t, d, 100.0 * share);
  return buf;
}

/// Coverage (distance, share) at time t: the last sample at or before it.
exploration::CoverageSample coverage_at(const exploration::ExploreResult& r, double t) {
  exploration::CoverageSample s;
  for (const auto& c : r.coverage) {
    if (c.time_s > t + 1e-9) break;
    s = c;
  }
  return s;
}

/// The snapshots nearest to fixed shares (1/n, 2/n, .., 1) of the run's time.
std::vector<draw::ExplorePanel> strip_panels(const exploration::ExploreResult& r,
                                             const ExploreRunInfo& info) {
  std::vector<draw::ExplorePanel> panels;
  if (r.snapshots.empty()) return panels;
  const double step_s = info.control_period_s * static_cast<double>(info.path_sample_every);
  for (int i = 1; i <= info.strip_panels; ++i) {
    const double want = r.time_s * i / info.strip_panels;
    const exploration::MapSnapshot* best = &r.snapshots.front();
    for (const auto& s : r.snapshots)
      if (std::abs(s.time_s - want) < std::abs(best->time_s - want)) best = &s;
    const std::size_t n = i == info.strip_panels
                              ? r.path.size()
                              : static_cast<std::size_t>(std::floor(best->time_s / step_s + 1e-9));
    const auto cov = coverage_at(r, best->time_s);
    panels.push_back({best->cells, path_points(r, info.start, n), best->robot.position_m(),
                      caption(best->time_s, cov.distance_m, cov.explored_share)});
  }
  return panels;
}

}  // namespace

ordered_json explore_json(const exploration::ExploreResult& r, const ExploreRunInfo& info) {
  ordered_json series = ordered_json::array();
  for (const auto& c : r.coverage)
    series.push_back({{"time_s", r6(c.time_s)},
                      {"distance_m", r6(c.distance_m)},
                      {"explored_share", r6(c.explored_share)}});
  const double a = info.truth_cell_m * info.truth_cell_m;
  return {
      {"map", info.map_name},
      {"start",
       {{"x_m", r6(info.start.x_m)},
        {"y_m", r6(info.start.y_m)},
        {"heading_deg", r6(deg(info.start.theta_rad))},
        {"rule", info.start_rule}}},
      {"goal_rule", std::string(exploration::to_string(info.rule))},
      {"seed", info.seed},
      {"status", std::string(exploration::to_string(r.status))},
      {"explored_share", r6(r.explored_share)},
      {"reachable_free_m2", r6(static_cast<double>(r.reachable_cells) * a)},
      {"reached_95", r.distance_to_share(0.95).has_value()},
      {"distance_to_95_m", optional_number(r.distance_to_share(0.95))},
      {"time_to_95_s", optional_number(r.time_to_share(0.95))},
      {"distance_m", r6(r.distance_m)},
      {"time_s", r6(r.time_s)},
      {"goals", r.goals},
      {"blacklisted_frontiers", r.blacklisted_frontiers},
      {"obstacle_stops", r.obstacle_stops},
      {"collisions", r.collisions},
      {"navigator_runs", r.navigator_runs},
      {"series", series},
  };
}

std::vector<std::string> write_explore_files(const fs::path& dir,
                                             const exploration::ExploreResult& r,
                                             const ExploreRunInfo& info) {
  formats::write_ros_map(dir, "map", r.map.cells, r.map.geometry);
  write_path_geojson(dir / "path.geojson", r, info);
  formats::write_json(dir / "explore.json", explore_json(r, info));
  const draw::ExplorePanel final_map{
      r.map.cells, path_points(r, info.start, r.path.size()),
      r.path.empty() ? info.start.position_m() : r.path.back().position_m(), ""};
  const std::string title = "explore-sim: " + info.map_name + ", " +
                            std::string(exploration::to_string(info.rule)) + ", " +
                            caption(r.time_s, r.distance_m, r.explored_share);
  draw::write_explore_png(dir / "explore.png", final_map, r.map.geometry, info.start.position_m(),
                          title);
  draw::write_explore_strip_png(dir / "explore_strip.png", strip_panels(r, info), r.map.geometry,
                                "explore-sim: " + info.map_name + " over the run");
  return {"map.pgm",      "map.yaml",    "path.geojson",
          "explore.json", "explore.png", "explore_strip.png"};
}

}  // namespace indoormap::app
