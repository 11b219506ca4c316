#include "objects_outputs.hpp"

#include <array>
#include <iomanip>
#include <sstream>

#include "indoormap/cloud_io/write.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/io/map_io.hpp"
#include "indoormap/io/render.hpp"

namespace indoormap::app {

namespace fs = std::filesystem;
using nlohmann::json;

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

std::vector<std::string> write_object_outputs(const fs::path& out, const layout::MapResult& map,
                                              const objects::ObjectsResult& res,
                                              const ObjectOutputs& what) {
  std::vector<std::string> written;
  json list = json::array();
  std::vector<std::vector<std::size_t>> crops;
  if (what.input_points)
    crops = objects::crop_indices(res, map.geometry, map.cloud_map.points, what.crop_margin_m);
  if (what.input_points) fs::create_directories(out / "objects");
  for (std::size_t k = 0; k < res.objects.size(); ++k) {
    json j = object_json(res.objects[k]);
    if (what.input_points) {
      // Crops are in the input frame: the original points, picked by index.
      std::vector<Eigen::Vector3f> pts;
      pts.reserve(crops[k].size());
      for (auto i : crops[k]) pts.push_back((*what.input_points)[i]);
      const std::string name = "objects/object_" + std::to_string(res.objects[k].id) + ".pcd";
      cloud_io::write_pcd_binary(out / name, pts);
      j["crop_file"] = name;
      j["crop_points"] = pts.size();
      written.push_back(name);
    }
    list.push_back(j);
  }
  json doc = {{"frame", "map (levelled; see summary.json levelling.map_from_input)"},
              {"cell_m", map.geometry.cell_m()},
              {"count", res.objects.size()},
              {"objects", list}};
  io::write_json(out / "objects.json", doc);
  written.push_back("objects.json");

  if (what.csv) {
    std::ostringstream csv;
    csv << std::setprecision(6)
        << "id,kind,cells,area_m2,center_x_m,center_y_m,length_m,width_m,angle_deg,z_min_m,z_max_m,"
           "point_count,touches_wall\n";
    for (const auto& o : res.objects) {
      csv << o.id << ',' << to_string(o.kind) << ',' << o.cells << ',' << o.area_m2 << ','
          << o.box.center_m.x() << ',' << o.box.center_m.y() << ',' << o.box.length_m << ','
          << o.box.width_m << ',' << o.box.angle_deg << ',';
      if (o.has_height)
        csv << o.z_min_m << ',' << o.z_max_m;
      else
        csv << ',';
      csv << ',' << o.point_count << ',' << (o.touches_wall ? "true" : "false") << '\n';
    }
    write_file_atomic(out / "objects.csv", csv.str());
    written.push_back("objects.csv");
  }
  if (what.picture) {
    io::RenderOptions ro;
    ro.title = "objects: " + std::to_string(res.objects.size());
    for (const auto& s : map.cloud_map.scanners) ro.markers_map.emplace_back(s.x(), s.y());
    // One colour per kind; the legend lists the kinds that occur.
    const std::vector<std::pair<std::string, std::array<std::uint8_t, 3>>> colours = {
        {"furniture", {170, 0, 150}}, {"pillar", {200, 30, 30}}, {"hanging", {0, 130, 200}},
        {"lamp", {0, 170, 170}},      {"column", {120, 60, 0}},  {"installation", {120, 60, 0}}};
    std::vector<bool> used(colours.size(), false);
    for (const auto& o : res.objects) {
      io::Overlay ov;
      ov.points_m = o.footprint_m;
      ov.label = std::to_string(o.id);
      std::size_t k = 0;
      while (k + 1 < colours.size() && colours[k].first != to_string(o.kind)) ++k;
      if (colours[k].first != to_string(o.kind)) k = 0;
      used[k] = true;
      ov.rgb = colours[k].second;
      ro.overlays.push_back(ov);
    }
    for (std::size_t k = 0; k < colours.size(); ++k)
      if (used[k] || k == 0) ro.legend.push_back({colours[k].first + " (id)", colours[k].second});
    io::write_layout_png(out / "objects.png", map.layout.layout, map.geometry, ro);
    written.push_back("objects.png");
  }
  return written;
}

void add_border_objects(objects::ObjectsResult& objs, const border::BorderResult& r) {
  if (!r.closed) return;
  for (const auto& io : r.interior_objects) {
    const Eigen::Vector2d centre = 0.5 * (io.min_m + io.max_m);
    if (!indoormap::contains(r.polygon_m, centre)) continue;
    bool covered = false;
    for (const auto& o : objs.objects)
      covered |=
          (centre.array() >= o.min_m.array()).all() && (centre.array() <= o.max_m.array()).all();
    if (covered) continue;
    objects::FurnitureObject o;
    o.id = static_cast<int>(objs.objects.size()) + 1;
    o.kind =
        io.kind == border::ComponentKind::kRing ? ObjectKind::kColumn : ObjectKind::kInstallation;
    o.cells = io.cells;
    o.start_cell = io.min;
    o.min_cell = io.min;
    o.max_cell = io.max;
    o.min_m = io.min_m;
    o.max_m = io.max_m;
    o.footprint_m = {
        io.min_m, {io.max_m.x(), io.min_m.y()}, io.max_m, {io.min_m.x(), io.max_m.y()}};
    const Eigen::Vector2d size = io.max_m - io.min_m;
    o.area_m2 = size.x() * size.y();
    o.box.center_m = centre;
    o.box.length_m = std::max(size.x(), size.y());
    o.box.width_m = std::min(size.x(), size.y());
    o.box.angle_deg = size.x() >= size.y() ? 0.0 : 90.0;
    // The border analysis keeps no per-cell mask: the crop region is the bounding box.
    for (int row = io.min.row; row <= io.max.row; ++row)
      for (int col = io.min.col; col <= io.max.col; ++col) o.own_cells.push_back({col, row});
    objs.objects.push_back(std::move(o));
  }
}

}  // namespace indoormap::app
