#include "areas_outputs.hpp"

#include "indoormap/draw/areas_png.hpp"
#include "indoormap/formats/areas_geojson.hpp"
#include "indoormap/formats/costmap_masks.hpp"
#include "indoormap/formats/json.hpp"

namespace indoormap::app {

nlohmann::json score_json(const areas::SegmentationScore& s) {
  return {{"recall", s.recall},           {"precision", s.precision},
          {"true_rooms", s.true_rooms},   {"areas", s.areas},
          {"room_recall", s.room_recall}, {"area_precision", s.area_precision}};
}

nlohmann::json areas_summary_json(const GridAreasRun& run) {
  int n[3] = {0, 0, 0};
  for (const auto& a : run.result.areas) ++n[static_cast<int>(a.kind)];
  nlohmann::json j = {{"areas", run.result.areas.size()},
                      {"rooms", n[0]},
                      {"corridors", n[1]},
                      {"crossings", n[2]},
                      {"doors", run.result.doors.size()},
                      {"free_cells", run.result.free_cells},
                      {"reachable_cells", run.result.reachable_cells},
                      {"reachable_components", run.result.reachable_components},
                      {"graph_components", run.result.graph_components}};
  if (run.score)
    j["score"] = {{"truth", *run.truth_path},
                  {"recall", run.score->recall},
                  {"precision", run.score->precision}};
  return j;
}

std::vector<std::string> write_grid_areas_outputs(const std::filesystem::path& dir,
                                                  const GridAreasRun& run) {
  const auto& r = run.result;
  formats::write_areas_geojson(dir / "areas.geojson", r);
  formats::write_json(dir / "areas.json", formats::areas_json(r));
  formats::write_labels_png(dir / "areas_labels.png", r.labels);
  draw::write_areas_png(dir / "areas.png", r, run.map.cells, run.map.geometry,
                        std::filesystem::path(run.map_path).filename().string());
  formats::write_costmap_masks(dir, r, run.map.geometry, speed_percents(run.config));
  std::vector<std::string> files = {"areas.geojson",          "areas.json",
                                    "areas_labels.png",       "areas.png",
                                    "speed_mask.pgm",         "speed_mask.yaml",
                                    "speed_filter_info.yaml", "keepout_mask.pgm",
                                    "keepout_mask.yaml",      "keepout_filter_info.yaml"};
  if (run.score) {
    formats::write_json(dir / "score.json", score_json(*run.score));
    files.push_back("score.json");
  }
  return files;
}

}  // namespace indoormap::app
