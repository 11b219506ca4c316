#include "indoormap/formats/objects_json.hpp"

#include <iomanip>
#include <numbers>
#include <sstream>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/object_kind.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/objects/objects.hpp"
#include "indoormap/sim/eval.hpp"
#include "json_read.hpp"

namespace indoormap::formats {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace detail;

json object_json(const objects::FurnitureObject& o) {
  json fp = json::array();
  for (const auto& p : o.footprint_m) fp.push_back({p.x(), p.y()});
  json j = {
      {"id", o.id},
      {"kind", std::string(to_string(o.kind))},
      {"cells", o.cells},
      {"start_cell", {o.start_cell.col, o.start_cell.row}},
      {"bbox_cells",
       {{"min", {o.min_cell.col, o.min_cell.row}}, {"max", {o.max_cell.col, o.max_cell.row}}}},
      {"bbox_m", {{"min", {o.min_m.x(), o.min_m.y()}}, {"max", {o.max_m.x(), o.max_m.y()}}}},
      {"area_m2", o.area_m2},
      {"obb",
       {{"center", {o.box.center_m.x(), o.box.center_m.y()}},
        {"width_m", o.box.width_m},
        {"length_m", o.box.length_m},
        {"angle_deg", o.box.angle_deg}}},
      {"footprint", fp},
      {"point_count", o.point_count},
      {"seen_cells", o.seen_cells},
      {"surface_cells", o.surface_cells},
      {"touches_wall", o.touches_wall},
      {"on_floor", o.on_floor},
  };
  if (o.has_height) {
    j["z_min_m"] = o.z_min_m;
    j["z_max_m"] = o.z_max_m;
    j["height_m"] = o.z_max_m - o.z_min_m;
  } else {
    j["z_min_m"] = nullptr;
    j["z_max_m"] = nullptr;
    j["height_m"] = nullptr;
  }
  return j;
}

json objects_json(const objects::ObjectsResult& objects, const GridGeometry& geometry,
                  const std::vector<ObjectCrop>& crops) {
  json list = json::array();
  for (std::size_t k = 0; k < objects.objects.size(); ++k) {
    json j = object_json(objects.objects[k]);
    if (k < crops.size()) {
      j["crop_file"] = crops[k].file;
      j["crop_points"] = crops[k].points;
    }
    list.push_back(j);
  }
  return {{"frame", "map (levelled; see summary.json levelling.map_from_input)"},
          {"cell_m", geometry.cell_m()},
          {"count", objects.objects.size()},
          {"objects", list}};
}

void write_objects_json(const fs::path& path, const objects::ObjectsResult& objects,
                        const GridGeometry& geometry, const std::vector<ObjectCrop>& crops) {
  write_json(path, objects_json(objects, geometry, crops));
}

std::string objects_csv(const objects::ObjectsResult& objects) {
  std::ostringstream csv;
  csv << std::setprecision(6)
      << "id,kind,cells,area_m2,center_x_m,center_y_m,length_m,width_m,angle_deg,z_min_m,z_max_m,"
         "point_count,touches_wall\n";
  for (const auto& o : objects.objects) {
    csv << o.id << ',' << to_string(o.kind) << ',' << o.cells << ',' << o.area_m2 << ','
        << o.box.center_m.x() << ',' << o.box.center_m.y() << ',' << o.box.length_m << ','
        << o.box.width_m << ',' << o.box.angle_deg << ',';
    if (o.has_height)
      csv << o.z_min_m << ',' << o.z_max_m;
    else
      csv << ',';
    csv << ',' << o.point_count << ',' << (o.touches_wall ? "true" : "false") << '\n';
  }
  return csv.str();
}

void write_objects_csv(const fs::path& path, const objects::ObjectsResult& objects) {
  write_file_atomic(path, objects_csv(objects));
}

namespace {

std::vector<sim::EvalObject> read_objects_json_unguarded(const fs::path& path) {
  const json j = parse_json_file(path);
  const json& objects = member(j, "objects", path, "");
  if (!objects.is_array()) bad(path, "objects", "expected a list");
  std::vector<sim::EvalObject> out;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::string key = "objects[" + std::to_string(i) + "]";
    const json& o = objects[i];
    if (!o.is_object()) bad(path, key, "expected an object");
    sim::EvalObject e;
    if (o.contains("id"))
      e.id = o["id"].is_string() ? o["id"].get<std::string>() : o["id"].dump();
    else
      e.id = std::to_string(i);
    e.type = o.value("type", o.value("label", ""));
    // furniture-extract's "hanging" and "lamp" objects do not claim to stand on the floor.
    if (o.contains("kind") && o["kind"].is_string()) {
      const auto kind = parse_object_kind(o["kind"].get<std::string>());
      e.on_floor = !kind || stands_on_floor(*kind);
    }
    if (o.contains("footprint")) {
      e.footprint = polygon(o["footprint"], path, key + ".footprint");
    } else if (o.contains("obb")) {
      const json& b = o["obb"];
      const Eigen::Vector2d c =
          point(member(b, "center", path, key + ".obb"), path, key + ".obb.center");
      const double w = number(member(b, "width_m", path, key + ".obb"), path, key + ".obb.width_m");
      const double l =
          number(member(b, "length_m", path, key + ".obb"), path, key + ".obb.length_m");
      const double a =
          number(member(b, "angle_deg", path, key + ".obb"), path, key + ".obb.angle_deg");
      if (!(w > 0 && l > 0)) bad(path, key + ".obb", "width_m and length_m must be positive");
      e.footprint = rectangle(c, {l, w}, a * std::numbers::pi / 180.0);
    } else {
      bad(path, key, "needs 'footprint' or 'obb'");
    }
    // null: no height measured (what write_objects_json writes for such an object).
    if (o.contains("z_min_m") && !o["z_min_m"].is_null())
      e.z_min_m = number(o["z_min_m"], path, key + ".z_min_m");
    if (o.contains("z_max_m") && !o["z_max_m"].is_null())
      e.z_max_m = number(o["z_max_m"], path, key + ".z_max_m");
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace

std::vector<sim::EvalObject> read_objects_json(const fs::path& path) {
  return guarded(path, [&] { return read_objects_json_unguarded(path); });
}

}  // namespace indoormap::formats
