#pragma once
// The one palette: the cell classes (two colour sets, one per family of pictures, so that every
// picture keeps the colours it has always had) and the object kinds.
#include <array>
#include <cstdint>
#include <opencv2/core.hpp>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/object_kind.hpp"

namespace indoormap::draw {

enum class CellColours {
  kMap,    ///< pcd-to-map / furniture-extract pictures: wall dark blue, furniture orange
  kTruth,  ///< scene-sim's ground-truth layout: wall dark grey, furniture orange-brown
};

/// BGR colour of a cell class (free white, unknown grey in both sets).
cv::Scalar cell_colour(Cell c, CellColours set = CellColours::kMap);

/// RGB colour of an object kind, the same in every picture that draws objects by kind. The six
/// (purple, blue, dark teal, red, near-black, olive) differ pairwise by at least 30 CIEDE2000
/// units, each by at least 25 from the furniture, free and unknown cells it is drawn over, and
/// each has a contrast of at least 3 with white (tests/test_draw.cpp).
std::array<std::uint8_t, 3> kind_rgb(ObjectKind kind);

/// kind_rgb as an OpenCV (BGR) colour.
cv::Scalar kind_colour(ObjectKind kind);

}  // namespace indoormap::draw
