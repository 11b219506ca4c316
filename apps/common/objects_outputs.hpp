#pragma once
// Writing the furniture objects (objects.json, objects.csv, objects.png, objects/object_<id>.pcd),
// shared by furniture-extract and pcd-to-map.
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "indoormap/border/border.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "indoormap/objects/objects.hpp"

namespace indoormap::app {

struct ObjectOutputs {
  bool csv = true;
  bool picture = true;
  /// Points of the input cloud, input frame, in the order make_map received them; when set, each
  /// object's crop is written to objects/object_<id>.pcd.
  const std::vector<Eigen::Vector3f>* input_points = nullptr;
  /// When set (the walls were aligned: every output in the map frame), the crops are turned by
  /// it (levelling.map_from_input) into the map frame; otherwise they stay in the input frame.
  /// objects.json's "crop_frame" says which.
  const Eigen::Matrix3d* crop_map_from_input = nullptr;
  double crop_margin_m = 0.05;
  /// When set (one per object, in the order of objects.objects): each object's "room_id" in
  /// objects.json (0: in no room; docs/pcd-to-map.md, "Rooms").
  const std::vector<int>* room_ids = nullptr;
};

/// Writes the chosen outputs into out (atomically, each; objects.json and objects.csv by
/// lib/formats, objects.png by lib/draw) and returns the list of files written.
std::vector<std::string> write_object_outputs(const std::filesystem::path& out,
                                              const layout::MapResult& map,
                                              const objects::ObjectsResult& objects,
                                              const ObjectOutputs& what);

/// The border analysis's interior objects that stand inside the closed room polygon and that no
/// listed object covers (its box's centre lies in none of their boxes) join the object list:
/// kind "column" for a closed ring (seen all round), "installation" otherwise; footprint = the
/// box, no heights; own_cells = the box's cells, so a crop holds the box's points at every
/// height. Boxes smaller than min_area_m2 (objects.min_area_m2) are not added. Nothing is added
/// when the border is not closed.
void add_border_objects(objects::ObjectsResult& objs, const border::BorderResult& r,
                        double min_area_m2);

}  // namespace indoormap::app
