#pragma once
// Furniture objects: objects.json and objects.csv (furniture-extract, pcd-to-map; the format is
// documented in docs/furniture-extract.md), and the objects.json reader of map-eval.
// The value types are only declared here: the writers' callers include
// indoormap/objects/objects.hpp (im_objects), the reader's indoormap/sim/eval.hpp (im_sim).
#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "indoormap/core/grid.hpp"

namespace indoormap::objects {
struct FurnitureObject;
struct ObjectsResult;
}  // namespace indoormap::objects
namespace indoormap::sim {
struct EvalObject;
}  // namespace indoormap::sim

namespace indoormap::formats {

/// One object as JSON (map metres).
nlohmann::json object_json(const objects::FurnitureObject& o);

/// Where an object's point crop was written (relative to the output directory), and its size.
struct ObjectCrop {
  std::string file;
  std::size_t points = 0;
};

/// objects.json: {frame, cell_m, count, objects: [object_json + crop_file, crop_points]}. crops
/// is empty, or holds one entry per object (in the order of objects.objects).
nlohmann::json objects_json(const objects::ObjectsResult& objects, const GridGeometry& geometry,
                            const std::vector<ObjectCrop>& crops = {});
void write_objects_json(const std::filesystem::path& path, const objects::ObjectsResult& objects,
                        const GridGeometry& geometry, const std::vector<ObjectCrop>& crops = {});

/// objects.csv: one line per object (id, kind, cells, area, box, heights, points, touches_wall).
std::string objects_csv(const objects::ObjectsResult& objects);
void write_objects_csv(const std::filesystem::path& path, const objects::ObjectsResult& objects);

/// Reads objects.json: {"objects": [{id, footprint [[x,y],...] | obb {center, width_m,
/// length_m, angle_deg}, z_min_m, z_max_m}]}. length_m runs along angle_deg (counter-clockwise
/// from +x). Objects of kind "hanging" or "lamp" are read with on_floor = false. Throws
/// InputError naming the file and the key.
std::vector<sim::EvalObject> read_objects_json(const std::filesystem::path& path);

}  // namespace indoormap::formats
