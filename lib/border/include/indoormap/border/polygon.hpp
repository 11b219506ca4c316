#pragma once
// Small polygon helpers for the room border (map metres or cell units alike). Polygons are vertex
// lists without a repeated closing vertex.
#include <Eigen/Core>
#include <vector>

namespace indoormap::border {

using Polygon = std::vector<Eigen::Vector2d>;

/// Signed area (positive when counter-clockwise).
double signed_area(const Polygon& poly);
/// Length of the closed boundary.
double perimeter(const Polygon& poly);
/// Even-odd point-in-polygon test; valid for any simple polygon, convex or not.
bool contains(const Polygon& poly, const Eigen::Vector2d& p);
/// True when no two edges intersect except consecutive edges at their shared vertex, and no
/// edge has zero length. O(n^2): meant for simplified polygons and tests.
bool is_simple(const Polygon& poly);
/// Douglas-Peucker simplification of a closed polygon with tolerance tol (same unit as the
/// vertices). Keeps at least three vertices when the input has them.
Polygon simplify_closed(const Polygon& poly, double tol);
/// Minimum-area enclosing rectangle (rotating calipers on the convex hull): its area.
double min_area_rect_area(const Polygon& poly);

}  // namespace indoormap::border
