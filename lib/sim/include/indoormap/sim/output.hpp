#pragma once
// scene-sim's output options. The outputs of a simulated scene are written by apps/scene-sim with
// lib/cloud_io, lib/formats and lib/draw.
#include <string>

namespace indoormap::sim {

struct OutputOptions {
  double truth_cell_m = 0.05;
  bool write_3dtk = false;  ///< DIR/3dtk/scanNNN.3d + scanNNN.pose
  std::string tdtk_subdir = "3dtk";
  std::string generator = "scene-sim";  ///< recorded in ground_truth.json
};

/// Throws UsageError unless truth_cell_m is in [0.001, 10] m. Called by write_scene_outputs.
void validate(const OutputOptions& options);

}  // namespace indoormap::sim
