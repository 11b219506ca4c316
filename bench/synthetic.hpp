#pragma once
// A synthetic building-scale cloud for benchmarks: a block of furnished box rooms, points sampled
// uniformly on floors, ceilings, walls and furniture boxes, slightly tilted. Fixed seed.
// scan_order = true orders each room's points as a terrestrial scanner in its middle delivers them
// (by azimuth, then elevation), which is what real clouds look like in memory; false leaves them
// shuffled, the worst case for any cache.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace indoormap::bench {

inline std::vector<Eigen::Vector3f> synthetic_building(std::size_t n_points, bool scan_order = true,
                                                       int rooms_x = 4, int rooms_y = 3,
                                                       std::uint32_t seed = 5) {
  const double w = 8.0, d = 6.0, h = 2.9;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.005);
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd(1.2 * M_PI / 180.0, Eigen::Vector3d(1, 0.3, 0).normalized())
          .toRotationMatrix();
  std::vector<Eigen::Vector3f> pts;
  std::vector<std::uint64_t> keys;
  pts.reserve(n_points);
  keys.reserve(n_points);
  while (pts.size() < n_points) {
    const int rx = static_cast<int>(u(rng) * rooms_x), ry = static_cast<int>(u(rng) * rooms_y);
    const double ox = w * rx, oy = d * ry;
    const double s = u(rng);
    Eigen::Vector3d p;
    if (s < 0.35)
      p = {u(rng) * w, u(rng) * d, 0.0};  // floor
    else if (s < 0.55)
      p = {u(rng) * w, u(rng) * d, h};  // ceiling
    else if (s < 0.65)
      p = {u(rng) * w, 0.0, u(rng) * h};  // walls
    else if (s < 0.75)
      p = {0.0, u(rng) * d, u(rng) * h};
    else if (s < 0.85)
      p = {0.3 + u(rng) * 2.0, 0.2 + u(rng) * 0.8, 0.75};  // desk top
    else
      p = {w - 0.5, 1.0 + u(rng) * 3.0, u(rng) * 2.0};                  // cabinet front
    const double az = std::atan2(p.y() - d / 2, p.x() - w / 2) + M_PI;  // seen from the room middle
    const double el = std::atan2(p.z() - 1.5, std::hypot(p.x() - w / 2, p.y() - d / 2)) + M_PI;
    keys.push_back((static_cast<std::uint64_t>(ry * rooms_x + rx) << 40) |
                   (static_cast<std::uint64_t>(az / (2 * M_PI) * 36000) << 20) |
                   static_cast<std::uint64_t>(el / (2 * M_PI) * 100000));
    p += Eigen::Vector3d(ox + noise(rng), oy + noise(rng), noise(rng));
    pts.push_back((tilt * p).cast<float>());
  }
  if (!scan_order) return pts;
  std::vector<std::uint32_t> order(pts.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return keys[a] < keys[b]; });
  std::vector<Eigen::Vector3f> sorted;
  sorted.reserve(pts.size());
  for (auto i : order) sorted.push_back(pts[i]);
  return sorted;
}

/// A hall of 80 x 60 x 4 m seen by one terrestrial scanner in its middle (1.5 m high): rays in
/// random directions (elevation -70..+90 degrees) to the floor, the ceiling, the walls or one of
/// 60 crates (0.5-2 m); 3 % of the returns are stray points somewhere along their ray (mixed
/// pixels, the ghost filter's work). Fixed seed. Points in the hall's frame, z up.
struct Hall {
  std::vector<Eigen::Vector3f> points;
  Eigen::Vector3d scanner;
};

inline Hall synthetic_hall(std::size_t n_points, std::uint32_t seed = 8) {
  const Eigen::Vector3d size(80.0, 60.0, 4.0);
  Hall hall{{}, {40.0, 30.0, 1.5}};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::AlignedBox3d> crates;
  while (crates.size() < 60) {
    const Eigen::Vector3d lo(u(rng) * 76 + 1, u(rng) * 56 + 1, 0.0);
    const Eigen::Vector3d ext(0.5 + 1.5 * u(rng), 0.5 + 1.5 * u(rng), 0.5 + 1.5 * u(rng));
    const Eigen::AlignedBox3d b(lo, lo + ext);
    if (b.exteriorDistance(hall.scanner) > 1.0) crates.push_back(b);
  }
  const double z_lo = std::sin(-70.0 * M_PI / 180.0);
  hall.points.reserve(n_points);
  while (hall.points.size() < n_points) {
    const double z = z_lo + (1.0 - z_lo) * u(rng), a = 2 * M_PI * u(rng), r = std::sqrt(1 - z * z);
    const Eigen::Vector3d d(r * std::cos(a), r * std::sin(a), z);
    double t = 1e9;
    for (int k = 0; k < 3; ++k) {  // the hall's box, from inside
      if (d[k] > 1e-9) t = std::min(t, (size[k] - hall.scanner[k]) / d[k]);
      if (d[k] < -1e-9) t = std::min(t, -hall.scanner[k] / d[k]);
    }
    for (const auto& b : crates) {  // slab test, nearest entry
      double t0 = 0.0, t1 = t;
      for (int k = 0; k < 3 && t0 <= t1; ++k) {
        if (std::abs(d[k]) < 1e-12) {
          if (hall.scanner[k] < b.min()[k] || hall.scanner[k] > b.max()[k]) t0 = 2e9;
          continue;
        }
        double ta = (b.min()[k] - hall.scanner[k]) / d[k],
               tb = (b.max()[k] - hall.scanner[k]) / d[k];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
      }
      if (t0 <= t1) t = t0;
    }
    if (u(rng) < 0.03) t *= u(rng);
    hall.points.push_back((hall.scanner + t * d).cast<float>());
  }
  return hall;
}

}  // namespace indoormap::bench
