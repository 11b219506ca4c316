#pragma once
// The one palette of the cell classes. Two colour sets exist, one per family of pictures, so that
// every picture keeps the colours it has always had.
#include <opencv2/core.hpp>

#include "indoormap/core/cell.hpp"

namespace indoormap::draw {

enum class CellColours {
  kMap,    ///< pcd-to-map / furniture-extract pictures: wall dark blue, furniture orange
  kTruth,  ///< scene-sim's ground-truth layout: wall dark grey, furniture orange-brown
};

/// BGR colour of a cell class (free white, unknown grey in both sets).
cv::Scalar cell_colour(Cell c, CellColours set = CellColours::kMap);

}  // namespace indoormap::draw
