#include "scene_outputs.hpp"

#include <span>

#include "indoormap/cloud_io/write.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/draw/layout_png.hpp"
#include "indoormap/formats/ground_truth_json.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/formats/pgm.hpp"
#include "indoormap/formats/ros_map.hpp"
#include "indoormap/sim/world.hpp"

namespace indoormap::scene_sim {

namespace fs = std::filesystem;
using namespace sim;

namespace {

/// The simulated scans as 3DTK scan files (cloud_io::write_3dtk_scans: scan-local, left-handed,
/// y-up centimetres), one per ScanBlock.
std::vector<std::string> write_3dtk(const fs::path& dir, const SimResult& sim) {
  std::vector<cloud_io::TdtkScan> scans;
  for (const ScanBlock& b : sim.scans)
    scans.push_back({std::span(sim.points).subspan(b.begin, b.end - b.begin),
                     sim.scanner_positions_m[b.scanner]});
  return cloud_io::write_3dtk_scans(dir, scans);
}

}  // namespace

WrittenOutputs write_scene_outputs(const fs::path& dir, const Scene& input, const SimResult& sim,
                                   const OutputOptions& options) {
  validate(options);
  ensure_writable_dir(dir);
  const Scene scene = normalised(input);
  const SceneGeometry geometry = build_geometry(scene);
  WrittenOutputs out;
  out.layout = truth_layout(scene, geometry, options.truth_cell_m);

  const Eigen::Vector3d viewpoint =
      sim.scanner_positions_m.empty() ? Eigen::Vector3d::Zero() : sim.scanner_positions_m.front();
  cloud_io::write_pcd_binary((dir / formats::kTruthCloud).string(), sim.points, viewpoint);
  out.files.push_back(formats::kTruthCloud);

  formats::write_layout_pgm(dir / formats::kTruthLayoutImage, out.layout.cells);
  std::vector<Eigen::Vector2d> markers;
  for (const auto& s : scene.scanners) markers.push_back(s.position_m.head<2>());
  draw::write_truth_layout_png(dir / formats::kTruthLayoutPicture, out.layout.cells,
                               out.layout.geometry, markers);
  formats::write_map_yaml(dir / formats::kTruthLayoutYaml,
                          formats::map_meta(formats::kTruthLayoutImage, out.layout.geometry),
                          formats::MapYamlStyle::kShortest);
  out.files.insert(out.files.end(), {formats::kTruthLayoutImage, formats::kTruthLayoutPicture,
                                     formats::kTruthLayoutYaml});

  nlohmann::ordered_json j = formats::ground_truth_json(scene, sim, out.layout, options.generator);
  if (options.write_3dtk) {
    auto files = write_3dtk(dir / options.tdtk_subdir, sim);
    for (auto& f : files) out.files.push_back(options.tdtk_subdir + "/" + f);
    j["tdtk"] = formats::ground_truth_tdtk_json(options.tdtk_subdir, sim.scans.size());
  }
  formats::write_json(dir / "ground_truth.json", j);
  out.files.push_back("ground_truth.json");
  return out;
}

}  // namespace indoormap::scene_sim
