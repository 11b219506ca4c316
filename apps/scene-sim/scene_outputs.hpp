#pragma once
// scene-sim's output set: cloud.pcd, ground_truth.json, ground_truth_layout.{pgm,png,yaml} and
// optionally a 3DTK scan directory. Every file is written atomically.
#include <filesystem>
#include <string>
#include <vector>

#include "indoormap/sim/ground_truth.hpp"
#include "indoormap/sim/output.hpp"
#include "indoormap/sim/scene.hpp"
#include "indoormap/sim/simulate.hpp"

namespace indoormap::scene_sim {

/// What write_scene_outputs wrote (file names relative to the output directory).
struct WrittenOutputs {
  std::vector<std::string> files;
  sim::TruthLayout layout;
};

/// Writes the cloud, the ground truth and (optionally) the 3DTK scans for a simulated scene.
/// scene must be the scene given to simulate(); it is normalised here the same way.
WrittenOutputs write_scene_outputs(const std::filesystem::path& dir, const sim::Scene& scene,
                                   const sim::SimResult& sim,
                                   const sim::OutputOptions& options = {});

}  // namespace indoormap::scene_sim
