#pragma once
// scene-sim's output options, and the 3DTK scan writer (every file written atomically). The
// other outputs of a simulated scene are written by apps/scene-sim with lib/formats and lib/draw.
#include <filesystem>
#include <string>
#include <vector>

#include "indoormap/sim/simulate.hpp"

namespace indoormap::sim {

struct OutputOptions {
  double truth_cell_m = 0.05;
  bool write_3dtk = false;      ///< DIR/3dtk/scanNNN.3d + scanNNN.pose
  std::string tdtk_subdir = "3dtk";
  std::string generator = "scene-sim";  ///< recorded in ground_truth.json
};

/// 3DTK scans: one scanNNN.3d per ScanBlock, with points in the scan's local frame (the tilted
/// frame translated to the scanner position; no rotation) converted to 3DTK's left-handed,
/// y-up centimetres (x = -100 Y, y = 100 Z, z = 100 X), and a .pose holding the scanner position
/// in the same units with zero Euler angles. Returns the file names written.
std::vector<std::string> write_3dtk(const std::filesystem::path& dir, const SimResult& sim);

}  // namespace indoormap::sim
