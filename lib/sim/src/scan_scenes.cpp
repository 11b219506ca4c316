#include "indoormap/sim/scan_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "indoormap/core/errors.hpp"
#include "indoormap/core/polygon.hpp"

namespace indoormap::sim {

void ScanSceneParams::validate() const {
  if (!(min_side_m >= 3.0 && max_side_m >= min_side_m))
    throw UsageError("scan scene: need 3 <= min_side_m <= max_side_m");
  for (double s : {l_shape_share, pillar_share, door_share})
    if (!(s >= 0.0 && s <= 1.0)) throw UsageError("scan scene: shares must be in [0, 1]");
  if (!(min_door_m > 0.0 && max_door_m >= min_door_m))
    throw UsageError("scan scene: need 0 < min_door_m <= max_door_m");
}

void LaserModel::validate() const {
  if (beams < 2) throw UsageError("laser model: beams must be >= 2");
  if (!(fov_rad > 0.0 && fov_rad <= 2.0 * std::numbers::pi))
    throw UsageError("laser model: fov_rad must be in (0, 2 pi]");
  if (!(max_range_m > 0.0 && sigma_r_m >= 0.0))
    throw UsageError("laser model: max_range_m > 0 and sigma_r_m >= 0 needed");
}

namespace {

using V = Eigen::Vector2d;

double cross(const V& a, const V& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// Adds the closed outline as walls (in its own order) and its vertices as corners of `type`.
void add_outline(ScanScene& s, const std::vector<V>& poly, TrueCornerType type) {
  for (std::size_t i = 0; i < poly.size(); ++i) {
    s.walls.push_back({poly[i], poly[(i + 1) % poly.size()]});
    s.corners.push_back({poly[i], type});
  }
}

/// Cuts a door into room side `side` (a wall from a to b) and adds a closet behind it.
void add_door(ScanScene& s, std::size_t side, double width, double pos, double depth,
              double margin) {
  const V a = s.walls[side].a, b = s.walls[side].b;
  const V d = (b - a).normalized(), out(d.y(), -d.x());  // out: away from the room (right)
  const V j0 = a + d * pos, j1 = a + d * (pos + width);
  s.walls[side] = {a, j0};
  s.walls.push_back({j1, b});
  s.doors.push_back({j0, j1});
  // Closet: counter-clockwise seen from inside it, corners on the room wall's line included.
  const V c0 = j0 - d * margin, c1 = j1 + d * margin;
  const std::vector<V> closet{c0, c0 + out * depth, c1 + out * depth, c1};
  for (std::size_t i = 0; i + 1 < closet.size(); ++i) s.walls.push_back({closet[i], closet[i + 1]});
  s.walls.push_back({c1, j1});  // the room wall's back, its free side facing the closet
  s.walls.push_back({j0, c0});
  for (const V& c : closet) s.corners.push_back({c, TrueCornerType::kInner});
}

}  // namespace

ScanScene random_scan_scene(std::uint64_t seed, const ScanSceneParams& p) {
  p.validate();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto uni = [&](double lo, double hi) { return lo + (hi - lo) * u01(rng); };
  ScanScene s;
  const double w = uni(p.min_side_m, p.max_side_m), h = uni(p.min_side_m, p.max_side_m);
  if (u01(rng) < p.l_shape_share) {  // notch at the top right corner
    const double nw = uni(1.2, 0.45 * w), nh = uni(1.2, 0.45 * h);
    s.room = {{0, 0}, {w, 0}, {w, h - nh}, {w - nw, h - nh}, {w - nw, h}, {0, h}};
  } else {
    s.room = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  }
  add_outline(s, s.room, TrueCornerType::kInner);
  if (s.room.size() == 6) s.corners[3].type = TrueCornerType::kOuter;  // the notch's reflex vertex
  const std::size_t sides = s.walls.size();
  for (std::size_t i = 0; i < sides; ++i) {
    if (s.room.size() == 6 && (i == 2 || i == 3)) continue;  // the notch's sides: no closet room
    const double len = (s.walls[i].b - s.walls[i].a).norm();
    const double width = uni(p.min_door_m, p.max_door_m);
    if (len < width + 2.0 || u01(rng) >= p.door_share) continue;
    // One draw per statement (the order of a call's arguments is unspecified: gcc and clang
    // differ), in the order gcc gave when they were arguments, so the scenes stay as they were.
    const double margin_m = uni(0.3, 0.6), depth_m = uni(1.2, 2.5);
    const double offset_m = uni(0.9, len - width - 0.9);
    add_door(s, i, width, offset_m, depth_m, margin_m);
  }
  if (u01(rng) < p.pillar_share) {
    const double cy = uni(0.25, 0.4) * h;  // drawn first, as above
    const V c(uni(0.35, 0.65) * w * 0.6 + 0.2 * w, cy);
    const double side = uni(0.4, 0.8);
    // Clockwise, so that the free side (outside the pillar) is on the left of every wall.
    Polygon pillar = rectangle(c, {side, side}, uni(0.0, std::numbers::pi / 2));
    std::reverse(pillar.begin(), pillar.end());
    s.pillar = pillar;
    add_outline(s, pillar, TrueCornerType::kOuter);
  }
  return s;
}

double cast_ray(const ScanScene& scene, const V& o, const V& dir) {
  double best = std::numeric_limits<double>::infinity();
  for (const ScanSegment& w : scene.walls) {
    const V e = w.b - w.a;
    const double den = cross(dir, e);
    if (std::abs(den) < 1e-12) continue;
    const V ao = w.a - o;
    const double t = cross(ao, e) / den, u = cross(ao, dir) / den;
    if (t > 1e-9 && u >= 0.0 && u <= 1.0) best = std::min(best, t);
  }
  return best;
}

bool line_of_sight(const ScanScene& scene, const V& from, const V& to, double tol_m) {
  const double len = (to - from).norm();
  if (len <= tol_m) return true;
  return cast_ray(scene, from, (to - from) / len) >= len - tol_m;
}

laser::LaserScan cast_scan(const ScanScene& scene, const laser::Pose2d& laser_map,
                           const LaserModel& m, std::mt19937_64& rng) {
  m.validate();
  std::normal_distribution<double> noise(0.0, m.sigma_r_m);
  laser::LaserScan scan;
  const bool full = m.fov_rad >= 2.0 * std::numbers::pi - 1e-9;
  scan.angle_increment_rad = full ? m.fov_rad / m.beams : m.fov_rad / (m.beams - 1);
  scan.angle_min_rad = full ? -std::numbers::pi : -m.fov_rad / 2;
  scan.max_range_m = m.max_range_m;
  scan.robot_pose_map = laser_map;
  scan.ranges_m.resize(static_cast<std::size_t>(m.beams));
  for (int i = 0; i < m.beams; ++i) {
    const double a = laser_map.theta_rad + scan.beam_angle_rad(static_cast<std::size_t>(i));
    const double r = cast_ray(scene, laser_map.position_m(), {std::cos(a), std::sin(a)});
    const double noisy = r + noise(rng);
    scan.ranges_m[static_cast<std::size_t>(i)] =
        std::isfinite(r) && noisy < m.max_range_m ? static_cast<float>(noisy) : 0.0f;
  }
  return scan;
}

laser::Pose2d random_pose(const ScanScene& scene, double clearance_m, std::mt19937_64& rng) {
  const auto [lo, hi] = bounds(scene.room);
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y()),
      ut(-std::numbers::pi, std::numbers::pi);
  for (int attempt = 0; attempt < 10000; ++attempt) {
    const double y = uy(rng);  // one draw per statement, gcc's order (see random_scan_scene)
    const V p(ux(rng), y);
    if (!contains(scene.room, p) || (!scene.pillar.empty() && contains(scene.pillar, p))) continue;
    bool clear = true;
    for (const ScanSegment& w : scene.walls) {
      const V e = w.b - w.a;
      const double t = std::clamp(e.dot(p - w.a) / e.squaredNorm(), 0.0, 1.0);
      if ((w.a + t * e - p).norm() < clearance_m) clear = false;
    }
    if (clear) return {p.x(), p.y(), ut(rng)};
  }
  throw Error("scan scene: no free pose found");
}

}  // namespace indoormap::sim
