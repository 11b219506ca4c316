#include "indoormap/sim/scene.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "indoormap/core/angles.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/core/polygon.hpp"

namespace indoormap::sim {

namespace {

struct TypeName {
  FurnitureType type;
  std::string_view name;
};
constexpr TypeName kTypeNames[] = {
    {FurnitureType::kDesk, "desk"},       {FurnitureType::kTable, "table"},
    {FurnitureType::kCabinet, "cabinet"}, {FurnitureType::kShelf, "shelf"},
    {FurnitureType::kBox, "box"},         {FurnitureType::kChair, "chair"},
    {FurnitureType::kBin, "bin"},         {FurnitureType::kPillar, "pillar"},
    {FurnitureType::kLamp, "lamp"},
};

bool finite(double v) {
  return std::isfinite(v);
}
bool finite(const Eigen::Vector2d& v) {
  return v.allFinite();
}
}  // namespace

std::string_view to_string(FurnitureType t) {
  for (const auto& tn : kTypeNames)
    if (tn.type == t) return tn.name;
  return "invalid";
}

std::optional<FurnitureType> parse_furniture_type(std::string_view s) {
  for (const auto& tn : kTypeNames)
    if (tn.name == s) return tn.type;
  return std::nullopt;
}

double default_height_m(FurnitureType t) {
  switch (t) {
    case FurnitureType::kDesk:
      return 0.75;
    case FurnitureType::kTable:
      return 0.75;
    case FurnitureType::kCabinet:
      return 1.2;
    case FurnitureType::kShelf:
      return 1.9;
    case FurnitureType::kBox:
      return 0.5;
    case FurnitureType::kChair:
      return 0.9;
    case FurnitureType::kBin:
      return 0.4;
    case FurnitureType::kPillar:
      return 0.0;
    case FurnitureType::kLamp:
      return 0.0;
  }
  return 0.5;
}

Eigen::Matrix3d tilt_rotation(const Tilt& tilt) {
  return (Eigen::AngleAxisd(tilt.pitch_deg * kDeg, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(tilt.roll_deg * kDeg, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

double ceiling_z(const Room& room, const Eigen::Vector2d& p) {
  const double s = std::tan(room.ceiling.slope_deg * kDeg);
  if (s == 0.0) return room.ceiling.height_m;
  const Eigen::Vector2d dir(std::cos(room.ceiling.rise_azimuth_deg * kDeg),
                            std::sin(room.ceiling.rise_azimuth_deg * kDeg));
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& v : room.polygon) lowest = std::min(lowest, dir.dot(v));
  return room.ceiling.height_m + s * (dir.dot(p) - lowest);
}

int room_at(const Scene& scene, const Eigen::Vector2d& p) {
  for (std::size_t i = 0; i < scene.rooms.size(); ++i)
    if (scene.rooms[i].polygon.size() >= 3 && contains(scene.rooms[i].polygon, p))
      return static_cast<int>(i);
  return -1;
}

Scene normalised(Scene scene) {
  for (auto& room : scene.rooms) {
    if (room.polygon.size() < 3 || signed_area(room.polygon) >= 0) continue;
    const int n = static_cast<int>(room.polygon.size());
    std::vector<double> lengths(n);
    for (int e = 0; e < n; ++e) lengths[e] = (room.polygon[(e + 1) % n] - room.polygon[e]).norm();
    std::reverse(room.polygon.begin(), room.polygon.end());
    // Edge e (v_e -> v_e+1) becomes edge (n - 2 - e) mod n, run in the other direction.
    for (auto* list : {&room.doors, &room.windows}) {
      for (auto& o : *list) {
        if (o.edge < 0 || o.edge >= n) continue;  // reported by check_scene
        const double len = lengths[o.edge];
        o.edge = ((n - 2 - o.edge) % n + n) % n;
        o.at_m = len - o.at_m;
      }
    }
  }
  std::map<std::string, int> counters;
  std::set<std::string> used;
  for (const auto& f : scene.furniture)
    if (!f.id.empty()) used.insert(f.id);
  for (auto& f : scene.furniture) {
    if (!f.id.empty()) continue;
    const std::string base(to_string(f.type));
    std::string id;
    do {
      id = base + "_" + std::to_string(counters[base]++);
    } while (used.count(id));
    used.insert(id);
    f.id = id;
  }
  return scene;
}

namespace {

constexpr double kMaxExtent = 2000.0;  // metres from the origin; keeps grids bounded

// The problems of one room (its outline, ceiling, doors and windows).
void check_room(const Room& room, std::size_t r, std::vector<SceneProblem>& out) {
  auto bad = [&](std::string key, std::string problem) {
    out.push_back({std::move(key), std::move(problem)});
  };
  const std::string key = "rooms[" + std::to_string(r) + "]";
  if (room.polygon.size() < 3) {
    bad(key + ".polygon", "needs at least 3 vertices");
    return;
  }
  bool finite_ok = true;
  for (const auto& v : room.polygon)
    if (!finite(v) || std::abs(v.x()) > kMaxExtent || std::abs(v.y()) > kMaxExtent)
      finite_ok = false;
  if (!finite_ok) {
    bad(key + ".polygon", "vertices must be finite and within 2000 m of the origin");
    return;
  }
  if (!is_simple(room.polygon))
    bad(key + ".polygon", "edges cross or a vertex repeats (not a simple polygon)");
  if (std::abs(signed_area(room.polygon)) < 0.25) bad(key + ".polygon", "area below 0.25 m^2");
  if (!(room.wall_thickness_m > 0.0 && room.wall_thickness_m <= 2.0))
    bad(key + ".wall_thickness_m", "must be in (0, 2] m");
  // Very sharp corners make the mitred wall explode.
  const int n = static_cast<int>(room.polygon.size());
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = (room.polygon[i] - room.polygon[(i + n - 1) % n]).normalized();
    const Eigen::Vector2d b = (room.polygon[(i + 1) % n] - room.polygon[i]).normalized();
    if (a.dot(b) < -0.95)
      bad(key + ".polygon",
          "corner at vertex " + std::to_string(i) + " is sharper than ~18 degrees");
  }
  const Ceiling& c = room.ceiling;
  if (!(c.height_m >= 1.0 && c.height_m <= 50.0))
    bad(key + ".ceiling.height_m", "must be in [1, 50] m");
  if (!(c.slope_deg >= 0.0 && c.slope_deg <= 60.0))
    bad(key + ".ceiling.slope_deg", "must be in [0, 60] degrees");
  if (!finite(c.rise_azimuth_deg)) bad(key + ".ceiling.rise_azimuth_deg", "must be finite");
  double lowest_ceiling = std::numeric_limits<double>::infinity();
  for (const auto& v : room.polygon) lowest_ceiling = std::min(lowest_ceiling, ceiling_z(room, v));

  std::vector<std::vector<std::pair<double, double>>> spans(n);
  for (int kind = 0; kind < 2; ++kind) {
    const auto& list = kind == 0 ? room.doors : room.windows;
    const std::string what = kind == 0 ? ".doors[" : ".windows[";
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Opening& o = list[i];
      const std::string k = key + what + std::to_string(i) + "]";
      if (o.edge < 0 || o.edge >= n) {
        bad(k + ".edge", "no edge " + std::to_string(o.edge) + " (the polygon has " +
                             std::to_string(n) + " edges, 0-based)");
        continue;
      }
      const double len = (room.polygon[(o.edge + 1) % n] - room.polygon[o.edge]).norm();
      if (!(o.width_m > 0.05)) bad(k + ".width_m", "must be above 0.05 m");
      const double s0 = o.at_m - o.width_m / 2, s1 = o.at_m + o.width_m / 2;
      if (!(s0 >= room.wall_thickness_m && s1 <= len - room.wall_thickness_m))
        bad(k + ".at_m", "opening [" + std::to_string(s0) + ", " + std::to_string(s1) +
                             "] m must lie on the edge (length " + std::to_string(len) +
                             " m) at least one wall thickness from its ends");
      if (kind == 1 && !(o.bottom_m > 0.0)) bad(k + ".sill_m", "must be above 0 m");
      if (kind == 0 && o.bottom_m != 0.0) bad(k, "a door starts at the floor");
      if (!(o.top_m > o.bottom_m + 0.05 && o.top_m < lowest_ceiling))
        bad(k + (kind == 0 ? ".height_m" : ".top_m"),
            "must be above the bottom / sill and below the room's lowest ceiling point");
      for (const auto& [a, b] : spans[o.edge])
        if (s0 < b && a < s1)
          bad(k, "overlaps another door or window on edge " + std::to_string(o.edge));
      spans[o.edge].emplace_back(s0, s1);
    }
  }
}

void check_furniture(const Scene& scene, std::vector<SceneProblem>& out) {
  auto bad = [&](std::string key, std::string problem) {
    out.push_back({std::move(key), std::move(problem)});
  };
  std::set<std::string> ids;
  for (std::size_t i = 0; i < scene.furniture.size(); ++i) {
    const Furniture& f = scene.furniture[i];
    const std::string key = "furniture[" + std::to_string(i) + "]";
    if (!f.id.empty() && !ids.insert(f.id).second) bad(key + ".id", "duplicate id '" + f.id + "'");
    if (!finite(f.center_m)) {
      bad(key + ".center", "must be finite");
      continue;
    }
    const bool round =
        f.type == FurnitureType::kBin || f.type == FurnitureType::kPillar ||
        ((f.type == FurnitureType::kTable || f.type == FurnitureType::kLamp) && f.radius_m > 0);
    if (round) {
      if (!(f.radius_m > 0.01 && f.radius_m < 20))
        bad(key + ".radius_m", "must be in (0.01, 20) m");
    } else if (!(f.size_m.x() > 0.02 && f.size_m.y() > 0.02 && f.size_m.x() < 50 &&
                 f.size_m.y() < 50)) {
      bad(key + ".size", "both sides must be in (0.02, 50) m");
    }
    if (!finite(f.yaw_deg)) bad(key + ".yaw_deg", "must be finite");
    const int r = room_at(scene, f.center_m);
    if (r < 0) {
      bad(key + ".center", "lies in no room");
      continue;
    }
    const double ceil = ceiling_z(scene.rooms[r], f.center_m);
    const double h = f.height_m > 0 ? f.height_m : default_height_m(f.type);
    if (f.height_m < 0 || h > ceil) bad(key + ".height_m", "must be in [0, ceiling height] m");
    if (f.type == FurnitureType::kChair && !(f.seat_height_m > 0.1 && f.seat_height_m < h - 0.05))
      bad(key + ".seat_height_m", "must be above 0.1 m and below the backrest top (height_m)");
    if (f.type == FurnitureType::kLamp) {
      const double th = f.thickness_m > 0 ? f.thickness_m : 0.06;
      if (!(f.drop_m >= 0 && f.drop_m + th < ceil - 0.5))
        bad(key + ".drop_m", "lamp must hang at least 0.5 m above the floor");
    }
    if (f.thickness_m < 0 || f.thickness_m > 0.5)
      bad(key + ".thickness_m", "must be in [0, 0.5] m");
  }
}

void check_scanners(const Scene& scene, std::vector<SceneProblem>& out) {
  auto bad = [&](std::string key, std::string problem) {
    out.push_back({std::move(key), std::move(problem)});
  };
  if (scene.scanners.empty()) bad("scanners", "at least one scanner position is needed");
  for (std::size_t i = 0; i < scene.scanners.size(); ++i) {
    const auto& p = scene.scanners[i].position_m;
    const std::string key = "scanners[" + std::to_string(i) + "].position";
    if (!p.allFinite()) {
      bad(key, "must be finite");
      continue;
    }
    const int r = room_at(scene, p.head<2>());
    if (r < 0) {
      bad(key, "lies in no room");
      continue;
    }
    if (!(p.z() > 0.05 && p.z() < ceiling_z(scene.rooms[r], p.head<2>()) - 0.05))
      bad(key, "height must lie between the floor and the ceiling");
  }
}

}  // namespace

std::vector<SceneProblem> check_scene(const Scene& scene) {
  std::vector<SceneProblem> out;
  auto bad = [&](std::string key, std::string problem) {
    out.push_back({std::move(key), std::move(problem)});
  };

  if (scene.rooms.empty()) bad("rooms", "at least one room is needed");
  for (std::size_t r = 0; r < scene.rooms.size(); ++r) check_room(scene.rooms[r], r, out);
  check_furniture(scene, out);
  check_scanners(scene, out);

  const ScannerParams& s = scene.scanner;
  if (!(s.azimuth_step_deg >= 0.005 && s.azimuth_step_deg <= 10))
    bad("scanner.azimuth_step_deg", "must be in [0.005, 10]");
  if (!(s.elevation_step_deg >= 0.005 && s.elevation_step_deg <= 10))
    bad("scanner.elevation_step_deg", "must be in [0.005, 10]");
  if (!(s.elevation_min_deg >= -90 && s.elevation_max_deg <= 90 &&
        s.elevation_min_deg < s.elevation_max_deg))
    bad("scanner.elevation_min_deg", "need -90 <= elevation_min_deg < elevation_max_deg <= 90");
  if (!(s.range_min_m >= 0 && s.range_max_m > s.range_min_m && s.range_max_m <= 10000))
    bad("scanner.range_max_m", "need 0 <= range_min_m < range_max_m <= 10000");
  if (!(s.range_sigma_m >= 0 && s.range_sigma_m <= 1))
    bad("scanner.range_sigma_m", "must be in [0, 1] m");
  if (!(s.mixed_pixel_probability >= 0 && s.mixed_pixel_probability <= 1))
    bad("scanner.mixed_pixel_probability", "must be in [0, 1]");
  if (!(s.mixed_pixel_min_jump_m > 0)) bad("scanner.mixed_pixel_min_jump_m", "must be above 0");
  if (!(s.coordinate_step_m >= 0 && s.coordinate_step_m <= 0.1))
    bad("scanner.coordinate_step_m", "must be in [0, 0.1] m (0: float precision)");
  if (!(std::abs(scene.tilt.roll_deg) <= 30 && std::abs(scene.tilt.pitch_deg) <= 30))
    bad("tilt", "roll_deg and pitch_deg must be within +-30 degrees");
  return out;
}

void require_valid(const Scene& scene) {
  const auto problems = check_scene(scene);
  if (!problems.empty())
    throw UsageError("scene: " + problems.front().key + ": " + problems.front().problem);
}

}  // namespace indoormap::sim
