#pragma once
// scene-sim's ground_truth.json (docs/scene-sim.md, docs/evaluation.md): the writer, and the
// reader of map-eval. Users of this header link im_sim for the value types.
#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "indoormap/core/grid.hpp"
#include "indoormap/sim/eval.hpp"
#include "indoormap/sim/floor_eval.hpp"
#include "indoormap/sim/ground_truth.hpp"
#include "indoormap/sim/scene.hpp"
#include "indoormap/sim/simulate.hpp"

namespace indoormap::formats {

/// The file names ground_truth.json refers to (in the same directory).
inline constexpr const char* kTruthCloud = "cloud.pcd";
inline constexpr const char* kTruthLayoutImage = "ground_truth_layout.pgm";
inline constexpr const char* kTruthLayoutPicture = "ground_truth_layout.png";
inline constexpr const char* kTruthLayoutYaml = "ground_truth_layout.yaml";

/// ground_truth.json for a simulated scene: rooms (polygon, area, ceiling, doors, windows),
/// furniture (sim::furniture_truth), scanners, scanner model, cloud statistics and the layout
/// image's grid. scene must be normalised (sim::normalised) as given to the truth functions;
/// generator is recorded with the version ("scene-sim" -> "scene-sim 0.1.0").
nlohmann::ordered_json ground_truth_json(const sim::Scene& scene, const sim::SimResult& sim,
                                         const sim::TruthLayout& layout,
                                         const std::string& generator);
/// The "tdtk" block of ground_truth.json when a 3DTK scan directory was written beside it.
nlohmann::ordered_json ground_truth_tdtk_json(const std::string& subdir, std::size_t scans);

/// ground_truth.json as map-eval reads it.
struct TruthFile {
  std::filesystem::path path;
  std::vector<sim::TruthRoom> rooms;
  std::vector<sim::EvalObject> furniture;
  std::filesystem::path layout_image;  ///< resolved against the JSON's directory
  GridGeometry layout_geometry;
  /// Optional in the file (older ground truths have none of these):
  std::vector<sim::TruthDoor> doors;           ///< rooms[].doors[] (id "<room>.door<j>")
  std::vector<Eigen::Vector2d> scanners_xy_m;  ///< scanners[].position_m, scene frame
  struct Storey {
    int k = 0;
    double floor_z_m = 0.0, ceiling_z_m = 0.0;
    std::filesystem::path ground_truth;  ///< resolved; the storey's own ground_truth.json
  };
  std::vector<Storey> storeys;  ///< "storeys" (scene-sim --storeys S > 1)
};

/// Reads ground_truth.json (as written by scene-sim). Throws InputError naming the file and key.
TruthFile read_truth_json(const std::filesystem::path& path);

}  // namespace indoormap::formats
