#include "laser_outputs.hpp"

#include <cstdio>

#include "indoormap/draw/layout_png.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/formats/ros_map.hpp"
#include "indoormap/laser/mappers.hpp"

namespace indoormap::app {

using nlohmann::json;

namespace {

json cell_counts(const Grid<Cell>& cells) {
  std::size_t occupied = 0, free = 0, unknown = 0;
  for (int r = 0; r < cells.height; ++r)
    for (int c = 0; c < cells.width; ++c) {
      const Cell v = cells.at(c, r);
      if (laser::is_obstacle(v))
        ++occupied;
      else if (v == Cell::kFree)
        ++free;
      else
        ++unknown;
    }
  return {{"occupied", occupied}, {"free", free}, {"unknown", unknown}};
}

std::string method_name(laser::MapperKind k) {
  return k == laser::MapperKind::kHimm ? "himm" : "logodds";
}

}  // namespace

json refine_json(const std::vector<PoseRefineStats>& passes) {
  json out = json::array();
  for (const auto& p : passes)
    out.push_back({{"scans", p.scans},
                   {"scans_moved", p.scans_moved},
                   {"median_shift_m", p.median_shift_m},
                   {"max_shift_m", p.max_shift_m},
                   {"max_turn_deg", p.max_turn_deg}});
  return out;
}

json laser_map_json(const LaserMapRun& run) {
  const auto& r = run.check;
  const auto& g = run.map.geometry;
  return {
      {"log", run.log_path},
      {"method", method_name(run.config.method)},
      {"cell_m", g.cell_m()},
      {"scans_read", run.stats.scans},
      {"scans_mapped", run.scans_mapped},
      {"scans_skipped", run.scans_skipped},
      {"lines", run.stats.lines},
      {"other_messages_skipped", run.stats.skipped},
      {"pose_refine", refine_json(run.refine)},
      {"consistency",
       {{"beams_checked", r.beams_checked},
        {"beams_within", r.beams_within},
        {"within_share", r.within_share},
        {"within_m", r.within_m},
        {"within_cells", run.config.consistency.within_cells},
        {"median_abs_error_m", r.median_abs_error_m},
        {"mean_abs_error_m", r.mean_abs_error_m}}},
      {"grid",
       {{"width", g.width()},
        {"height", g.height()},
        {"resolution_m", g.cell_m()},
        {"origin_m", {g.origin_m().x(), g.origin_m().y()}},
        {"cells", cell_counts(run.map.cells)}}},
  };
}

std::vector<std::string> write_laser_map_outputs(const std::filesystem::path& out,
                                                 const LaserMapRun& run) {
  formats::write_ros_map(out, "map", run.map.cells, run.map.geometry);
  draw::RenderOptions ro;
  char share[96];
  std::snprintf(share, sizeof share, ", %.1f %% of beams within %g cells",
                run.check.within_share * 100.0, run.config.consistency.within_cells);
  ro.title = "laser-to-map " + method_name(run.config.method) + ": " +
             std::filesystem::path(run.log_path).filename().string() + share;
  draw::Overlay path;
  path.points_m = run.path_m;
  path.closed = false;
  path.rgb = {220, 30, 30};
  path.thickness_px = 1;
  ro.overlays.push_back(std::move(path));
  ro.legend.push_back({"robot path", {220, 30, 30}});
  draw::write_layout_png(out / "map.png", run.map.cells, run.map.geometry, ro);
  formats::write_json(out / "laser_map.json", laser_map_json(run));
  return {"map.pgm", "map.yaml", "map.png", "laser_map.json"};
}

}  // namespace indoormap::app
