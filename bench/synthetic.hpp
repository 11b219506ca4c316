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
      Eigen::AngleAxisd(1.2 * M_PI / 180.0, Eigen::Vector3d(1, 0.3, 0).normalized()).toRotationMatrix();
  std::vector<Eigen::Vector3f> pts;
  std::vector<std::uint64_t> keys;
  pts.reserve(n_points);
  keys.reserve(n_points);
  while (pts.size() < n_points) {
    const int rx = static_cast<int>(u(rng) * rooms_x), ry = static_cast<int>(u(rng) * rooms_y);
    const double ox = w * rx, oy = d * ry;
    const double s = u(rng);
    Eigen::Vector3d p;
    if (s < 0.35) p = {u(rng) * w, u(rng) * d, 0.0};             // floor
    else if (s < 0.55) p = {u(rng) * w, u(rng) * d, h};          // ceiling
    else if (s < 0.65) p = {u(rng) * w, 0.0, u(rng) * h};        // walls
    else if (s < 0.75) p = {0.0, u(rng) * d, u(rng) * h};
    else if (s < 0.85) p = {0.3 + u(rng) * 2.0, 0.2 + u(rng) * 0.8, 0.75};  // desk top
    else p = {w - 0.5, 1.0 + u(rng) * 3.0, u(rng) * 2.0};         // cabinet front
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

}  // namespace indoormap::bench
