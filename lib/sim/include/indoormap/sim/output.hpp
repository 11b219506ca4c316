#pragma once
// Writing a simulated scene: cloud.pcd, ground_truth.json, ground_truth_layout.{pgm,png,yaml} and
// optionally a 3DTK scan directory. Every file is written atomically.
#include <filesystem>
#include <string>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/sim/ground_truth.hpp"
#include "indoormap/sim/scene.hpp"
#include "indoormap/sim/simulate.hpp"

namespace indoormap::sim {

struct OutputOptions {
  double truth_cell_m = 0.05;
  bool write_3dtk = false;      ///< DIR/3dtk/scanNNN.3d + scanNNN.pose
  std::string tdtk_subdir = "3dtk";
  std::string generator = "scene-sim";  ///< recorded in ground_truth.json
};

/// Throws UsageError unless truth_cell_m is in [0.001, 10] m. Called by write_scene_outputs.
void validate(const OutputOptions& options);

/// What write_scene_outputs wrote (file names relative to the output directory).
struct WrittenOutputs {
  std::vector<std::string> files;
  TruthLayout layout;
};

/// Writes the cloud, the ground truth and (optionally) the 3DTK scans for a simulated scene.
/// scene must be the scene given to simulate(); it is normalised here the same way.
WrittenOutputs write_scene_outputs(const std::filesystem::path& dir, const Scene& scene,
                                   const SimResult& sim, const OutputOptions& options = {});

/// 8-bit binary PGM (P5) of the raw cell values, image row 0 = highest y (north up).
void write_layout_pgm(const std::filesystem::path& path, const Grid<Cell>& cells);
/// Colour picture of a layout with a legend, image row 0 = highest y.
void write_layout_png(const std::filesystem::path& path, const Grid<Cell>& cells,
                      const GridGeometry& geometry,
                      const std::vector<Eigen::Vector2d>& markers_m = {});
/// A ROS map_server YAML (image, resolution, origin, negate, occupied_thresh, free_thresh).
void write_map_yaml(const std::filesystem::path& path, const std::string& image,
                    const GridGeometry& geometry);

/// 3DTK scans: one scanNNN.3d per ScanBlock, with points in the scan's local frame (the tilted
/// frame translated to the scanner position; no rotation) converted to 3DTK's left-handed,
/// y-up centimetres (x = -100 Y, y = 100 Z, z = 100 X), and a .pose holding the scanner position
/// in the same units with zero Euler angles. Returns the file names written.
std::vector<std::string> write_3dtk(const std::filesystem::path& dir, const SimResult& sim);

/// Reads an 8-bit binary PGM (P5, maxval <= 255). Throws InputError naming the file.
Grid<std::uint8_t> read_pgm(const std::filesystem::path& path, bool flip_rows_to_y_up = true);

}  // namespace indoormap::sim
