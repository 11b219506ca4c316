#include "scene_outputs.hpp"

#include <span>

#include "indoormap/cloud_io/write.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/draw/layout_png.hpp"
#include "indoormap/formats/ground_truth_json.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/formats/pgm.hpp"
#include "indoormap/formats/ros_map.hpp"
#include "indoormap/formats/trajectory.hpp"
#include "indoormap/sim/world.hpp"

namespace indoormap::scene_sim {

namespace fs = std::filesystem;
using namespace sim;

namespace {

constexpr const char* kSeenImage = "ground_truth_seen.pgm";
constexpr const char* kSeenYaml = "ground_truth_seen.yaml";
constexpr const char* kTrajectory = "trajectory.txt";

/// The simulated scans as 3DTK scan files (cloud_io::write_3dtk_scans: scan-local, left-handed,
/// y-up centimetres), one per ScanBlock.
std::vector<std::string> write_3dtk(const fs::path& dir, const SimResult& sim) {
  std::vector<cloud_io::TdtkScan> scans;
  for (const ScanBlock& b : sim.scans)
    scans.push_back({std::span(sim.points).subspan(b.begin, b.end - b.begin),
                     sim.scanner_positions_m[b.scanner]});
  return cloud_io::write_3dtk_scans(dir, scans);
}

/// The statistics and scanner positions of storey k only (no points: ground_truth_json reads
/// scanner_positions_m and the counts).
SimResult storey_view(const BuildingSim& b, int k) {
  SimResult v;
  for (std::size_t s = 0; s < b.scanner_storey.size(); ++s)
    if (b.scanner_storey[s] == k) v.scanner_positions_m.push_back(b.sim.scanner_positions_m[s]);
  for (const ScanBlock& sb : b.sim.scans)
    if (b.scanner_storey[sb.scanner] == k) {
      v.scans.push_back(sb);
      v.returns += sb.end - sb.begin;
    }
  return v;
}

/// The truth files of one storey in dir / sub ("" or "storey_<k>/"); returns the storey's JSON.
nlohmann::ordered_json write_storey(const fs::path& dir, const std::string& sub, const Storey& st,
                                    const SimResult& view, const StoreyTruth& t,
                                    const OutputOptions& options, std::vector<std::string>& files) {
  ensure_writable_dir(dir / sub);
  formats::write_layout_pgm(dir / sub / formats::kTruthLayoutImage, t.layout.cells);
  std::vector<Eigen::Vector2d> markers;
  for (const auto& s : st.scene.scanners) markers.push_back(s.position_m.head<2>());
  draw::write_truth_layout_png(dir / sub / formats::kTruthLayoutPicture, t.layout.cells,
                               t.layout.geometry, markers);
  formats::write_map_yaml(dir / sub / formats::kTruthLayoutYaml,
                          formats::map_meta(formats::kTruthLayoutImage, t.layout.geometry),
                          formats::MapYamlStyle::kShortest);
  formats::write_pgm(dir / sub / kSeenImage, seen_image(t.seen));
  formats::write_map_yaml(dir / sub / kSeenYaml, formats::map_meta(kSeenImage, t.layout.geometry),
                          formats::MapYamlStyle::kShortest);
  for (const char* f : {formats::kTruthLayoutImage, formats::kTruthLayoutPicture,
                        formats::kTruthLayoutYaml, kSeenImage, kSeenYaml})
    files.push_back(sub + f);
  return formats::ground_truth_json(st.scene, view, t.layout, options.generator);
}

}  // namespace

WrittenOutputs write_building_outputs(const fs::path& dir, const Building& building,
                                      const BuildingSim& bsim,
                                      const std::vector<StoreyTruth>& truths,
                                      const OutputOptions& options,
                                      const std::optional<MobileParams>& mobile) {
  validate(options);
  ensure_writable_dir(dir);
  WrittenOutputs out;
  const SimResult& sim = bsim.sim;
  const Eigen::Vector3d viewpoint =
      sim.scanner_positions_m.empty() ? Eigen::Vector3d::Zero() : sim.scanner_positions_m.front();
  cloud_io::write_pcd_binary((dir / formats::kTruthCloud).string(), sim.points, viewpoint);
  out.files.push_back(formats::kTruthCloud);

  const bool multi = building.storeys.size() > 1;
  nlohmann::ordered_json j;
  nlohmann::ordered_json storeys = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < building.storeys.size(); ++k) {
    const Storey& st = building.storeys[k];
    const std::string sub = multi ? "storey_" + std::to_string(k) + "/" : "";
    if (!multi) {
      j = write_storey(dir, sub, st, sim, truths[k], options, out.files);
      continue;
    }
    const SimResult view = storey_view(bsim, static_cast<int>(k));
    nlohmann::ordered_json js = write_storey(dir, sub, st, view, truths[k], options, out.files);
    js["storey"] = k;
    js["floor_z_m"] = st.floor_z_m;
    js["ceiling_z_m"] = st.ceiling_z_m;
    js["frame"] =
        "storey frame: the scene frame with z measured from this storey's floor "
        "(z_scene = z + floor_z_m); position_cloud_m is in the merged cloud's frame";
    js["cloud"]["file"] = "../" + std::string(formats::kTruthCloud);
    js["cloud"]["points"] = view.returns;
    js["cloud"]["note"] = "points and scans of this storey in the merged cloud";
    formats::write_json(dir / sub / "ground_truth.json", js);
    out.files.push_back(sub + "ground_truth.json");
    storeys.push_back({{"k", k},
                       {"directory", "storey_" + std::to_string(k)},
                       {"ground_truth", sub + "ground_truth.json"},
                       {"floor_z_m", st.floor_z_m},
                       {"ceiling_z_m", st.ceiling_z_m},
                       {"rooms", js["rooms"]},
                       {"furniture", js["furniture"]},
                       {"scanners", js["scanners"]}});
    if (k == 0) j = js;
  }
  if (multi) {
    // The top level is storey 0 (its layout under storey_0/) plus the list of every storey.
    for (const char* key : {"image", "picture", "yaml"})
      j["layout"][key] = "storey_0/" + j["layout"][key].get<std::string>();
    j["cloud"] = {{"file", formats::kTruthCloud},     {"frame", "tilted"},
                  {"points", sim.points.size()},      {"rays", sim.rays},
                  {"mixed_pixels", sim.mixed_pixels}, {"scans", sim.scans.size()}};
    j.erase("storey");
    j["frame"] =
        "scene frame: metres, right-handed, z up, storey k's floor at z = floor_z_m. "
        "The cloud is in the tilted frame: p_cloud = tilt.rotation * p_scene.";
    j["storeys"] = storeys;
  }
  if (mobile) {
    std::vector<ScannerPose> poses;
    for (const Storey& st : building.storeys)
      for (ScannerPose p : st.scene.scanners) {
        p.position_m.z() += st.floor_z_m;
        poses.push_back(p);
      }
    formats::write_tum_trajectory(
        dir / kTrajectory,
        trajectory(poses, building.storeys.front().scene.tilt, mobile->speed_m_s));
    out.files.push_back(kTrajectory);
    j["mobile"] = {{"trajectory", kTrajectory},
                   {"positions", poses.size()},
                   {"step_m", mobile->step_m},
                   {"ray_share", mobile->ray_share},
                   {"beams", mobile->beams},
                   {"elevation_min_deg", mobile->elevation_min_deg},
                   {"elevation_max_deg", mobile->elevation_max_deg},
                   {"sensor_height_m", mobile->sensor_height_m},
                   {"viewpoint", "cloud.pcd's VIEWPOINT is the first position only"}};
  }
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
