#include "indoormap/sim/floor_scene.hpp"

#include "indoormap/core/errors.hpp"
#include "indoormap/sim/world.hpp"

namespace indoormap::sim {

std::vector<StoreyTruth> storey_truths(const Building& building, const BuildingSim& sim,
                                       double truth_cell_m, const SeenParams& seen) {
  std::vector<StoreyTruth> out;
  const Tilt tilt = building.storeys.front().scene.tilt;
  for (std::size_t k = 0; k < building.storeys.size(); ++k) {
    const Storey& st = building.storeys[k];
    StoreyTruth t;
    t.layout = truth_layout(st.scene, build_geometry(st.scene), truth_cell_m);
    t.seen = seen_cells(t.layout, sim.sim, tilt, sim.scanner_storey, static_cast<int>(k),
                        st.floor_z_m, seen);
    out.push_back(std::move(t));
  }
  return out;
}

std::vector<MobilePath> plan_mobile_paths(Building& building, const MobileParams& params,
                                          double truth_cell_m) {
  std::vector<MobilePath> out;
  for (std::size_t k = 0; k < building.storeys.size(); ++k) {
    Scene& sc = building.storeys[k].scene;
    const TruthLayout L = truth_layout(sc, build_geometry(sc), truth_cell_m);
    MobilePath path = plan_mobile_path(sc, L, params);
    if (path.poses.empty())
      throw InputError("<mobile path>",
                       "storey " + std::to_string(k) + ": no path could be planned");
    sc.scanners = path.poses;
    out.push_back(std::move(path));
  }
  return out;
}

BuildingSim simulate_storeys(const Building& building, const SimOptions& options,
                             const MobileParams* mobile) {
  std::vector<SimResult> parts;
  for (const Storey& st : building.storeys)
    parts.push_back(mobile ? simulate_mobile(st.scene, *mobile, options)
                           : simulate(st.scene, options));
  return merge_storeys(building, std::move(parts));
}

FloorScene simulate_floor_scene(std::uint64_t seed, const FloorSceneParams& p) {
  FloorScene f;
  f.building = random_building(seed, p.building);
  for (auto& st : f.building.storeys) st.scene.scanner = p.scanner;
  if (p.mobile) f.paths = plan_mobile_paths(f.building, p.mobile_params, p.truth_cell_m);
  f.sim = simulate_storeys(f.building, p.sim, p.mobile ? &p.mobile_params : nullptr);
  f.truths = storey_truths(f.building, f.sim, p.truth_cell_m, p.seen);
  return f;
}

}  // namespace indoormap::sim
