#pragma once
// PNG pictures of layouts, with a legend, a scale bar and markers.
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::io {

struct RenderOptions {
  std::string title;
  int min_width_px = 640;   ///< cells are scaled up by an integer factor to reach this width
  std::vector<Eigen::Vector2d> markers_map;  ///< scanner positions etc. (map metres), red crosses
  std::string marker_label = "scanner";
};

/// Renders the layout in colour (unknown grey, wall dark blue, furniture orange, free white),
/// north up, with a legend and a 1 m scale bar, and writes it as PNG atomically.
void write_layout_png(const std::filesystem::path& path, const Grid<Cell>& layout,
                      const GridGeometry& geometry, const RenderOptions& options = {});

}  // namespace indoormap::io
