#pragma once
// PNG pictures of layouts (layout.png, objects.png, ground_truth_layout.png), with a legend, a
// scale bar and markers.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"
#include "indoormap/draw/canvas.hpp"

namespace indoormap::draw {

/// A polyline or polygon drawn over the layout, with an optional text label. Labels are placed
/// without overlap (place_labels): on the label point, or beside it with a leader line; a label
/// with no free place is left off the map and its table_row goes to RenderOptions::unlabelled.
struct Overlay {
  std::vector<Eigen::Vector2d> points_m;  ///< map frame
  bool closed = true;
  std::string label;
  /// The point the label names (map frame); the mean of points_m when absent.
  std::optional<Eigen::Vector2d> label_at_m;
  std::vector<std::string> table_row;  ///< its row of `unlabelled` when the label finds no place
  std::array<std::uint8_t, 3> rgb = {200, 0, 160};
  int thickness_px = 2;
};

struct RenderOptions {
  std::string title;
  int min_width_px = 640;  ///< cells are scaled up by an integer factor to reach this width
  std::vector<Eigen::Vector2d> markers_map;  ///< scanner positions etc. (map metres), red crosses
  std::string marker_label = "scanner";
  std::vector<Overlay> overlays;
  /// Extra legend entries (label, colour) for the overlays.
  std::vector<std::pair<std::string, std::array<std::uint8_t, 3>>> legend;
  /// Drawn below the legend: title, header and column widths as given, one row per overlay whose
  /// label found no place (its table_row), in the overlays' order.
  LegendTable unlabelled;
};

/// Renders the layout in colour (CellColours::kMap), north up, with the overlays and their labels,
/// a legend (wrapped onto more rows when it does not fit the width) ending in the 1 m scale bar,
/// and the table of unlabelled overlays; writes it as PNG atomically.
void write_layout_png(const std::filesystem::path& path, const Grid<Cell>& layout,
                      const GridGeometry& geometry, const RenderOptions& options = {});

/// scene-sim's picture of the true layout (CellColours::kTruth, up to 8 px per cell, about 900
/// px wide), the scanner positions as red dots, a legend of the classes; north up.
void write_truth_layout_png(const std::filesystem::path& path, const Grid<Cell>& cells,
                            const GridGeometry& geometry,
                            const std::vector<Eigen::Vector2d>& markers_m = {});

}  // namespace indoormap::draw
