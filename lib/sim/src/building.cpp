#include "indoormap/sim/building.hpp"

#include <algorithm>
#include <cmath>

#include "indoormap/core/errors.hpp"

namespace indoormap::sim {

void validate(const BuildingParams& p) {
  validate(p.random);
  if (p.storeys < 1 || p.storeys > 20) throw UsageError("storeys must be in [1, 20]");
  if (!(p.slab_thickness_m >= 0.15 && p.slab_thickness_m <= 2.0))
    throw UsageError("slab_thickness_m must be in [0.15, 2] m");
}

double storey_top_z(const Scene& scene) {
  double top = 0.0;
  for (const Room& room : scene.rooms)
    for (const auto& v : room.polygon) top = std::max(top, ceiling_z(room, v));
  return top;
}

Building stack_storeys(std::vector<Scene> storeys, double slab_thickness_m) {
  if (storeys.empty()) throw UsageError("a building needs at least one storey");
  if (!(slab_thickness_m >= 0.15 && slab_thickness_m <= 2.0))
    throw UsageError("slab_thickness_m must be in [0.15, 2] m");
  Building b;
  double floor = 0.0;
  for (std::size_t k = 0; k < storeys.size(); ++k) {
    Scene& s = storeys[k];
    if (k > 0) s.tilt = storeys.front().tilt;
    const auto problems = check_scene(s);
    if (!problems.empty())
      throw UsageError("storey " + std::to_string(k) + ": " + problems.front().key + ": " +
                       problems.front().problem);
    Storey st;
    st.scene = normalised(std::move(s));
    st.floor_z_m = floor;
    st.ceiling_z_m = floor + storey_top_z(st.scene);
    floor = st.ceiling_z_m + slab_thickness_m;
    b.storeys.push_back(std::move(st));
  }
  return b;
}

Building random_building(std::uint64_t seed, const BuildingParams& p) {
  validate(p);
  std::vector<Scene> scenes;
  scenes.push_back(random_scene(seed, p.random));
  RandomSceneParams upper = p.random;
  upper.yaw_deg = random_scene_yaw_deg(scenes.front());
  for (int k = 1; k < p.storeys; ++k) {
    if (p.same_footprint) {
      Scene s = scenes.front();
      s.seed = seed + 7919ULL * static_cast<std::uint64_t>(k);  // other noise, same rooms
      for (auto& sc : s.scanners) sc.heading_deg = std::fmod(sc.heading_deg + 37.0 * k, 360.0);
      scenes.push_back(std::move(s));
      continue;
    }
    Scene s = random_scene(seed * 1000003ULL + static_cast<std::uint64_t>(k), upper);
    s.name = scenes.front().name + "_storey_" + std::to_string(k);
    scenes.push_back(std::move(s));
  }
  return stack_storeys(std::move(scenes), p.slab_thickness_m);
}

BuildingSim merge_storeys(const Building& building, std::vector<SimResult> storeys) {
  BuildingSim out;
  if (storeys.size() == 1 && building.storeys.size() == 1 && building.storeys[0].floor_z_m == 0.0) {
    out.sim = std::move(storeys.front());
    out.scanner_storey.assign(out.sim.scanner_positions_m.size(), 0);
    return out;
  }
  SimResult& m = out.sim;
  const Eigen::Matrix3d R = tilt_rotation(building.storeys.front().scene.tilt);
  for (std::size_t k = 0; k < storeys.size(); ++k) {
    SimResult& s = storeys[k];
    const Eigen::Vector3d off = R * Eigen::Vector3d(0, 0, building.storeys[k].floor_z_m);
    const Eigen::Vector3f off_f = off.cast<float>();
    const std::size_t base = m.points.size();
    const int scanner_base = static_cast<int>(m.scanner_positions_m.size());
    m.points.reserve(base + s.points.size());
    for (const auto& p : s.points) m.points.push_back(p + off_f);
    for (ScanBlock b : s.scans) {
      b.scanner += scanner_base;
      b.begin += base;
      b.end += base;
      m.scans.push_back(b);
    }
    for (const auto& p : s.scanner_positions_m) {
      m.scanner_positions_m.push_back(p + off);
      out.scanner_storey.push_back(static_cast<int>(k));
    }
    m.rays += s.rays;
    m.returns += s.returns;
    m.mixed_pixels += s.mixed_pixels;
    s = SimResult{};  // free as we go
  }
  return out;
}

BuildingSim simulate_building(const Building& building, const SimOptions& options) {
  std::vector<SimResult> parts;
  for (const Storey& s : building.storeys) parts.push_back(simulate(s.scene, options));
  return merge_storeys(building, std::move(parts));
}

}  // namespace indoormap::sim
