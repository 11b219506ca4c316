#include "indoormap/sim/random_scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "indoormap/core/angles.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/core/polygon.hpp"
#include "indoormap/sim/simulate.hpp"

namespace indoormap::sim {

namespace {

using V2 = Eigen::Vector2d;

/// Furniture placement inside one room, in the room's local axis-aligned frame.
struct Planner {
  Polygon polygon;
  std::vector<std::pair<V2, V2>> taken;  // AABBs (min, max) incl. clearance

  bool inside(const V2& lo, const V2& hi) const {
    for (int i = 0; i <= 4; ++i)
      for (int j = 0; j <= 4; ++j)
        if (!contains(polygon, V2(lo.x() + (hi.x() - lo.x()) * i / 4.0,
                                  lo.y() + (hi.y() - lo.y()) * j / 4.0)))
          return false;
    return true;
  }
  bool free(const V2& lo, const V2& hi) const {
    for (const auto& [a, b] : taken)
      if (lo.x() < b.x() && a.x() < hi.x() && lo.y() < b.y() && a.y() < hi.y()) return false;
    return true;
  }
  /// Reserves an axis-aligned box of full extent `ext` centred at c (with clearance) if possible.
  bool place(const V2& c, const V2& ext, double clearance = 0.08) {
    const V2 lo = c - ext / 2, hi = c + ext / 2;
    if (!inside(lo, hi)) return false;
    const V2 clo = lo.array() - clearance, chi = hi.array() + clearance;
    if (!free(clo, chi)) return false;
    taken.emplace_back(clo, chi);
    return true;
  }
};

Furniture item(FurnitureType type, const V2& c, const V2& size, double yaw_deg, double height = 0) {
  Furniture f;
  f.type = type;
  f.center_m = c;
  f.size_m = size;
  f.yaw_deg = yaw_deg;
  f.height_m = height;
  return f;
}

Furniture round_item(FurnitureType type, const V2& c, double r, double height = 0) {
  Furniture f;
  f.type = type;
  f.center_m = c;
  f.radius_m = r;
  f.height_m = height;
  return f;
}

struct LocalRoom {
  Room room;
  std::vector<Furniture> furniture;
  std::vector<ScannerPose> scanners;
};

/// The room's ceiling, outline (a rectangle, or an L) with its south wall on y = y0, the door
/// into the corridor (edge 0) and the windows in the north wall. Returns whether it is an L.
bool shape_room(Rng& rng, const RandomSceneParams& p, double x0, double y0, double w, double d,
                double t, Room& room) {
  room.ceiling.height_m = rng.uniform(2.6, 3.2);
  if (rng.uniform() < p.sloped_ceiling_probability) {
    room.ceiling.height_m = rng.uniform(2.4, 2.7);
    room.ceiling.slope_deg = rng.uniform(5, 15);
    room.ceiling.rise_azimuth_deg = rng.uniform_int(0, 3) * 90.0;
  }
  const bool l_shape = w >= 4.5 && d >= 4.0 && rng.uniform() < p.l_shape_probability;
  int north_edge = 2;
  double north_len = w;
  if (l_shape) {
    const double cx = rng.uniform(0.3, 0.45) * w, cy = rng.uniform(0.3, 0.45) * d;
    room.polygon = {{x0, y0},
                    {x0 + w, y0},
                    {x0 + w, y0 + d - cy},
                    {x0 + w - cx, y0 + d - cy},
                    {x0 + w - cx, y0 + d},
                    {x0, y0 + d}};
    north_edge = 4;
    north_len = w - cx;
  } else {
    room.polygon = {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + d}, {x0, y0 + d}};
  }
  // Door into the corridor (edge 0, the south wall).
  Opening door;
  door.edge = 0;
  door.width_m = rng.uniform(0.85, 1.0);
  door.top_m = rng.uniform(2.0, 2.15);
  const double margin = t + 0.3 + door.width_m / 2;
  door.at_m = rng.uniform(margin, w - margin);
  room.doors.push_back(door);
  // Windows in the north wall.
  const int nwin = rng.uniform_int(0, 2);
  const double lowest = room.ceiling.height_m;
  for (int k = 0; k < nwin; ++k) {
    // Window k sits in its share of the wall, at least a wall thickness + 0.1 m from its ends.
    const double share = north_len / nwin, start = k * share, margin_w = t + 0.1;
    Opening win;
    win.edge = north_edge;
    win.width_m = std::min(rng.uniform(1.0, 1.8), share - 2 * margin_w);
    if (win.width_m < 0.5) break;
    win.bottom_m = rng.uniform(0.8, 1.0);
    win.top_m = std::min(rng.uniform(2.0, 2.3), lowest - 0.2);
    win.at_m =
        rng.uniform(start + margin_w + win.width_m / 2, start + share - margin_w - win.width_m / 2);
    room.windows.push_back(win);
  }
  return l_shape;
}

/// The furniture of the room, placed where `plan` has space; lamps hang clear of the scanner.
void furnish_room(Rng& rng, Planner& plan, const Room& room, double x0, double y0, double w,
                  double d, const V2& scanner_xy, std::vector<Furniture>& F) {
  // Desks with chairs along the north wall(s): walk along y = y0 + d (or the L's lower top).
  const int ndesk = rng.uniform_int(1, 3);
  for (int k = 0; k < ndesk; ++k) {
    const double size_y = rng.uniform(0.7, 0.8);
    const V2 size(rng.uniform(1.2, 1.8), size_y);
    for (int attempt = 0; attempt < 20; ++attempt) {
      const double x = rng.uniform(x0 + size.x() / 2 + 0.05, x0 + w - size.x() / 2 - 0.05);
      // The top y at this x: the polygon's highest interior y (probe downwards).
      double ytop = y0 + d;
      while (ytop > y0 && !contains(room.polygon, V2(x, ytop - 0.01))) ytop -= 0.05;
      const V2 c(x, ytop - 0.02 - size.y() / 2);
      if (!plan.place(c, V2(size.x(), size.y() + 0.7))) continue;  // includes the chair's space
      F.push_back(item(FurnitureType::kDesk, c, size, 0));
      F.push_back(item(FurnitureType::kChair, c - V2(0, size.y() / 2 + 0.3), V2(0.45, 0.45),
                       90 + rng.uniform(-20, 20)));
      break;
    }
  }
  // Cabinets / shelves along the west and east walls.
  const int nstore = rng.uniform_int(1, 4);
  for (int k = 0; k < nstore; ++k) {
    const bool shelf = rng.uniform() < 0.5;
    const double depth = shelf ? rng.uniform(0.3, 0.45) : rng.uniform(0.45, 0.6);
    const double len = rng.uniform(0.8, 1.4);
    for (int attempt = 0; attempt < 20; ++attempt) {
      const bool west = rng.uniform() < 0.5;
      const double y = rng.uniform(y0 + len / 2 + 0.05, y0 + d - len / 2 - 0.05);
      double xw = west ? x0 : x0 + w;
      if (!west)
        while (xw > x0 && !contains(room.polygon, V2(xw - 0.01, y))) xw -= 0.05;
      const V2 c(west ? xw + 0.02 + depth / 2 : xw - 0.02 - depth / 2, y);
      if (!plan.place(c, V2(depth, len))) continue;
      F.push_back(item(shelf ? FurnitureType::kShelf : FurnitureType::kCabinet, c, V2(len, depth),
                       west ? -90 : 90, shelf ? rng.uniform(1.6, 2.0) : rng.uniform(0.8, 1.3)));
      break;
    }
  }
  // A table in the middle, with chairs.
  if (rng.uniform() < 0.7) {
    const bool round = rng.uniform() < 0.3;
    const double size_y = round ? 0.0 : rng.uniform(0.8, 1.1);
    const V2 size =
        round ? V2::Constant(2 * rng.uniform(0.45, 0.65)) : V2(rng.uniform(1.4, 2.4), size_y);
    for (int attempt = 0; attempt < 30; ++attempt) {
      const double cy = rng.uniform(y0 + 1.2, y0 + d - 1.2);
      const V2 c(rng.uniform(x0 + 1.2, x0 + w - 1.2), cy);
      if (!plan.place(c, size + V2(1.0, 1.0))) continue;
      if (round) {
        F.push_back(round_item(FurnitureType::kTable, c, size.x() / 2, rng.uniform(0.72, 0.76)));
      } else {
        F.push_back(item(FurnitureType::kTable, c, size, 0, rng.uniform(0.72, 0.76)));
      }
      const int nch = rng.uniform_int(0, 4);
      for (int k = 0; k < nch; ++k) {
        const double a = (k * 90.0 + (round ? 45 : 0)) * kDeg;
        const V2 dir(std::cos(a), std::sin(a));
        const V2 off(dir.x() * (size.x() / 2 + 0.25), dir.y() * (size.y() / 2 + 0.25));
        // The chair faces the table: its local +x points at it.
        F.push_back(item(FurnitureType::kChair, c + off, V2(0.45, 0.45),
                         std::atan2(-dir.y(), -dir.x()) / kDeg + rng.uniform(-10, 10)));
      }
      break;
    }
  }
  // Bins near walls, sometimes a pillar.
  const int nbin = rng.uniform_int(0, 2);
  for (int k = 0; k < nbin; ++k) {
    const double r = rng.uniform(0.12, 0.2);
    for (int attempt = 0; attempt < 30; ++attempt) {
      const double cy = rng.uniform(y0 + r + 0.05, y0 + d - r - 0.05);
      const V2 c(rng.uniform(x0 + r + 0.05, x0 + w - r - 0.05), cy);
      if (!plan.place(c, V2::Constant(2 * r))) continue;
      F.push_back(round_item(FurnitureType::kBin, c, r, rng.uniform(0.3, 0.5)));
      break;
    }
  }
  if (rng.uniform() < 0.15) {
    const double r = rng.uniform(0.15, 0.3);
    for (int attempt = 0; attempt < 30; ++attempt) {
      const double cy = rng.uniform(y0 + 1, y0 + d - 1);
      const V2 c(rng.uniform(x0 + 1, x0 + w - 1), cy);
      if (!plan.place(c, V2::Constant(2 * r))) continue;
      F.push_back(round_item(FurnitureType::kPillar, c, r));
      break;
    }
  }
  // Ceiling lamps (not in the planner: they hang above everything).
  const int nlamp = rng.uniform_int(1, 3);
  for (int k = 0; k < nlamp; ++k) {
    const V2 c(x0 + w * (k + 0.5) / nlamp, y0 + d * rng.uniform(0.3, 0.5));
    if (!contains(room.polygon, c)) continue;
    Furniture lamp = item(FurnitureType::kLamp, c, V2(1.2, 0.3), rng.uniform() < 0.5 ? 0 : 90);
    lamp.drop_m = rng.uniform(0.3, 0.7);
    // Keep clear of the scanner head.
    if ((c - scanner_xy).norm() < 0.9) lamp.drop_m = 0.1;
    F.push_back(lamp);
  }
}

/// A furnished room with its south wall on y = y0, x in [x0, x0 + w], depth d, door in edge 0.
LocalRoom make_room(Rng& rng, const RandomSceneParams& p, int index, double x0, double y0, double w,
                    double d, double t) {
  LocalRoom lr;
  Room& room = lr.room;
  room.name = "room_" + std::to_string(index);
  room.wall_thickness_m = t;
  const bool l_shape = shape_room(rng, p, x0, y0, w, d, t, room);
  const Opening& door = room.doors.front();

  Planner plan;
  plan.polygon = room.polygon;
  // Keep clear: the area in front of the door and around the scanner.
  const V2 door_c(x0 + door.at_m, y0 + 0.6);
  plan.taken.emplace_back(door_c - V2(door.width_m / 2 + 0.2, 0.8),
                          door_c + V2(door.width_m / 2 + 0.2, 0.8));
  // Two draws in the arguments of one call have no fixed order in C++ (gcc draws the last
  // argument first, clang the first): here and in furnish_room the later one is drawn
  // beforehand, as gcc did, so a seed gives the same scene with every compiler.
  const double scanner_v = rng.uniform(0.4, 0.6);
  V2 scanner_xy(x0 + w * rng.uniform(0.4, 0.6), y0 + (l_shape ? 0.5 : 1.0) * d * scanner_v);
  plan.taken.emplace_back(scanner_xy.array() - 0.45, scanner_xy.array() + 0.45);
  ScannerPose sp;
  sp.position_m = Eigen::Vector3d(scanner_xy.x(), scanner_xy.y(), rng.uniform(1.2, 1.5));
  sp.heading_deg = rng.uniform(0, 360);
  lr.scanners.push_back(sp);
  furnish_room(rng, plan, room, x0, y0, w, d, scanner_xy, lr.furniture);
  return lr;
}

V2 rotate(const V2& p, double yaw) {
  return {std::cos(yaw) * p.x() - std::sin(yaw) * p.y(),
          std::sin(yaw) * p.x() + std::cos(yaw) * p.y()};
}

}  // namespace

void validate(const RandomSceneParams& p) {
  if (p.rooms < 1 || p.rooms > 200) throw UsageError("--rooms must be in [1, 200]");
}

Scene random_scene(std::uint64_t seed, const RandomSceneParams& p) {
  validate(p);
  Rng rng(seed ^ 0x5ce9e5ce9e5ce9eULL);
  Scene scene;
  scene.name = "random_" + std::to_string(seed);
  scene.seed = seed;
  const double t = rng.uniform(0.15, 0.3);
  const double cw = rng.uniform(1.6, 2.4);
  const bool two_sided = p.rooms >= 4;
  const int north = two_sided ? (p.rooms + 1) / 2 : p.rooms;
  std::vector<LocalRoom> locals;
  double x_north = 0.0, x_south = 0.0;
  for (int i = 0; i < p.rooms; ++i) {
    const bool is_north = i < north;
    const double w = rng.uniform(3.0, 7.5), d = rng.uniform(3.0, 6.5);
    double& x = is_north ? x_north : x_south;
    LocalRoom lr = make_room(rng, p, i, x, t, w, d, t);
    x += w + t;
    if (!is_north) {  // mirror across the corridor's centre line y = -cw / 2
      auto mirror = [&](V2& v) { v.y() = -cw - v.y(); };
      for (auto& v : lr.room.polygon) mirror(v);
      for (auto& f : lr.furniture) {
        mirror(f.center_m);
        f.yaw_deg = -f.yaw_deg;
      }
      for (auto& s : lr.scanners) s.position_m.y() = -cw - s.position_m.y();
      if (lr.room.ceiling.slope_deg > 0)
        lr.room.ceiling.rise_azimuth_deg = -lr.room.ceiling.rise_azimuth_deg;
    }
    locals.push_back(std::move(lr));
  }
  const double length = std::max(x_north, x_south) - t;
  Room corridor;
  corridor.name = "corridor";
  corridor.kind = RoomKind::kCorridor;
  corridor.wall_thickness_m = t;
  corridor.ceiling.height_m = rng.uniform(2.5, 2.8);
  corridor.polygon = {{-1.5, -cw}, {length + 1.5, -cw}, {length + 1.5, 0.0}, {-1.5, 0.0}};
  // Rooms must not have openings above the corridor's ceiling on the shared wall.
  for (auto& lr : locals)
    for (auto& door : lr.room.doors)
      door.top_m = std::min(door.top_m, corridor.ceiling.height_m - 0.2);
  for (auto& lr : locals) {
    scene.rooms.push_back(lr.room);
    scene.furniture.insert(scene.furniture.end(), lr.furniture.begin(), lr.furniture.end());
    scene.scanners.insert(scene.scanners.end(), lr.scanners.begin(), lr.scanners.end());
  }
  scene.rooms.push_back(corridor);
  if (p.scanner_in_corridor && p.rooms >= 2) {
    ScannerPose sp;
    sp.position_m = Eigen::Vector3d(length / 2, -cw / 2, 1.3);
    scene.scanners.push_back(sp);
  }
  // Rotate the whole building.
  const double drawn_yaw = rng.uniform(-p.max_yaw_deg, p.max_yaw_deg) * kDeg;
  const double yaw = p.yaw_deg ? *p.yaw_deg * kDeg : drawn_yaw;
  for (auto& room : scene.rooms) {
    for (auto& v : room.polygon) v = rotate(v, yaw);
    if (room.ceiling.slope_deg > 0) room.ceiling.rise_azimuth_deg += yaw / kDeg;
  }
  for (auto& f : scene.furniture) {
    f.center_m = rotate(f.center_m, yaw);
    f.yaw_deg += yaw / kDeg;
  }
  for (auto& s : scene.scanners) {
    const V2 xy = rotate(s.position_m.head<2>(), yaw);
    s.position_m.head<2>() = xy;
  }
  const double tilt = rng.uniform(0.3, std::max(0.3, p.max_tilt_deg));
  const double dir = rng.uniform(0, 2 * std::numbers::pi);
  scene.tilt.roll_deg = tilt * std::cos(dir);
  scene.tilt.pitch_deg = tilt * std::sin(dir);
  return normalised(scene);
}

std::optional<double> random_scene_yaw_deg(const Scene& scene) {
  for (const Room& room : scene.rooms) {
    if (room.kind != RoomKind::kCorridor || room.polygon.size() < 2) continue;
    const V2 d = room.polygon[1] - room.polygon[0];
    return std::atan2(d.y(), d.x()) / kDeg;
  }
  return std::nullopt;
}

}  // namespace indoormap::sim
