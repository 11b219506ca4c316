#pragma once
// Polygon operations of the room border that OpenCV does for us (the Polygon type and its
// Eigen-only operations are in indoormap/core/polygon.hpp).
#include "indoormap/core/polygon.hpp"

namespace indoormap::border {

/// Douglas-Peucker simplification of a closed polygon with tolerance tol (same unit as the
/// vertices). Keeps at least three vertices when the input has them.
Polygon simplify_closed(const Polygon& poly, double tol);
/// Minimum-area enclosing rectangle (rotating calipers on the convex hull): its area.
double min_area_rect_area(const Polygon& poly);

}  // namespace indoormap::border
