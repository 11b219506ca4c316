#include "indoormap/sim/scan_eval.hpp"

#include <cmath>
#include <numbers>

namespace indoormap::sim {

void ScanScore::add(const ScanScore& o) {
  endpoint_errors_m.insert(endpoint_errors_m.end(), o.endpoint_errors_m.begin(),
                           o.endpoint_errors_m.end());
  endpoints_visible += o.endpoints_visible;
  doors_visible += o.doors_visible;
  doors_found += o.doors_found;
  doors_detected += o.doors_detected;
  doors_right += o.doors_right;
  corners_visible += o.corners_visible;
  corners_found += o.corners_found;
  corners_typed += o.corners_typed;
  corners_type_right += o.corners_type_right;
}

namespace {

using V = Eigen::Vector2d;
namespace sf = scan_features;

struct View {
  const ScanScene& scene;
  const laser::LaserScan& scan;
  const ScanEvalParams& p;
  V s;

  bool in_fov(const V& q) const {
    const double fov = std::abs(scan.angle_increment_rad) * static_cast<double>(scan.size());
    if (fov >= 2.0 * std::numbers::pi - 1e-6) return true;
    const V d = q - s;
    const double a = laser::wrap_angle(std::atan2(d.y(), d.x()) - scan.robot_pose_map.theta_rad);
    return a >= scan.angle_min_rad && a <= scan.angle_min_rad + fov;
  }
  bool sees(const V& q) const {
    return (q - s).norm() <= p.max_range_m && in_fov(q) && line_of_sight(scene, s, q, 0.01);
  }
  /// The end e of wall w is visible with a piece of the wall next to it.
  bool sees_end(const ScanSegment& w, const V& e) const {
    const V e_other = (e - w.a).norm() < 1e-9 ? w.b : w.a;
    const V probe = e + (e_other - e).normalized() * p.probe_m;
    const V d = w.b - w.a, ps = s - w.a;
    return d.x() * ps.y() - d.y() * ps.x() > 0.0 && sees(e) && sees(probe);
  }
};

double seg_distance(const ScanSegment& w, const V& q) {
  const V e = w.b - w.a;
  const double t = std::clamp(e.dot(q - w.a) / e.squaredNorm(), 0.0, 1.0);
  return (w.a + t * e - q).norm();
}

bool same_line(const ScanSegment& w, const sf::Wall& d, double tol) {
  const V gw = (w.b - w.a).normalized(), dw = (d.end_map - d.start_map).normalized();
  return seg_distance(w, d.start_map) <= tol && seg_distance(w, d.end_map) <= tol &&
         gw.dot(dw) >= std::cos(10.0 * std::numbers::pi / 180.0);
}

void score_walls(const View& v, const sf::ScanFeatures& f, ScanScore& out) {
  for (const ScanSegment& w : v.scene.walls)
    for (const V& e : {w.a, w.b}) {
      if (!v.sees_end(w, e)) continue;
      ++out.endpoints_visible;
      double best = v.p.endpoint_gate_m;
      for (const sf::Wall& d : f.walls)
        if (same_line(w, d, v.p.line_tol_m))
          best = std::min({best, (d.start_map - e).norm(), (d.end_map - e).norm()});
      if (best < v.p.endpoint_gate_m) out.endpoint_errors_m.push_back(best);
    }
}

void score_doors(const View& v, const sf::ScanFeatures& f, ScanScore& out) {
  auto matches = [&](const ScanSegment& g, const sf::Door& d) {
    const double t = v.p.door_tol_m;
    return ((d.a_map - g.a).norm() <= t && (d.b_map - g.b).norm() <= t) ||
           ((d.a_map - g.b).norm() <= t && (d.b_map - g.a).norm() <= t);
  };
  const double inc = std::abs(v.scan.angle_increment_rad);
  for (const ScanSegment& g : v.scene.doors) {
    const V dir = (g.b - g.a).normalized();
    const V da = g.a - v.s, db = g.b - v.s;
    const double subtended = std::acos(std::clamp(da.normalized().dot(db.normalized()), -1.0, 1.0));
    const bool room_side = dir.x() * (v.s - g.a).y() - dir.y() * (v.s - g.a).x() > 0.0;
    if (!room_side || subtended < 3.0 * inc || !v.sees(g.a) || !v.sees(g.b) ||
        !v.sees(g.a - dir * v.p.probe_m) || !v.sees(g.b + dir * v.p.probe_m))
      continue;
    ++out.doors_visible;
    for (const sf::Door& d : f.doors)
      if (matches(g, d)) {
        ++out.doors_found;
        break;
      }
  }
  for (const sf::Door& d : f.doors) {
    if ((d.a_map - v.s).norm() > v.p.max_range_m || (d.b_map - v.s).norm() > v.p.max_range_m)
      continue;
    ++out.doors_detected;
    for (const ScanSegment& g : v.scene.doors)
      if (matches(g, d)) {
        ++out.doors_right;
        break;
      }
  }
}

void score_corners(const View& v, const sf::ScanFeatures& f, ScanScore& out) {
  for (const TrueCorner& c : v.scene.corners) {
    if (!v.sees(c.p_map)) continue;
    ++out.corners_visible;
    for (const sf::Corner& d : f.corners)
      if ((d.p_map - c.p_map).norm() <= v.p.corner_tol_m) {
        ++out.corners_found;
        break;
      }
  }
  for (const sf::Corner& d : f.corners) {
    if ((d.p_map - v.s).norm() > v.p.max_range_m) continue;
    const TrueCorner* best = nullptr;
    double best_d = v.p.corner_tol_m;
    for (const TrueCorner& c : v.scene.corners)
      if ((d.p_map - c.p_map).norm() <= best_d) best_d = (d.p_map - c.p_map).norm(), best = &c;
    if (!best) continue;
    ++out.corners_typed;
    const bool right =
        d.type == sf::CornerType::kPotential
            ? !line_of_sight(v.scene, v.s, best->p_map, 0.01)
            : (d.type == sf::CornerType::kInner) == (best->type == TrueCornerType::kInner);
    if (right) ++out.corners_type_right;
  }
}

}  // namespace

ScanScore score_scan(const ScanScene& scene, const laser::LaserScan& scan,
                     const scan_features::ScanFeatures& features, const ScanEvalParams& params) {
  ScanScore out;
  const View v{scene, scan, params, scan.laser_pose_map().position_m()};
  score_walls(v, features, out);
  score_doors(v, features, out);
  score_corners(v, features, out);
  return out;
}

}  // namespace indoormap::sim
