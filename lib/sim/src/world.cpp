#include "indoormap/sim/world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "indoormap/core/angles.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::sim {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

Solid prism(Polygon footprint, double z0, double z1, int furniture, int room = -1) {
  Solid s;
  s.shape = Solid::Shape::kPrism;
  s.footprint = std::move(footprint);
  s.z0_m = z0;
  s.z1_m = z1;
  s.furniture = furniture;
  s.room = room;
  return s;
}

Solid cylinder(const Eigen::Vector2d& c, double r, double z0, double z1, int furniture) {
  Solid s;
  s.shape = Solid::Shape::kCylinder;
  s.center_m = c;
  s.radius_m = r;
  s.footprint = circle_polygon(c, r);
  s.z0_m = z0;
  s.z1_m = z1;
  s.furniture = furniture;
  return s;
}

double room_top_z(const Room& room) {
  double top = 0.0;
  for (const auto& v : room.polygon) top = std::max(top, ceiling_z(room, v));
  return top;
}
}  // namespace

std::vector<Solid> furniture_solids(const Scene& scene, int i) {
  const Furniture& f = scene.furniture[i];
  std::vector<Solid> out;
  const double yaw = f.yaw_deg * kDeg;
  const Eigen::Vector2d u(std::cos(yaw), std::sin(yaw)), v(-u.y(), u.x());
  const int r = room_at(scene, f.center_m);
  const double ceil = r >= 0 ? ceiling_z(scene.rooms[r], f.center_m) : 2.5;
  const double h = f.height_m > 0 ? f.height_m : default_height_m(f.type);
  const Eigen::Vector2d half = f.size_m / 2;
  // Four legs of side `leg` inset `inset` from the corners of the size_m rectangle.
  auto legs = [&](double leg, double inset, double z1) {
    for (int sx : {-1, 1}) {
      for (int sy : {-1, 1}) {
        const Eigen::Vector2d c = f.center_m + u * (sx * (half.x() - inset - leg / 2)) +
                                  v * (sy * (half.y() - inset - leg / 2));
        out.push_back(prism(rectangle(c, {leg, leg}, yaw), 0.0, z1, i));
      }
    }
  };
  switch (f.type) {
    case FurnitureType::kDesk:
    case FurnitureType::kTable: {
      const double top = f.thickness_m > 0 ? f.thickness_m : 0.03;
      if (f.type == FurnitureType::kTable && f.radius_m > 0) {
        out.push_back(cylinder(f.center_m, f.radius_m, h - top, h, i));
        out.push_back(cylinder(f.center_m, 0.04, 0.0, h - top, i));
        out.push_back(cylinder(f.center_m, std::min(0.3, f.radius_m * 0.6), 0.0, 0.03, i));
      } else {
        out.push_back(prism(rectangle(f.center_m, f.size_m, yaw), h - top, h, i));
        legs(0.05, 0.03, h - top);
      }
      break;
    }
    case FurnitureType::kCabinet:
    case FurnitureType::kShelf:
    case FurnitureType::kBox:
      out.push_back(prism(rectangle(f.center_m, f.size_m, yaw), 0.0, h, i));
      break;
    case FurnitureType::kChair: {
      const double seat = 0.05, back = 0.04;
      out.push_back(
          prism(rectangle(f.center_m, f.size_m, yaw), f.seat_height_m - seat, f.seat_height_m, i));
      legs(0.03, 0.02, f.seat_height_m - seat);
      const Eigen::Vector2d bc = f.center_m - u * (half.x() - back / 2);
      out.push_back(prism(rectangle(bc, {back, f.size_m.y()}, yaw), f.seat_height_m, h, i));
      break;
    }
    case FurnitureType::kBin:
      out.push_back(cylinder(f.center_m, f.radius_m, 0.0, h, i));
      break;
    case FurnitureType::kPillar:
      out.push_back(
          cylinder(f.center_m, f.radius_m, 0.0, f.height_m > 0 ? f.height_m : ceil + 0.01, i));
      break;
    case FurnitureType::kLamp: {
      const double th = f.thickness_m > 0 ? f.thickness_m : 0.06;
      const double z1 = ceil - f.drop_m, z0 = z1 - th;
      if (f.radius_m > 0) {
        out.push_back(cylinder(f.center_m, f.radius_m, z0, z1, i));
        if (f.drop_m > 0) out.push_back(cylinder(f.center_m, 0.004, z1, ceil + 0.01, i));
      } else {
        out.push_back(prism(rectangle(f.center_m, f.size_m, yaw), z0, z1, i));
        if (f.drop_m > 0)
          for (int s : {-1, 1})
            out.push_back(
                cylinder(f.center_m + u * (s * 0.35 * f.size_m.x()), 0.004, z1, ceil + 0.01, i));
      }
      break;
    }
  }
  return out;
}

SceneGeometry build_geometry(const Scene& scene) {
  SceneGeometry g;
  // 1. Wall pieces: one mitred quad per room edge, full height.
  struct EdgeFrame {
    Eigen::Vector2d a, u, n;
  };
  std::vector<std::vector<EdgeFrame>> frames(scene.rooms.size());
  for (std::size_t r = 0; r < scene.rooms.size(); ++r) {
    const Room& room = scene.rooms[r];
    const auto& P = room.polygon;
    const int n = static_cast<int>(P.size());
    const double t = room.wall_thickness_m;
    const double z1 = room_top_z(room) + 0.1;
    std::vector<Eigen::Vector2d> normals(n);
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d u = (P[(i + 1) % n] - P[i]).normalized();
      normals[i] = Eigen::Vector2d(u.y(), -u.x());  // outward for a counter-clockwise polygon
      frames[r].push_back({P[i], u, normals[i]});
    }
    std::vector<Eigen::Vector2d> outer(n);
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d& n1 = normals[(i + n - 1) % n];
      const Eigen::Vector2d& n2 = normals[i];
      outer[i] = P[i] + t * (n1 + n2) / (1.0 + n1.dot(n2));
    }
    for (int i = 0; i < n; ++i)
      g.solids.push_back(prism({P[i], outer[i], outer[(i + 1) % n], P[(i + 1) % n]}, 0.0, z1, -1,
                               static_cast<int>(r)));
  }
  // 2. Openings cut every full-height wall piece that holds their centre (the host room's wall
  // and, for a shared wall, the neighbour's).
  for (std::size_t r = 0; r < scene.rooms.size(); ++r) {
    const Room& room = scene.rooms[r];
    for (int kind = 0; kind < 2; ++kind) {
      for (const Opening& o : kind == 0 ? room.doors : room.windows) {
        const EdgeFrame& f = frames[r][o.edge];
        const Eigen::Vector2d centre = f.a + f.u * o.at_m + f.n * (room.wall_thickness_m / 2);
        const double s0 = o.at_m - o.width_m / 2 + f.u.dot(f.a);
        const double s1 = o.at_m + o.width_m / 2 + f.u.dot(f.a);
        const std::size_t count = g.solids.size();
        for (std::size_t k = 0; k < count; ++k) {
          Solid& w = g.solids[k];
          if (w.furniture >= 0 || w.z0_m != 0.0 || w.z1_m <= o.bottom_m ||
              !contains(w.footprint, centre))
            continue;
          const Solid piece = w;
          Polygon before = clip_halfplane(piece.footprint, f.u, s0);
          Polygon after = clip_halfplane(piece.footprint, -f.u, -s1);
          Polygon middle = clip_halfplane(clip_halfplane(piece.footprint, -f.u, -s0), f.u, s1);
          std::vector<Solid> parts;
          if (before.size() >= 3)
            parts.push_back(prism(before, piece.z0_m, piece.z1_m, -1, piece.room));
          if (after.size() >= 3)
            parts.push_back(prism(after, piece.z0_m, piece.z1_m, -1, piece.room));
          if (middle.size() >= 3) {
            if (o.bottom_m > 0) parts.push_back(prism(middle, 0.0, o.bottom_m, -1, piece.room));
            if (o.top_m < piece.z1_m)
              parts.push_back(prism(middle, o.top_m, piece.z1_m, -1, piece.room));
            if (kind == 0) g.door_floors.push_back(middle);
          }
          if (parts.empty()) continue;
          g.solids[k] = parts.front();  // `w` is invalid after the push_backs below
          for (std::size_t p = 1; p < parts.size(); ++p) g.solids.push_back(parts[p]);
        }
      }
    }
  }
  // 3. Furniture.
  for (std::size_t i = 0; i < scene.furniture.size(); ++i) {
    auto parts = furniture_solids(scene, static_cast<int>(i));
    g.solids.insert(g.solids.end(), parts.begin(), parts.end());
  }
  // 4. Caps: room floors and ceilings, door floors.
  for (std::size_t r = 0; r < scene.rooms.size(); ++r) {
    const Room& room = scene.rooms[r];
    Cap c;
    c.polygon = room.polygon;
    c.room = static_cast<int>(r);
    const double s = std::tan(room.ceiling.slope_deg * kDeg);
    const Eigen::Vector2d dir(std::cos(room.ceiling.rise_azimuth_deg * kDeg),
                              std::sin(room.ceiling.rise_azimuth_deg * kDeg));
    double lowest = kInf;
    for (const auto& v : room.polygon) lowest = std::min(lowest, dir.dot(v));
    c.ceiling_g = s * dir;
    c.ceiling_a = room.ceiling.height_m - s * lowest;
    g.caps.push_back(c);
  }
  for (const auto& df : g.door_floors) {
    Cap c;
    c.polygon = df;
    c.ceiling = false;
    g.caps.push_back(c);
  }
  return g;
}

// ---------------------------------------------------------------------------------------------

RayCaster::RayCaster(const SceneGeometry& geometry, double cell_m) : caps_(geometry.caps) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(kInf), hi = -lo;
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> boxes;
  for (const auto& s : geometry.solids) {
    Prim p;
    p.index = static_cast<int>(boxes.size());
    p.z0 = s.z0_m;
    p.z1 = s.z1_m;
    if (s.shape == Solid::Shape::kCylinder) {
      p.kind = 1;
      p.cx = s.center_m.x();
      p.cy = s.center_m.y();
      p.r = s.radius_m;
      boxes.emplace_back(s.center_m.array() - s.radius_m, s.center_m.array() + s.radius_m);
    } else {
      const auto& F = s.footprint;
      if (F.size() > 8)
        throw Error("ray caster: wall or furniture prism with more than 8 vertices");
      p.kind = 0;
      p.n = static_cast<std::uint8_t>(F.size());
      for (std::size_t k = 0; k < F.size(); ++k) {
        const Eigen::Vector2d e = F[(k + 1) % F.size()] - F[k];
        Eigen::Vector2d nrm(e.y(), -e.x());
        const double len = nrm.norm();
        if (len > 0) nrm /= len;
        p.nx[k] = nrm.x();
        p.ny[k] = nrm.y();
        p.off[k] = nrm.dot(F[k]);
      }
      boxes.push_back(bounds(F));
    }
    prims_.push_back(p);
  }
  for (std::size_t c = 0; c < caps_.size(); ++c) {
    Prim p;
    p.kind = 2;
    p.index = static_cast<int>(c);
    prims_.push_back(p);
    boxes.push_back(bounds(caps_[c].polygon));
  }
  for (const auto& [a, b] : boxes) {
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(b);
  }
  if (boxes.empty()) {
    lo = Eigen::Vector2d::Zero();
    hi = Eigen::Vector2d::Ones();
  }
  lo.array() -= 0.01;
  hi.array() += 0.01;
  const Eigen::Vector2d ext = hi - lo;
  cell_m_ = std::max({cell_m, std::sqrt(ext.prod() / 4e6), 1e-3});
  lo_ = lo;
  width_ = std::max(1, static_cast<int>(std::ceil(ext.x() / cell_m_)));
  height_ = std::max(1, static_cast<int>(std::ceil(ext.y() / cell_m_)));

  // Counting pass, then filling pass (CSR).
  auto cell_range = [&](const std::pair<Eigen::Vector2d, Eigen::Vector2d>& box) {
    const int c0 = std::clamp(static_cast<int>(std::floor((box.first.x() - lo_.x()) / cell_m_)), 0,
                              width_ - 1);
    const int c1 = std::clamp(static_cast<int>(std::floor((box.second.x() - lo_.x()) / cell_m_)), 0,
                              width_ - 1);
    const int r0 = std::clamp(static_cast<int>(std::floor((box.first.y() - lo_.y()) / cell_m_)), 0,
                              height_ - 1);
    const int r1 = std::clamp(static_cast<int>(std::floor((box.second.y() - lo_.y()) / cell_m_)), 0,
                              height_ - 1);
    return std::array<int, 4>{c0, c1, r0, r1};
  };
  const std::size_t ncells = static_cast<std::size_t>(width_) * height_;
  cell_begin_.assign(ncells + 1, 0);
  for (const auto& box : boxes) {
    const auto [c0, c1, r0, r1] = cell_range(box);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) ++cell_begin_[static_cast<std::size_t>(r) * width_ + c + 1];
  }
  for (std::size_t k = 0; k < ncells; ++k) cell_begin_[k + 1] += cell_begin_[k];
  items_.resize(cell_begin_[ncells]);
  std::vector<std::uint32_t> fill(cell_begin_.begin(), cell_begin_.end() - 1);
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    const auto [c0, c1, r0, r1] = cell_range(boxes[b]);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c)
        items_[fill[static_cast<std::size_t>(r) * width_ + c]++] = static_cast<std::uint32_t>(b);
  }
  mailbox_.assign(prims_.size(), 0);
}

double RayCaster::intersect(const Prim& p, const Eigen::Vector3d& o,
                            const Eigen::Vector3d& d) const {
  double t0 = -kInf, t1 = kInf;
  // Vertical extent (slab).
  if (p.kind != 2) {
    if (d.z() != 0.0) {
      double a = (p.z0 - o.z()) / d.z(), b = (p.z1 - o.z()) / d.z();
      if (a > b) std::swap(a, b);
      t0 = a;
      t1 = b;
    } else if (o.z() < p.z0 || o.z() > p.z1) {
      return kInf;
    }
  }
  if (p.kind == 0) {
    for (int k = 0; k < p.n; ++k) {
      const double nd = p.nx[k] * d.x() + p.ny[k] * d.y();
      const double dist = p.off[k] - (p.nx[k] * o.x() + p.ny[k] * o.y());
      if (nd == 0.0) {
        if (dist < 0) return kInf;
      } else {
        const double t = dist / nd;
        if (nd < 0) {
          t0 = std::max(t0, t);
        } else {
          t1 = std::min(t1, t);
        }
      }
      if (t0 > t1) return kInf;
    }
    return t0 > 0 ? t0 : kInf;
  }
  if (p.kind == 1) {
    const double ox = o.x() - p.cx, oy = o.y() - p.cy;
    const double a = d.x() * d.x() + d.y() * d.y();
    const double c = ox * ox + oy * oy - p.r * p.r;
    if (a < 1e-18) {
      if (c > 0) return kInf;
    } else {
      const double b = ox * d.x() + oy * d.y();
      const double disc = b * b - a * c;
      if (disc < 0) return kInf;
      const double sq = std::sqrt(disc);
      t0 = std::max(t0, (-b - sq) / a);
      t1 = std::min(t1, (-b + sq) / a);
    }
    if (t0 > t1) return kInf;
    return t0 > 0 ? t0 : kInf;
  }
  // Cap: floor at z = 0 and / or the ceiling plane, limited to the polygon.
  const Cap& cap = caps_[p.index];
  double tf = kInf, tc = kInf;
  if (cap.floor && d.z() != 0.0) {
    const double t = -o.z() / d.z();
    if (t > 0) tf = t;
  }
  if (cap.ceiling) {
    const double den = d.z() - cap.ceiling_g.dot(d.head<2>());
    if (den != 0.0) {
      const double t = (cap.ceiling_a + cap.ceiling_g.dot(o.head<2>()) - o.z()) / den;
      if (t > 0) tc = t;
    }
  }
  const double first = std::min(tf, tc), second = std::max(tf, tc);
  for (double t : {first, second}) {
    if (t == kInf) break;
    const Eigen::Vector2d q = o.head<2>() + t * d.head<2>();
    if (contains(cap.polygon, q)) return t;
  }
  return kInf;
}

std::optional<RayCaster::Hit> RayCaster::cast(const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                                              double t_max) {
  if (++ray_id_ == 0) {  // wrapped: forget every mailbox entry
    std::fill(mailbox_.begin(), mailbox_.end(), 0);
    ray_id_ = 1;
  }
  // Clip the ray to the grid's box (2D slabs).
  double t_in = 0.0, t_out = t_max;
  const double hi_x = lo_.x() + width_ * cell_m_, hi_y = lo_.y() + height_ * cell_m_;
  for (int axis = 0; axis < 2; ++axis) {
    const double lo = axis == 0 ? lo_.x() : lo_.y(), hi = axis == 0 ? hi_x : hi_y;
    if (d[axis] == 0.0) {
      if (o[axis] < lo || o[axis] > hi) return std::nullopt;
    } else {
      double a = (lo - o[axis]) / d[axis], b = (hi - o[axis]) / d[axis];
      if (a > b) std::swap(a, b);
      t_in = std::max(t_in, a);
      t_out = std::min(t_out, b);
    }
  }
  if (t_in > t_out) return std::nullopt;
  const double px = o.x() + t_in * d.x(), py = o.y() + t_in * d.y();
  int col = std::clamp(static_cast<int>(std::floor((px - lo_.x()) / cell_m_)), 0, width_ - 1);
  int row = std::clamp(static_cast<int>(std::floor((py - lo_.y()) / cell_m_)), 0, height_ - 1);
  const int step_c = d.x() > 0 ? 1 : -1, step_r = d.y() > 0 ? 1 : -1;
  const double dt_c = d.x() != 0.0 ? cell_m_ / std::abs(d.x()) : kInf;
  const double dt_r = d.y() != 0.0 ? cell_m_ / std::abs(d.y()) : kInf;
  double next_c = kInf, next_r = kInf;
  if (d.x() != 0.0) next_c = (lo_.x() + (col + (d.x() > 0 ? 1 : 0)) * cell_m_ - o.x()) / d.x();
  if (d.y() != 0.0) next_r = (lo_.y() + (row + (d.y() > 0 ? 1 : 0)) * cell_m_ - o.y()) / d.y();

  double best = t_max;
  int best_prim = -1;
  for (;;) {
    const std::size_t cell = static_cast<std::size_t>(row) * width_ + col;
    for (std::uint32_t k = cell_begin_[cell], e = cell_begin_[cell + 1]; k < e; ++k) {
      const std::uint32_t id = items_[k];
      if (mailbox_[id] == ray_id_) continue;
      mailbox_[id] = ray_id_;
      const double t = intersect(prims_[id], o, d);
      if (t <= best) {
        best = t;
        best_prim = static_cast<int>(id);
      }
    }
    const double t_exit = std::min({next_c, next_r, t_out});
    if (best_prim >= 0 && best <= t_exit) break;
    if (t_exit >= t_out) break;
    if (next_c < next_r) {
      col += step_c;
      if (col < 0 || col >= width_) break;
      next_c += dt_c;
    } else {
      row += step_r;
      if (row < 0 || row >= height_) break;
      next_r += dt_r;
    }
  }
  if (best_prim < 0) return std::nullopt;
  Hit h;
  h.t_m = best;
  const Prim& p = prims_[best_prim];
  if (p.kind == 2) {
    h.cap = p.index;
  } else {
    h.solid = p.index;
  }
  return h;
}

}  // namespace indoormap::sim
