#include "scene_yaml.hpp"

#include <optional>
#include <string>
#include <vector>

#include "config_reader.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::scene_sim {

namespace {

/// The structure reader of the scene file: the shared rules of app::ConfigReader, plus the line
/// of every key path for the messages of check_scene. A key whose value is null is absent.
class Reader : public app::ConfigReader {
 public:
  Reader(std::string file, std::map<std::string, std::size_t>* lines)
      : app::ConfigReader(std::move(file)), lines_(lines) {}

  void note(const YAML::Node& n, const std::string& key) {
    if (lines_ && n.IsDefined() && n.Mark().line >= 0)
      (*lines_)[key] = static_cast<std::size_t>(n.Mark().line) + 1;
  }

  void opt(const YAML::Node& parent, const char* name, const std::string& key, double& out) {
    const YAML::Node n = parent[name];
    if (!n.IsDefined() || n.IsNull()) return;
    note(n, join(key, name));
    out = finite_number(n, join(key, name));
  }

  void opt(const YAML::Node& parent, const char* name, const std::string& key, bool& out) {
    const YAML::Node n = parent[name];
    if (!n.IsDefined() || n.IsNull()) return;
    out = boolean(n, join(key, name));
  }

  void opt(const YAML::Node& parent, const char* name, const std::string& key, std::string& out) {
    const YAML::Node n = parent[name];
    if (!n.IsDefined() || n.IsNull()) return;
    out = text(n, join(key, name));
  }

  const YAML::Node required(const YAML::Node& parent, const char* name, const std::string& key) {
    const YAML::Node n = parent[name];
    if (!n.IsDefined() || n.IsNull()) fail(parent, join(key, name), "missing");
    note(n, join(key, name));
    return n;
  }

  static std::string join(const std::string& a, const char* b) {
    return a.empty() ? b : a + "." + b;
  }

 private:
  std::map<std::string, std::size_t>* lines_;
};

/// The scanner keys, in documentation order: the scanner section of the config (-c) and the
/// scene file's own scanner block.
template <class F>
void visit_scanner(sim::ScannerParams& s, F&& f) {
  f("scanner", "azimuth_step_deg", app::finite(s.azimuth_step_deg));
  f("scanner", "elevation_step_deg", app::finite(s.elevation_step_deg));
  f("scanner", "elevation_min_deg", app::finite(s.elevation_min_deg));
  f("scanner", "elevation_max_deg", app::finite(s.elevation_max_deg));
  f("scanner", "range_min_m", app::finite(s.range_min_m));
  f("scanner", "range_max_m", app::finite(s.range_max_m));
  f("scanner", "range_sigma_m", app::finite(s.range_sigma_m));
  f("scanner", "mixed_pixel_probability", app::finite(s.mixed_pixel_probability));
  f("scanner", "mixed_pixel_min_jump_m", app::finite(s.mixed_pixel_min_jump_m));
  f("scanner", "coordinate_step_m", app::finite(s.coordinate_step_m));
}

/// Every key of the config file (-c, config/scene-sim.yaml), in documentation order.
template <class F>
void visit(Config& c, F&& f) {
  visit_scanner(c.scanner, f);
  f("output", "truth_cell_m", app::finite(c.output.truth_cell_m));
  f("output", "3dtk", c.output.write_3dtk);
  f("output", "sector_deg", app::finite(c.sector_deg));
  f("random", "rooms", c.random.rooms);
  f("random", "max_yaw_deg", app::finite(c.random.max_yaw_deg));
  f("random", "max_tilt_deg", app::finite(c.random.max_tilt_deg));
  f("random", "l_shape_probability", app::finite(c.random.l_shape_probability));
  f("random", "sloped_ceiling_probability", app::finite(c.random.sloped_ceiling_probability));
  f("random", "scanner_in_corridor", c.random.scanner_in_corridor);
  f("building", "storeys", c.storeys);
  f("building", "slab_thickness_m", app::finite(c.slab_thickness_m));
  f("building", "same_footprint", c.same_footprint);
  f("mobile", "enabled", c.mobile);
  f("mobile", "step_m", app::finite(c.mobile_params.step_m));
  f("mobile", "ray_share", app::finite(c.mobile_params.ray_share));
  f("mobile", "beams", c.mobile_params.beams);
  f("mobile", "elevation_min_deg", app::finite(c.mobile_params.elevation_min_deg));
  f("mobile", "elevation_max_deg", app::finite(c.mobile_params.elevation_max_deg));
  f("mobile", "sensor_height_m", app::finite(c.mobile_params.sensor_height_m));
  f("mobile", "clearance_m", app::finite(c.mobile_params.clearance_m));
  f("mobile", "speed_m_s", app::finite(c.mobile_params.speed_m_s));
  f("seen", "min_height_m", app::finite(c.seen.min_height_m));
  f("seen", "max_height_m", app::finite(c.seen.max_height_m));
}

void read_scanner(Reader& rd, const YAML::Node& n, sim::ScannerParams& s) {
  std::vector<std::string> keys;
  visit_scanner(s, [&](const char*, const char* k, auto&&) { keys.emplace_back(k); });
  rd.only_keys(n, "scanner", keys);
  visit_scanner(
      s, [&](const char*, const char* k, app::Finite v) { rd.opt(n, k, "scanner", v.value); });
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
  const YAML::Node edge_node = rd.required(n, "edge", key);
  rd.finite_number(edge_node, key + ".edge");
  const auto edge = app::config_integer<int>(edge_node);  // a number: the one integer rule
  if (!edge || *edge < 0 || *edge > 1'000'000)
    rd.fail(edge_node, key + ".edge", "expected an edge index 0, 1, ...");
  o.edge = *edge;
  o.at_m = rd.finite_number(rd.required(n, "at_m", key), key + ".at_m");
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
  rd.only_keys(n, key,
               {"name", "kind", "polygon", "wall_thickness_m", "ceiling", "doors", "windows"});
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
      r.ceiling.height_m = rd.finite_number(c, ck);
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
  rd.only_keys(n, key,
               {"id", "type", "center", "size", "radius_m", "yaw_deg", "height_m", "seat_height_m",
                "drop_m", "thickness_m"});
  sim::Furniture f;
  const YAML::Node type = rd.required(n, "type", key);
  const auto parsed = type.IsScalar() ? sim::parse_furniture_type(type.Scalar()) : std::nullopt;
  if (!parsed)
    rd.fail(type, key + ".type",
            "expected one of desk, table, cabinet, shelf, box, chair, bin, pillar, lamp");
  f.type = *parsed;
  rd.opt(n, "id", key, f.id);
  f.center_m = rd.vec2(rd.required(n, "center", key), key + ".center");
  const bool round_only =
      f.type == sim::FurnitureType::kBin || f.type == sim::FurnitureType::kPillar;
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

}  // namespace

void apply_config_file(const std::string& file, Config& config) {
  app::read_config_file(file, [&](auto&& f) { visit(config, f); });
}

ParsedScene parse_scene_file(const std::string& file, const sim::ScannerParams& base_scanner) {
  const YAML::Node root = app::load_yaml_file(file, "the scene file");
  ParsedScene parsed;
  Reader rd(file, &parsed.key_lines);
  sim::Scene& scene = parsed.scene;
  scene.scanner = base_scanner;
  try {
    rd.only_keys(root, "", {"name", "seed", "tilt", "rooms", "furniture", "scanners", "scanner"});
    rd.opt(root, "name", "", scene.name);
    if (const YAML::Node s = root["seed"]; s.IsDefined()) {
      std::optional<std::uint64_t> seed;
      try {
        seed = app::config_integer<std::uint64_t>(s);
      } catch (const YAML::Exception&) {
      }
      if (!seed) rd.fail(s, "seed", "expected a non-negative integer");
      scene.seed = *seed;
    }
    if (const YAML::Node t = root["tilt"]; t.IsDefined() && !t.IsNull()) {
      rd.note(t, "tilt");
      rd.only_keys(t, "tilt", {"roll_deg", "pitch_deg"});
      rd.opt(t, "roll_deg", "tilt", scene.tilt.roll_deg);
      rd.opt(t, "pitch_deg", "tilt", scene.tilt.pitch_deg);
    }
    const YAML::Node rooms = rd.required(root, "rooms", "");
    if (!rooms.IsSequence() || rooms.size() == 0)
      rd.fail(rooms, "rooms", "expected a non-empty list of rooms");
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
    if (!scanners.IsSequence() || scanners.size() == 0)
      rd.fail(scanners, "scanners", "expected a non-empty list");
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
  return parsed;
}

std::string config_to_yaml(const Config& config) {
  Config c = config;
  return app::config_to_yaml([&](auto&& f) { visit(c, f); });
}

}  // namespace indoormap::scene_sim
