#include "indoormap/formats/ground_truth_json.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "indoormap/core/polygon.hpp"
#include "indoormap/version.hpp"
#include "json_read.hpp"
#include "json_write.hpp"

namespace indoormap::formats {

namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;
using namespace sim;
using namespace detail;

namespace {

ordered_json xyz(const Eigen::Vector3d& p) {
  return ordered_json::array({p.x(), p.y(), p.z()});
}
ordered_json poly_json(const Polygon& poly) {
  ordered_json a = ordered_json::array();
  for (const auto& p : poly) a.push_back(xy_json<ordered_json>(p));
  return a;
}

ordered_json opening_json(const Room& room, const Opening& o, bool door) {
  const int n = static_cast<int>(room.polygon.size());
  const Eigen::Vector2d a = room.polygon[o.edge], b = room.polygon[(o.edge + 1) % n];
  const Eigen::Vector2d u = (b - a).normalized();
  ordered_json j;
  j["edge"] = o.edge;
  j["at_m"] = o.at_m;
  j["width_m"] = o.width_m;
  if (door) {
    j["height_m"] = o.top_m;
  } else {
    j["sill_m"] = o.bottom_m;
    j["top_m"] = o.top_m;
  }
  j["center"] = xy_json<ordered_json>(a + u * o.at_m);
  j["segment"] = ordered_json::array({xy_json<ordered_json>(a + u * (o.at_m - o.width_m / 2)),
                                      xy_json<ordered_json>(a + u * (o.at_m + o.width_m / 2))});
  return j;
}

ordered_json rooms_json(const Scene& scene, double* wall_height) {
  ordered_json rooms = ordered_json::array();
  for (std::size_t r = 0; r < scene.rooms.size(); ++r) {
    const Room& room = scene.rooms[r];
    double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
    for (const auto& v : room.polygon) {
      zmin = std::min(zmin, ceiling_z(room, v));
      zmax = std::max(zmax, ceiling_z(room, v));
    }
    *wall_height = std::max(*wall_height, zmax);
    ordered_json jr;
    jr["id"] = r;
    jr["name"] = room.name;
    jr["kind"] = room.kind == RoomKind::kCorridor ? "corridor" : "room";
    jr["polygon"] = poly_json(room.polygon);
    jr["area_m2"] = signed_area(room.polygon);
    jr["wall_thickness_m"] = room.wall_thickness_m;
    jr["floor_z_m"] = 0.0;
    jr["wall_height_m"] = zmax;
    jr["ceiling"] = {{"height_m", room.ceiling.height_m},
                     {"slope_deg", room.ceiling.slope_deg},
                     {"rise_azimuth_deg", room.ceiling.rise_azimuth_deg},
                     {"min_z_m", zmin},
                     {"max_z_m", zmax}};
    jr["doors"] = ordered_json::array();
    for (const auto& d : room.doors) jr["doors"].push_back(opening_json(room, d, true));
    jr["windows"] = ordered_json::array();
    for (const auto& w : room.windows) jr["windows"].push_back(opening_json(room, w, false));
    rooms.push_back(jr);
  }
  return rooms;
}

/// rooms[i].doors (optional): the opening segment and the outward normal of the host edge.
void read_doors(const json& room, const sim::TruthRoom& r, const fs::path& path,
                const std::string& key, std::vector<sim::TruthDoor>& out) {
  if (!room.contains("doors") || !room["doors"].is_array()) return;
  const double t = room.contains("wall_thickness_m")
                       ? number(room["wall_thickness_m"], path, key + ".wall_thickness_m")
                       : 0.2;
  const double orient = signed_area(r.polygon) >= 0 ? 1.0 : -1.0;
  for (std::size_t j = 0; j < room["doors"].size(); ++j) {
    const std::string k = key + ".doors[" + std::to_string(j) + "]";
    const json& seg = member(room["doors"][j], "segment", path, k);
    if (!seg.is_array() || seg.size() != 2) bad(path, k + ".segment", "expected two points");
    sim::TruthDoor d;
    d.id = r.name + ".door" + std::to_string(j);
    d.a = point(seg[0], path, k + ".segment[0]");
    d.b = point(seg[1], path, k + ".segment[1]");
    if ((d.b - d.a).norm() <= 0) bad(path, k + ".segment", "has no length");
    const Eigen::Vector2d u = (d.b - d.a).normalized();
    d.outward = orient * Eigen::Vector2d(u.y(), -u.x());
    d.wall_thickness_m = t;
    out.push_back(d);
  }
}

/// The optional scanners and storeys lists.
void read_floor_keys(const json& j, const fs::path& path, TruthFile& t) {
  if (j.contains("scanners") && j["scanners"].is_array())
    for (std::size_t i = 0; i < j["scanners"].size(); ++i) {
      const std::string k = "scanners[" + std::to_string(i) + "]";
      t.scanners_xy_m.push_back(
          point(member(j["scanners"][i], "position_m", path, k), path, k + ".position_m"));
    }
  if (!j.contains("storeys") || !j["storeys"].is_array()) return;
  for (std::size_t i = 0; i < j["storeys"].size(); ++i) {
    const std::string k = "storeys[" + std::to_string(i) + "]";
    const json& s = j["storeys"][i];
    TruthFile::Storey st;
    st.k = static_cast<int>(i);
    st.floor_z_m = number(member(s, "floor_z_m", path, k), path, k + ".floor_z_m");
    st.ceiling_z_m = number(member(s, "ceiling_z_m", path, k), path, k + ".ceiling_z_m");
    const json& g = member(s, "ground_truth", path, k);
    if (!g.is_string()) bad(path, k + ".ground_truth", "expected a file name");
    st.ground_truth = path.parent_path() / g.get<std::string>();
    t.storeys.push_back(st);
  }
}

TruthFile read_truth_json_unguarded(const fs::path& path) {
  const json j = parse_json_file(path);
  TruthFile t;
  t.path = path;
  if (!j.is_object() || j.value("format", "") != "indoormap-ground-truth")
    throw InputError(
        path.string(),
        "not a scene-sim ground truth (key 'format' must be \"indoormap-ground-truth\")");
  const json& rooms = member(j, "rooms", path, "");
  if (!rooms.is_array()) bad(path, "rooms", "expected a list");
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    const std::string key = "rooms[" + std::to_string(i) + "]";
    sim::TruthRoom r;
    r.name = rooms[i].value("name", key);
    r.kind = rooms[i].value("kind", "room");
    r.polygon = polygon(member(rooms[i], "polygon", path, key), path, key + ".polygon");
    read_doors(rooms[i], r, path, key, t.doors);
    t.rooms.push_back(std::move(r));
  }
  const json& furniture = member(j, "furniture", path, "");
  if (!furniture.is_array()) bad(path, "furniture", "expected a list");
  for (std::size_t i = 0; i < furniture.size(); ++i) {
    const std::string key = "furniture[" + std::to_string(i) + "]";
    const json& f = furniture[i];
    sim::EvalObject o;
    o.id = f.value("id", key);
    o.type = f.value("type", "");
    o.footprint = polygon(member(f, "footprint", path, key), path, key + ".footprint");
    o.z_min_m = number(member(f, "z_min_m", path, key), path, key + ".z_min_m");
    o.z_max_m = number(member(f, "z_max_m", path, key), path, key + ".z_max_m");
    o.on_floor = f.value("on_floor", true);
    t.furniture.push_back(std::move(o));
  }
  const json& layout = member(j, "layout", path, "");
  const json& image = member(layout, "image", path, "layout");
  if (!image.is_string()) bad(path, "layout.image", "expected a file name");
  t.layout_image = path.parent_path() / image.get<std::string>();
  const double res =
      number(member(layout, "resolution", path, "layout"), path, "layout.resolution");
  const json& origin = member(layout, "origin", path, "layout");
  const Eigen::Vector2d o = point(origin, path, "layout.origin");
  const double w = number(member(layout, "width", path, "layout"), path, "layout.width");
  const double h = number(member(layout, "height", path, "layout"), path, "layout.height");
  if (!(res > 0) || w < 1 || h < 1 || w * h > 4e8)
    bad(path, "layout", "resolution / width / height out of range");
  t.layout_geometry = GridGeometry(o, res, static_cast<int>(w), static_cast<int>(h));
  read_floor_keys(j, path, t);
  return t;
}

}  // namespace

ordered_json ground_truth_json(const Scene& scene, const SimResult& sim, const TruthLayout& layout,
                               const std::string& generator) {
  const auto items = furniture_truth(scene);
  ordered_json j;
  j["format"] = "indoormap-ground-truth";
  j["format_version"] = 1;
  j["generator"] = generator + " " + kVersion;
  j["scene"] = scene.name;
  j["seed"] = scene.seed;
  j["frame"] =
      "scene frame: metres, right-handed, z up, floor at z = 0. The cloud is in the tilted frame: "
      "p_cloud = tilt.rotation * p_scene (rotation about the origin).";
  const Eigen::Matrix3d R = tilt_rotation(scene.tilt);
  ordered_json rot = ordered_json::array();
  for (int r = 0; r < 3; ++r) rot.push_back(ordered_json::array({R(r, 0), R(r, 1), R(r, 2)}));
  const double tilt_deg = std::acos(std::clamp(R(2, 2), -1.0, 1.0)) * 180.0 / std::acos(-1.0);
  j["tilt"] = {{"roll_deg", scene.tilt.roll_deg},
               {"pitch_deg", scene.tilt.pitch_deg},
               {"angle_deg", tilt_deg},
               {"convention", "R = Ry(pitch) * Rx(roll)"},
               {"rotation", rot}};
  double wall_height = 0.0;
  const ordered_json rooms = rooms_json(scene, &wall_height);
  j["wall_height_m"] = wall_height;
  j["rooms"] = rooms;
  ordered_json furn = ordered_json::array();
  for (std::size_t i = 0; i < items.size(); ++i) {
    const auto& t = items[i];
    const Furniture& f = scene.furniture[i];
    ordered_json jf;
    jf["id"] = t.id;
    jf["type"] = std::string(to_string(t.type));
    jf["footprint"] = poly_json(t.footprint);
    jf["z_min_m"] = t.z_min_m;
    jf["z_max_m"] = t.z_max_m;
    jf["on_floor"] = t.on_floor;
    jf["room"] = t.room;
    jf["center"] = xy_json<ordered_json>(f.center_m);
    jf["yaw_deg"] = f.yaw_deg;
    if (f.radius_m > 0 && (f.type == FurnitureType::kBin || f.type == FurnitureType::kPillar ||
                           f.type == FurnitureType::kTable || f.type == FurnitureType::kLamp)) {
      jf["radius_m"] = f.radius_m;
    } else {
      jf["size"] = xy_json<ordered_json>(f.size_m);
    }
    furn.push_back(jf);
  }
  j["furniture"] = furn;
  ordered_json scanners = ordered_json::array();
  for (std::size_t s = 0; s < scene.scanners.size(); ++s) {
    scanners.push_back(
        {{"position_m", xyz(scene.scanners[s].position_m)},
         {"position_cloud_m", xyz(s < sim.scanner_positions_m.size() ? sim.scanner_positions_m[s]
                                                                     : Eigen::Vector3d::Zero())},
         {"heading_deg", scene.scanners[s].heading_deg}});
  }
  j["scanners"] = scanners;
  const ScannerParams& sp = scene.scanner;
  j["scanner_model"] = {{"azimuth_step_deg", sp.azimuth_step_deg},
                        {"elevation_step_deg", sp.elevation_step_deg},
                        {"elevation_min_deg", sp.elevation_min_deg},
                        {"elevation_max_deg", sp.elevation_max_deg},
                        {"range_min_m", sp.range_min_m},
                        {"range_max_m", sp.range_max_m},
                        {"range_sigma_m", sp.range_sigma_m},
                        {"mixed_pixel_probability", sp.mixed_pixel_probability},
                        {"mixed_pixel_min_jump_m", sp.mixed_pixel_min_jump_m}};
  j["cloud"] = {{"file", kTruthCloud},
                {"frame", "tilted"},
                {"points", sim.points.size()},
                {"rays", sim.rays},
                {"mixed_pixels", sim.mixed_pixels},
                {"scans", sim.scans.size()}};
  const auto& g = layout.geometry;
  j["layout"] = {{"image", kTruthLayoutImage},
                 {"picture", kTruthLayoutPicture},
                 {"yaml", kTruthLayoutYaml},
                 {"resolution", g.cell_m()},
                 {"origin", ordered_json::array({g.origin_m().x(), g.origin_m().y(), 0.0})},
                 {"width", g.width()},
                 {"height", g.height()},
                 {"rows", "image row 0 = highest y"},
                 {"classes", {{"0", "unknown"}, {"1", "wall"}, {"2", "furniture"}, {"3", "free"}}}};
  return j;
}

ordered_json ground_truth_tdtk_json(const std::string& subdir, std::size_t scans) {
  return {{"directory", subdir},
          {"scans", scans},
          {"convention",
           "points in the scan's local frame (tilted frame minus the scanner position), "
           "3DTK units and axes (cm, left-handed, y up: x = -100 Y, y = 100 Z, z = 100 X); "
           ".pose = scanner position in the same units, Euler angles 0 0 0"}};
}

TruthFile read_truth_json(const fs::path& path) {
  return guarded(path, [&] { return read_truth_json_unguarded(path); });
}

}  // namespace indoormap::formats
