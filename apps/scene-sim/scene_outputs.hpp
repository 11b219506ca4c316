#pragma once
// scene-sim's output set: cloud.pcd, ground_truth.json, ground_truth_layout.{pgm,png,yaml},
// ground_truth_seen.{pgm,yaml}, optionally a 3DTK scan directory and (mobile mode)
// trajectory.txt. With several storeys the per-storey truth goes to storey_<k>/ (each with its own
// ground_truth.json) and ground_truth.json lists the storeys. Every file is written atomically.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "indoormap/sim/building.hpp"
#include "indoormap/sim/floor_scene.hpp"
#include "indoormap/sim/ground_truth.hpp"
#include "indoormap/sim/mobile.hpp"
#include "indoormap/sim/output.hpp"
#include "indoormap/sim/seen.hpp"

namespace indoormap::scene_sim {

using sim::StoreyTruth;

/// What write_building_outputs wrote (file names relative to the output directory).
struct WrittenOutputs {
  std::vector<std::string> files;
};

/// Writes the cloud, the ground truth, the 3DTK scans (options.write_3dtk) and, with mobile, the
/// trajectory (trajectory.txt) and the mobile block of ground_truth.json. The storeys' scenes
/// must be normalised (stack_storeys does it).
WrittenOutputs write_building_outputs(const std::filesystem::path& dir,
                                      const sim::Building& building, const sim::BuildingSim& sim,
                                      const std::vector<StoreyTruth>& truths,
                                      const sim::OutputOptions& options,
                                      const std::optional<sim::MobileParams>& mobile);

}  // namespace indoormap::scene_sim
