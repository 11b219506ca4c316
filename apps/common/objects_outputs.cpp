#include "objects_outputs.hpp"

#include "indoormap/cloud_io/write.hpp"
#include "indoormap/draw/objects_png.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/formats/objects_json.hpp"

namespace indoormap::app {

namespace fs = std::filesystem;

std::vector<std::string> write_object_outputs(const fs::path& out, const layout::MapResult& map,
                                              const objects::ObjectsResult& res,
                                              const ObjectOutputs& what) {
  std::vector<std::string> written;
  std::vector<formats::ObjectCrop> crops;
  if (what.input_points) {
    const auto indices =
        objects::crop_indices(res, map.geometry, map.cloud_map.points, what.crop_margin_m);
    fs::create_directories(out / "objects");
    for (std::size_t k = 0; k < res.objects.size(); ++k) {
      // Crops are the original points, picked by index: in the input frame, or turned into the
      // (wall-aligned) map frame.
      std::vector<Eigen::Vector3f> pts;
      pts.reserve(indices[k].size());
      for (auto i : indices[k]) pts.push_back((*what.input_points)[i]);
      if (what.crop_map_from_input) {
        const Eigen::Matrix3f r = what.crop_map_from_input->cast<float>();
        for (auto& p : pts) p = r * p;
      }
      const std::string name = "objects/object_" + std::to_string(res.objects[k].id) + ".pcd";
      cloud_io::write_pcd_binary(out / name, pts);
      crops.push_back({name, pts.size()});
      written.push_back(name);
    }
  }
  nlohmann::json j = formats::objects_json(res, map.geometry, crops);
  if (what.room_ids && what.room_ids->size() == res.objects.size())
    for (std::size_t k = 0; k < res.objects.size(); ++k)
      j["objects"][k]["room_id"] = (*what.room_ids)[k];
  if (map.level.align.applied)
    j["frame"] = "map (levelled and wall-aligned; see summary.json levelling.map_from_input)";
  if (what.input_points) j["crop_frame"] = what.crop_map_from_input ? "map" : "input";
  formats::write_json(out / "objects.json", j);
  written.push_back("objects.json");
  if (what.csv) {
    formats::write_objects_csv(out / "objects.csv", res);
    written.push_back("objects.csv");
  }
  if (what.picture) {
    draw::write_objects_png(out / "objects.png", map, res);
    written.push_back("objects.png");
  }
  return written;
}

void add_border_objects(objects::ObjectsResult& objs, const border::BorderResult& r,
                        double min_area_m2) {
  if (!r.closed) return;
  for (const auto& io : r.interior_objects) {
    const Eigen::Vector2d centre = 0.5 * (io.min_m + io.max_m);
    const Eigen::Vector2d extent = io.max_m - io.min_m;
    if (extent.x() * extent.y() < min_area_m2) continue;
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
