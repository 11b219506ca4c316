#pragma once
// border.png (pcd-to-map, docs/border-closure.md). Users of this header link im_border and
// im_layout for the value types.
#include <filesystem>

#include "indoormap/border/border.hpp"
#include "indoormap/layout/pipeline.hpp"

namespace indoormap::draw {

/// The layout (north up) with the heavy border tinted, the chain, the polygon, the openings,
/// the interior objects and the scanners; a legend and a 1 m scale bar below.
void write_border_png(const std::filesystem::path& path, const layout::MapResult& map,
                      const border::BorderResult& border);

}  // namespace indoormap::draw
