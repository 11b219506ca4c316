#pragma once
// explore-sim's pictures (docs/explore-sim.md): the built map with the robot's path, and a strip
// of snapshots of the run. Values only: cells, points in map metres, captions.
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::draw {

/// One moment of a run: the map built so far, the path driven so far, the robot's position.
struct ExplorePanel {
  Grid<Cell> cells;
  std::vector<Eigen::Vector2d> path_m;  ///< map frame
  Eigen::Vector2d robot_m = Eigen::Vector2d::Zero();
  std::string caption;  ///< e.g. "120 s, 48 m, 63 %"
};

/// explore.png: the built map (north up) with the path (blue), the start (red cross) and the
/// end (green dot), a legend and a 1 m scale bar.
void write_explore_png(const std::filesystem::path& path, const ExplorePanel& final_map,
                       const GridGeometry& geometry, const Eigen::Vector2d& start_m,
                       const std::string& title);

/// explore_strip.png: the panels side by side, each scaled to panel_width_px (about), its
/// caption above it; one legend and a 1 m scale bar below. Throws OutputError.
void write_explore_strip_png(const std::filesystem::path& path,
                             const std::vector<ExplorePanel>& panels, const GridGeometry& geometry,
                             const std::string& title, int panel_width_px = 300);

}  // namespace indoormap::draw
