#include "eval_pair.hpp"

#include <optional>

#include "eval_rooms.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/formats/objects_json.hpp"
#include "indoormap/formats/pgm.hpp"
#include "indoormap/formats/room_geojson.hpp"
#include "indoormap/formats/ros_map.hpp"
#include "indoormap/sim/floor_eval.hpp"
#include "map_yaml.hpp"

namespace indoormap::map_eval {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

/// Grid geometry of a result layout: layout.yaml if present, else map.yaml (same grid), read by
/// the one map.yaml reader (app::read_map_yaml; the image it names is not opened).
GridGeometry result_geometry(const fs::path& dir, const Grid<std::uint8_t>& image,
                             std::string& source) {
  fs::path yaml = dir / "layout.yaml";
  if (!fs::exists(yaml)) yaml = dir / "map.yaml";
  if (!fs::exists(yaml))
    throw InputError(
        (dir / "map.yaml").string(),
        "missing: layout.pgm needs map.yaml (or layout.yaml) for its resolution and origin");
  source = yaml.filename().string();
  const formats::RosMapMeta meta = app::read_map_yaml(yaml);
  if (meta.origin.z() != 0.0)
    throw InputError(yaml.string(), "key 'origin': a rotated map (yaw != 0) is not supported");
  return GridGeometry({meta.origin.x(), meta.origin.y()}, meta.resolution_m, image.width,
                      image.height);
}

ordered_json opt(const std::optional<double>& v) {
  return v ? ordered_json(*v) : ordered_json(nullptr);
}

ordered_json layout_json(const sim::LayoutScores& s) {
  ordered_json j;
  ordered_json classes;
  for (int k = 0; k < 4; ++k) {
    const auto& c = s.classes[k];
    classes[std::string(to_string(static_cast<Cell>(k)))] = {{"iou", opt(c.iou)},
                                                             {"intersection_m2", c.intersection_m2},
                                                             {"union_m2", c.union_m2},
                                                             {"truth_m2", c.truth_m2},
                                                             {"result_m2", c.result_m2}};
  }
  j["classes"] = classes;
  j["mean_iou"] = opt(s.mean_iou);
  j["mean_iou_over"] = {"wall", "furniture", "free"};
  j["accuracy"] = s.accuracy;
  ordered_json conf;
  for (int t = 0; t < 4; ++t) {
    ordered_json row;
    for (int r = 0; r < 4; ++r)
      row[std::string(to_string(static_cast<Cell>(r)))] = s.confusion_m2[t][r];
    conf[std::string(to_string(static_cast<Cell>(t)))] = row;
  }
  j["confusion_m2"] = conf;
  j["confusion_rows"] = "truth class";
  j["confusion_columns"] = "result class";
  return j;
}

ordered_json objects_json(const sim::ObjectScores& s) {
  ordered_json j;
  j["truth_count"] = s.truth_count;
  j["result_count"] = s.result_count;
  j["matched"] = s.matched;
  j["matched_all"] = s.matched_all;  // with the matches of truth items below min_area: precision's
  j["recall"] = s.recall;
  j["precision"] = s.precision;
  j["mean_abs_z_max_error_m"] = opt(s.mean_abs_z_max_error_m);
  j["mean_abs_z_min_error_m"] = opt(s.mean_abs_z_min_error_m);
  j["max_abs_height_error_m"] = opt(s.max_abs_height_error_m);
  ordered_json m = ordered_json::array();
  for (const auto& x : s.matches)
    m.push_back({{"truth_id", x.truth_id},
                 {"result_id", x.result_id},
                 {"iou", x.iou},
                 {"z_min_error_m", opt(x.z_min_error_m)},
                 {"z_max_error_m", opt(x.z_max_error_m)}});
  j["matches"] = m;
  j["missed"] = s.missed;
  j["spurious"] = s.spurious;
  return j;
}

ordered_json rooms_json(const std::vector<sim::RoomMatch>& rooms) {
  ordered_json a = ordered_json::array();
  for (const auto& r : rooms) {
    ordered_json j;
    j["result_index"] = r.result_index;
    if (r.truth_index < 0) {
      j["truth_room"] = nullptr;
      j["note"] = "overlaps no truth room";
    } else {
      j["truth_room"] = r.truth_name;
      j["iou"] = r.iou;
      j["hausdorff_m"] = r.hausdorff_m;
      j["truth_area_m2"] = r.truth_area_m2;
      j["result_area_m2"] = r.result_area_m2;
      j["area_error_m2"] = r.area_error_m2;
      j["area_error_rel"] = r.area_error_rel;
    }
    a.push_back(j);
  }
  return a;
}

ordered_json null_note(const std::string& note) {
  return {{"value", nullptr}, {"note", note}};
}

ordered_json seen_json(const sim::SeenIou& s) {
  return {{"iou", opt(s.iou)},
          {"intersection_m2", s.intersection_m2},
          {"union_m2", s.union_m2},
          {"seen_m2", s.seen_m2}};
}

ordered_json faces_json(const sim::FaceScores& f) {
  return {{"face_recall", opt(f.face_recall)},
          {"wall_precision", opt(f.wall_precision)},
          {"truth_faces", f.truth_faces},
          {"result_walls", f.result_walls}};
}

/// A result grid with its geometry.
struct ResultGrid {
  GridGeometry geometry;
  Grid<Cell> cells;
};

/// The "floor" block: every metric that has its inputs; the others null with a note.
ordered_json floor_json(const formats::TruthFile& truth, const Grid<Cell>& truth_cells,
                        const std::optional<ResultGrid>& layout,
                        const std::optional<ResultGrid>& map, const PairParams& p) {
  ordered_json j;
  const GridGeometry& tg = truth.layout_geometry;
  const sim::Mask truth_free = sim::class_mask(truth_cells, Cell::kFree);
  const fs::path seen_file = truth.layout_image.parent_path() / "ground_truth_seen.pgm";
  std::optional<sim::Mask> seen;
  if (fs::exists(seen_file)) {
    sim::Mask raw = formats::read_pgm(seen_file);
    if (raw.width != tg.width() || raw.height != tg.height())
      throw InputError(seen_file.string(), "size differs from the truth layout's");
    for (auto& v : raw.data) v = v > 127;
    seen = std::move(raw);
  }
  const std::string no_seen = "no ground_truth_seen.pgm beside the truth layout";
  const std::string no_map = "no map.yaml with its image in the result";
  for (const auto& [name, grid] : {std::pair{"layout", &layout}, std::pair{"map", &map}}) {
    ordered_json k;
    if (!*grid) {
      k["seen_free_iou"] =
          null_note(name == std::string("map") ? no_map : "no layout.pgm in the result");
      j[name] = k;
      continue;
    }
    const ResultGrid& r = **grid;
    const sim::Mask free = sim::class_mask(r.cells, Cell::kFree);
    k["seen_free_iou"] =
        seen ? seen_json(sim::evaluate_seen_free(tg, truth_free, *seen, r.geometry, free))
             : null_note(no_seen);
    k["free_iou_all"] =
        seen_json(sim::evaluate_seen_free(tg, truth_free, truth_free, r.geometry, free));
    if (seen) {
      const sim::FarFree ff = sim::evaluate_far_free(tg, *seen, r.geometry, free, p.far_free_m);
      k["far_free"] = {{"far_m", p.far_free_m},
                       {"far_m2", ff.far_m2},
                       {"free_m2", ff.free_m2},
                       {"share", opt(ff.share)}};
    } else {
      k["far_free"] = null_note(no_seen);
    }
    const sim::FurnitureFree ff = sim::evaluate_furniture_free(tg, truth_cells, r.geometry, free);
    k["furniture_free"] = {
        {"furniture_m2", ff.furniture_m2}, {"free_m2", ff.free_m2}, {"share", opt(ff.share)}};
    k["wall_faces"] = faces_json(sim::evaluate_wall_faces(tg, truth_cells, r.geometry,
                                                          sim::class_mask(r.cells, Cell::kWall)));
    j[name] = k;
  }
  if (!map) {
    j["doors"] = null_note(no_map);
    j["reachability"] = null_note(no_map);
    return j;
  }
  const sim::Mask free = sim::class_mask(map->cells, Cell::kFree);
  const sim::DoorScores d = sim::evaluate_doors(truth.doors, map->geometry, free, p.robot_width_m);
  ordered_json dl = ordered_json::array();
  for (const auto& x : d.list) dl.push_back({{"id", x.id}, {"open", x.open}});
  j["doors"] = {
      {"doors", d.doors}, {"open", d.open}, {"open_share", opt(d.open_share)}, {"list", dl}};
  const sim::ReachScores r =
      sim::evaluate_reachability(truth.scanners_xy_m, map->geometry, free, p.robot_width_m);
  j["reachability"] = {
      {"scanners", r.scanners},   {"components", r.components},
      {"unplaced", r.unplaced},   {"all_reachable", r.all_reachable},
      {"component", r.component}, {"free_space", "map.pgm free cells eroded by the robot radius"}};
  return j;
}

}  // namespace

PairReport evaluate_pair(const formats::TruthFile& truth, const fs::path& dir,
                         const PairParams& p) {
  PairReport out;
  ordered_json& report = out.json;
  std::optional<ResultGrid> layout, map;
  // Layout (the result's file is read first: its problems are reported before the truth's).
  std::string source;
  if (fs::exists(dir / "layout.pgm")) {
    const Grid<std::uint8_t> raw = formats::read_pgm(dir / "layout.pgm");
    const GridGeometry rg = result_geometry(dir, raw, source);
    layout = ResultGrid{rg, formats::read_layout_pgm(dir / "layout.pgm", rg)};
  }
  const Grid<Cell> truth_cells =
      formats::read_layout_pgm(truth.layout_image, truth.layout_geometry);
  if (layout) {
    const GridGeometry& rg = layout->geometry;
    ordered_json j = {{"status", "ok"}, {"file", "layout.pgm"}, {"geometry_from", source}};
    j.update(
        layout_json(sim::evaluate_layout(truth.layout_geometry, truth_cells, rg, layout->cells)));
    report["layout"] = j;
    ++out.evaluated;
  } else {
    report["layout"] = {{"status", "missing"}, {"file", "layout.pgm"}};
    out.missing.push_back("layout.pgm");
  }
  // Objects.
  if (fs::exists(dir / "objects.json")) {
    // Without --include-hanging both sides are what stands on the floor (sim::evaluate_objects).
    const auto objects = formats::read_objects_json(dir / "objects.json");
    ordered_json j = {{"status", "ok"}, {"file", "objects.json"}};
    j.update(objects_json(sim::evaluate_objects(truth.furniture, objects, p.eval)));
    report["objects"] = j;
    ++out.evaluated;
  } else {
    report["objects"] = {{"status", "missing"}, {"file", "objects.json"}};
    out.missing.push_back("objects.json");
  }
  // Room polygons.
  if (fs::exists(dir / "room.geojson")) {
    const auto rooms = formats::read_room_geojson(dir / "room.geojson");
    ordered_json j = {{"status", rooms.empty() ? "empty" : "ok"}, {"file", "room.geojson"}};
    j["rooms"] = rooms_json(sim::evaluate_rooms(truth.rooms, rooms));
    report["room"] = j;
    ++out.evaluated;
  } else {
    report["room"] = {{"status", "missing"}, {"file", "room.geojson"}};
    out.missing.push_back("room.geojson");
  }
  // The rooms of the floor (rooms.geojson; "missing" status, not in "missing": older runs).
  report["rooms"] = evaluate_rooms_block(truth, dir, p.eval);
  // The navigation map.
  const auto map_image = [&] {
    const fs::path img = app::read_map_yaml(dir / "map.yaml").image;
    return img.is_absolute() ? img : dir / img;
  };
  if (fs::exists(dir / "map.yaml") && fs::exists(map_image())) {
    const formats::RosMap m = app::read_ros_map(dir / "map.yaml");
    if (m.meta.origin.z() != 0.0)
      throw InputError((dir / "map.yaml").string(),
                       "key 'origin': a rotated map (yaw != 0) is not supported");
    map = ResultGrid{m.geometry, m.cells};
    ++out.evaluated;
  }  // else: the floor block's map metrics are null with a note (not in "missing": older runs)
  report["floor"] = floor_json(truth, truth_cells, layout, map, p);
  report["missing"] = out.missing;
  return out;
}

}  // namespace indoormap::map_eval
