#include "scene_yaml.hpp"

#include <cmath>
#include <set>
#include <sstream>

#include "indoormap/core/errors.hpp"

namespace indoormap::scene_sim {

namespace {

/// Reads typed values out of one YAML document, naming file, key path and line on error.
class Reader {
 public:
  Reader(std::string file, std::map<std::string, std::size_t>* lines) : file_(std::move(file)), lines_(lines) {}

  [[noreturn]] void fail(const YAML::Node& n, const std::string& key, const std::string& problem) const {
    const std::size_t line = n.IsDefined() && n.Mark().line >= 0 ? static_cast<std::size_t>(n.Mark().line) + 1 : 0;
    throw InputError(file_, "key '" + key + "': " + problem, line);
  }

  void note(const YAML::Node& n, const std::string& key) {
    if (lines_ && n.IsDefined() && n.Mark().line >= 0) (*lines_)[key] = static_cast<std::size_t>(n.Mark().line) + 1;
  }

  /// Every key of map n must be in allowed (catches typos such as "heigth_m").
  void only_keys(const YAML::Node& n, const std::string& key, std::initializer_list<const char*> allowed) const {
    if (!n.IsMap()) fail(n, key, "expected a mapping");
    for (const auto& kv : n) {
      const std::string k = kv.first.as<std::string>();
      bool ok = false;
      for (const char* a : allowed) ok = ok || k == a;
      if (!ok) {
        std::string list;
        for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
        fail(kv.first, key.empty() ? k : key + "." + k, "unknown key (expected one of: " + list + ")");
      }
    }
  }

  double number(const YAML::Node& n, const std::string& key) const {
    if (!n.IsScalar()) fail(n, key, "expected a number");
    double v = 0;
    try {
      v = n.as<double>();
    } catch (const YAML::Exception&) {
      fail(n, key, "expected a number, got '" + n.Scalar() + "'");
    }
    if (!std::isfinite(v)) fail(n, key, "must be finite");
    return v;
  }

  void opt(const YAML::Node& parent, const char* name, const std::string& key, double& out) {
    const YAML::Node n = parent[name];
    if (!n.IsDefined() || n.IsNull()) return;
    note(n, join(key, name));
    out = number(n, join(key, name));
  }

  void opt(const YAML::Node& parent, const char* name, const std::string& key, bool& out) {
    const YAML::Node n = parent[name];
    if (!n.IsDefined() || n.IsNull()) return;
    try {
      out = n.as<bool>();
    } catch (const YAML::Exception&) {
      fail(n, join(key, name), "expected true or false");
    }
  }

  void opt(const YAML::Node& parent, const char* name, const std::string& key, int& out) {
    double v = out;
    opt(parent, name, key, v);
    if (v != std::floor(v) || std::abs(v) > 1e9) fail(parent[name], join(key, name), "expected an integer");
    out = static_cast<int>(v);
  }

  void opt(const YAML::Node& parent, const char* name, const std::string& key, std::string& out) {
    const YAML::Node n = parent[name];
    if (!n.IsDefined() || n.IsNull()) return;
    if (!n.IsScalar()) fail(n, join(key, name), "expected a string");
    out = n.Scalar();
  }

  const YAML::Node required(const YAML::Node& parent, const char* name, const std::string& key) {
    const YAML::Node n = parent[name];
    if (!n.IsDefined() || n.IsNull()) fail(parent, join(key, name), "missing");
    note(n, join(key, name));
    return n;
  }

  Eigen::Vector2d vec2(const YAML::Node& n, const std::string& key) const {
    if (!n.IsSequence() || n.size() != 2) fail(n, key, "expected [x, y]");
    return {number(n[0], key + "[0]"), number(n[1], key + "[1]")};
  }

  Eigen::Vector3d vec3(const YAML::Node& n, const std::string& key) const {
    if (!n.IsSequence() || n.size() != 3) fail(n, key, "expected [x, y, z]");
    return {number(n[0], key + "[0]"), number(n[1], key + "[1]"), number(n[2], key + "[2]")};
  }

  static std::string join(const std::string& a, const char* b) { return a.empty() ? b : a + "." + b; }

 private:
  std::string file_;
  std::map<std::string, std::size_t>* lines_;
};

void read_scanner(Reader& rd, const YAML::Node& n, sim::ScannerParams& s) {
  const std::string k = "scanner";
  rd.only_keys(n, k, {"azimuth_step_deg", "elevation_step_deg", "elevation_min_deg", "elevation_max_deg", "range_min_m",
                      "range_max_m", "range_sigma_m", "mixed_pixel_probability", "mixed_pixel_min_jump_m"});
  rd.opt(n, "azimuth_step_deg", k, s.azimuth_step_deg);
  rd.opt(n, "elevation_step_deg", k, s.elevation_step_deg);
  rd.opt(n, "elevation_min_deg", k, s.elevation_min_deg);
  rd.opt(n, "elevation_max_deg", k, s.elevation_max_deg);
  rd.opt(n, "range_min_m", k, s.range_min_m);
  rd.opt(n, "range_max_m", k, s.range_max_m);
  rd.opt(n, "range_sigma_m", k, s.range_sigma_m);
  rd.opt(n, "mixed_pixel_probability", k, s.mixed_pixel_probability);
  rd.opt(n, "mixed_pixel_min_jump_m", k, s.mixed_pixel_min_jump_m);
}

sim::Opening read_opening(Reader& rd, const YAML::Node& n, const std::string& key, bool door) {
  if (door) {
    rd.only_keys(n, key, {"edge", "at_m", "width_m", "height_m"});
  } else {
    rd.only_keys(n, key, {"edge", "at_m", "width_m", "sill_m", "top_m"});
  }
  sim::Opening o;
  if (!door) {
    o.bottom_m = 0.9;
    o.top_m = 2.2;
    o.width_m = 1.2;
  }
  double edge = rd.number(rd.required(n, "edge", key), key + ".edge");
  if (edge != std::floor(edge) || edge < 0 || edge > 1e6) rd.fail(n["edge"], key + ".edge", "expected an edge index 0, 1, ...");
  o.edge = static_cast<int>(edge);
  o.at_m = rd.number(rd.required(n, "at_m", key), key + ".at_m");
  rd.opt(n, "width_m", key, o.width_m);
  if (door) {
    rd.opt(n, "height_m", key, o.top_m);
  } else {
    rd.opt(n, "sill_m", key, o.bottom_m);
    rd.opt(n, "top_m", key, o.top_m);
  }
  return o;
}

sim::Room read_room(Reader& rd, const YAML::Node& n, const std::string& key) {
  rd.only_keys(n, key, {"name", "kind", "polygon", "wall_thickness_m", "ceiling", "doors", "windows"});
  sim::Room r;
  r.name = key;
  rd.opt(n, "name", key, r.name);
  std::string kind = "room";
  rd.opt(n, "kind", key, kind);
  if (kind == "room") {
    r.kind = sim::RoomKind::kRoom;
  } else if (kind == "corridor") {
    r.kind = sim::RoomKind::kCorridor;
  } else {
    rd.fail(n["kind"], key + ".kind", "expected 'room' or 'corridor'");
  }
  const YAML::Node poly = rd.required(n, "polygon", key);
  if (!poly.IsSequence()) rd.fail(poly, key + ".polygon", "expected a list of [x, y] points");
  if (poly.size() > 10000) rd.fail(poly, key + ".polygon", "more than 10000 vertices");
  for (std::size_t i = 0; i < poly.size(); ++i)
    r.polygon.push_back(rd.vec2(poly[i], key + ".polygon[" + std::to_string(i) + "]"));
  rd.opt(n, "wall_thickness_m", key, r.wall_thickness_m);
  if (const YAML::Node c = n["ceiling"]; c.IsDefined() && !c.IsNull()) {
    const std::string ck = key + ".ceiling";
    rd.note(c, ck);
    if (c.IsScalar()) {
      r.ceiling.height_m = rd.number(c, ck);
    } else {
      rd.only_keys(c, ck, {"height_m", "slope_deg", "rise_azimuth_deg"});
      rd.opt(c, "height_m", ck, r.ceiling.height_m);
      rd.opt(c, "slope_deg", ck, r.ceiling.slope_deg);
      rd.opt(c, "rise_azimuth_deg", ck, r.ceiling.rise_azimuth_deg);
    }
  }
  for (int kind_i = 0; kind_i < 2; ++kind_i) {
    const char* name = kind_i == 0 ? "doors" : "windows";
    const YAML::Node list = n[name];
    if (!list.IsDefined() || list.IsNull()) continue;
    if (!list.IsSequence()) rd.fail(list, key + "." + name, "expected a list");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string k = key + "." + name + "[" + std::to_string(i) + "]";
      rd.note(list[i], k);
      (kind_i == 0 ? r.doors : r.windows).push_back(read_opening(rd, list[i], k, kind_i == 0));
    }
  }
  return r;
}

sim::Furniture read_furniture(Reader& rd, const YAML::Node& n, const std::string& key) {
  rd.only_keys(n, key, {"id", "type", "center", "size", "radius_m", "yaw_deg", "height_m", "seat_height_m", "drop_m",
                        "thickness_m"});
  sim::Furniture f;
  const YAML::Node type = rd.required(n, "type", key);
  if (!type.IsScalar() || !sim::parse_furniture_type(type.Scalar(), f.type))
    rd.fail(type, key + ".type", "expected one of desk, table, cabinet, shelf, box, chair, bin, pillar, lamp");
  rd.opt(n, "id", key, f.id);
  f.center_m = rd.vec2(rd.required(n, "center", key), key + ".center");
  const bool round_only = f.type == sim::FurnitureType::kBin || f.type == sim::FurnitureType::kPillar;
  if (n["size"].IsDefined()) {
    if (round_only) rd.fail(n["size"], key + ".size", "a bin / pillar is round: give radius_m");
    rd.note(n["size"], key + ".size");
    f.size_m = rd.vec2(n["size"], key + ".size");
  } else if (f.type == sim::FurnitureType::kChair) {
    f.size_m = {0.45, 0.45};
  } else if (!round_only && !n["radius_m"].IsDefined()) {
    rd.fail(n, key + ".size", "missing (or radius_m for a round table / lamp)");
  }
  rd.opt(n, "radius_m", key, f.radius_m);
  if (round_only && f.radius_m <= 0) rd.fail(n, key + ".radius_m", "missing");
  rd.opt(n, "yaw_deg", key, f.yaw_deg);
  rd.opt(n, "height_m", key, f.height_m);
  rd.opt(n, "seat_height_m", key, f.seat_height_m);
  rd.opt(n, "drop_m", key, f.drop_m);
  rd.opt(n, "thickness_m", key, f.thickness_m);
  return f;
}

void read_random(Reader& rd, const YAML::Node& n, sim::RandomSceneParams& p) {
  const std::string k = "random";
  rd.only_keys(n, k, {"rooms", "max_yaw_deg", "max_tilt_deg", "l_shape_probability", "sloped_ceiling_probability",
                      "scanner_in_corridor"});
  rd.opt(n, "rooms", k, p.rooms);
  rd.opt(n, "max_yaw_deg", k, p.max_yaw_deg);
  rd.opt(n, "max_tilt_deg", k, p.max_tilt_deg);
  rd.opt(n, "l_shape_probability", k, p.l_shape_probability);
  rd.opt(n, "sloped_ceiling_probability", k, p.sloped_ceiling_probability);
  rd.opt(n, "scanner_in_corridor", k, p.scanner_in_corridor);
}

void read_output(Reader& rd, const YAML::Node& n, Config& c) {
  const std::string k = "output";
  rd.only_keys(n, k, {"truth_cell_m", "3dtk", "sector_deg"});
  rd.opt(n, "truth_cell_m", k, c.output.truth_cell_m);
  rd.opt(n, "3dtk", k, c.output.write_3dtk);
  rd.opt(n, "sector_deg", k, c.sector_deg);
}

}  // namespace

YAML::Node load_yaml_file(const std::string& file) {
  try {
    return YAML::LoadFile(file);
  } catch (const YAML::BadFile&) {
    throw InputError(file, "cannot open");
  } catch (const YAML::Exception& e) {
    const std::size_t line = e.mark.line >= 0 ? static_cast<std::size_t>(e.mark.line) + 1 : 0;
    throw InputError(file, "invalid YAML: " + e.msg, line);
  }
}

void apply_config_file(const std::string& file, Config& config) {
  const YAML::Node root = load_yaml_file(file);
  if (root.IsNull()) return;  // an empty file changes nothing
  Reader rd(file, nullptr);
  try {
    rd.only_keys(root, "", {"scanner", "output", "random"});
    if (root["scanner"].IsDefined() && !root["scanner"].IsNull()) read_scanner(rd, root["scanner"], config.scanner);
    if (root["output"].IsDefined() && !root["output"].IsNull()) read_output(rd, root["output"], config);
    if (root["random"].IsDefined() && !root["random"].IsNull()) read_random(rd, root["random"], config.random);
  } catch (const YAML::Exception& e) {
    throw InputError(file, e.msg, e.mark.line >= 0 ? static_cast<std::size_t>(e.mark.line) + 1 : 0);
  }
}

sim::Scene parse_scene_file(const std::string& file, const sim::ScannerParams& base_scanner,
                            std::map<std::string, std::size_t>& key_lines) {
  const YAML::Node root = load_yaml_file(file);
  Reader rd(file, &key_lines);
  sim::Scene scene;
  scene.scanner = base_scanner;
  try {
    rd.only_keys(root, "", {"name", "seed", "tilt", "rooms", "furniture", "scanners", "scanner"});
    rd.opt(root, "name", "", scene.name);
    if (const YAML::Node s = root["seed"]; s.IsDefined()) {
      try {
        scene.seed = s.as<std::uint64_t>();
      } catch (const YAML::Exception&) {
        rd.fail(s, "seed", "expected a non-negative integer");
      }
    }
    if (const YAML::Node t = root["tilt"]; t.IsDefined() && !t.IsNull()) {
      rd.note(t, "tilt");
      rd.only_keys(t, "tilt", {"roll_deg", "pitch_deg"});
      rd.opt(t, "roll_deg", "tilt", scene.tilt.roll_deg);
      rd.opt(t, "pitch_deg", "tilt", scene.tilt.pitch_deg);
    }
    const YAML::Node rooms = rd.required(root, "rooms", "");
    if (!rooms.IsSequence() || rooms.size() == 0) rd.fail(rooms, "rooms", "expected a non-empty list of rooms");
    for (std::size_t i = 0; i < rooms.size(); ++i) {
      const std::string k = "rooms[" + std::to_string(i) + "]";
      rd.note(rooms[i], k);
      scene.rooms.push_back(read_room(rd, rooms[i], k));
    }
    if (const YAML::Node f = root["furniture"]; f.IsDefined() && !f.IsNull()) {
      if (!f.IsSequence()) rd.fail(f, "furniture", "expected a list");
      for (std::size_t i = 0; i < f.size(); ++i) {
        const std::string k = "furniture[" + std::to_string(i) + "]";
        rd.note(f[i], k);
        scene.furniture.push_back(read_furniture(rd, f[i], k));
      }
    }
    const YAML::Node scanners = rd.required(root, "scanners", "");
    if (!scanners.IsSequence() || scanners.size() == 0) rd.fail(scanners, "scanners", "expected a non-empty list");
    for (std::size_t i = 0; i < scanners.size(); ++i) {
      const std::string k = "scanners[" + std::to_string(i) + "]";
      rd.note(scanners[i], k);
      rd.only_keys(scanners[i], k, {"position", "heading_deg"});
      sim::ScannerPose p;
      p.position_m = rd.vec3(rd.required(scanners[i], "position", k), k + ".position");
      rd.opt(scanners[i], "heading_deg", k, p.heading_deg);
      scene.scanners.push_back(p);
    }
    if (const YAML::Node s = root["scanner"]; s.IsDefined() && !s.IsNull()) {
      rd.note(s, "scanner");
      read_scanner(rd, s, scene.scanner);
    }
  } catch (const YAML::Exception& e) {
    throw InputError(file, e.msg, e.mark.line >= 0 ? static_cast<std::size_t>(e.mark.line) + 1 : 0);
  }
  return scene;
}

std::string config_to_yaml(const Config& c) {
  YAML::Emitter e;
  e.SetDoublePrecision(15);
  e << YAML::BeginMap;
  e << YAML::Key << "scanner" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "azimuth_step_deg" << YAML::Value << c.scanner.azimuth_step_deg;
  e << YAML::Key << "elevation_step_deg" << YAML::Value << c.scanner.elevation_step_deg;
  e << YAML::Key << "elevation_min_deg" << YAML::Value << c.scanner.elevation_min_deg;
  e << YAML::Key << "elevation_max_deg" << YAML::Value << c.scanner.elevation_max_deg;
  e << YAML::Key << "range_min_m" << YAML::Value << c.scanner.range_min_m;
  e << YAML::Key << "range_max_m" << YAML::Value << c.scanner.range_max_m;
  e << YAML::Key << "range_sigma_m" << YAML::Value << c.scanner.range_sigma_m;
  e << YAML::Key << "mixed_pixel_probability" << YAML::Value << c.scanner.mixed_pixel_probability;
  e << YAML::Key << "mixed_pixel_min_jump_m" << YAML::Value << c.scanner.mixed_pixel_min_jump_m;
  e << YAML::EndMap;
  e << YAML::Key << "output" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "truth_cell_m" << YAML::Value << c.output.truth_cell_m;
  e << YAML::Key << "3dtk" << YAML::Value << c.output.write_3dtk;
  e << YAML::Key << "sector_deg" << YAML::Value << c.sector_deg;
  e << YAML::EndMap;
  e << YAML::Key << "random" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "rooms" << YAML::Value << c.random.rooms;
  e << YAML::Key << "max_yaw_deg" << YAML::Value << c.random.max_yaw_deg;
  e << YAML::Key << "max_tilt_deg" << YAML::Value << c.random.max_tilt_deg;
  e << YAML::Key << "l_shape_probability" << YAML::Value << c.random.l_shape_probability;
  e << YAML::Key << "sloped_ceiling_probability" << YAML::Value << c.random.sloped_ceiling_probability;
  e << YAML::Key << "scanner_in_corridor" << YAML::Value << c.random.scanner_in_corridor;
  e << YAML::EndMap;
  e << YAML::EndMap;
  return std::string(e.c_str()) + "\n";
}

}  // namespace indoormap::scene_sim
