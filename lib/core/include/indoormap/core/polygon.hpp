#pragma once
// The one polygon type of the toolkit and its operations (Eigen only). A polygon is a vertex list
// without a repeated closing vertex; its unit and frame are the caller's (map metres for every
// polygon in a result or a file, cell units inside some algorithms). Counter-clockwise polygons
// have a positive signed area.
#include <Eigen/Core>
#include <utility>
#include <vector>

namespace indoormap {

using Polygon = std::vector<Eigen::Vector2d>;

/// Signed area (positive when counter-clockwise).
double signed_area(const Polygon& poly);
/// Length of the closed boundary.
double perimeter(const Polygon& poly);
/// Even-odd point-in-polygon test; valid for any simple polygon, convex or not.
bool contains(const Polygon& poly, const Eigen::Vector2d& p);
/// True when no two edges intersect except consecutive edges at their shared vertex (which must
/// not fold back onto each other), and no edge has zero length. O(n^2).
bool is_simple(const Polygon& poly);
/// True for a counter-clockwise convex polygon (collinear vertices allowed).
bool is_convex_ccw(const Polygon& poly);
/// Keeps the part of a convex polygon where n . p <= offset.
Polygon clip_halfplane(const Polygon& poly, const Eigen::Vector2d& n, double offset);
/// Axis-aligned bounding box as (min, max).
std::pair<Eigen::Vector2d, Eigen::Vector2d> bounds(const Polygon& poly);
/// Rectangle of the given full size centred at c, rotated by yaw (radians), counter-clockwise.
Polygon rectangle(const Eigen::Vector2d& c, const Eigen::Vector2d& size, double yaw_rad);
/// Axis-aligned rectangle [lo, hi], counter-clockwise from lo.
Polygon box_polygon(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi);
/// Regular n-gon with the same area as the circle of radius r, counter-clockwise.
Polygon circle_polygon(const Eigen::Vector2d& c, double r, int n = 32);
/// Distance from p to the segment [a, b].
double point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                              const Eigen::Vector2d& b);
/// Symmetric Hausdorff distance between the boundaries of two polygons, both sampled every
/// step (same unit as the vertices) along their edges, vertices included.
double boundary_hausdorff(const Polygon& a, const Polygon& b, double step = 0.01);
/// Intersection-over-union of two simple polygons, by rasterising both at cell (at most about
/// 4 M raster cells: the cell grows for large polygons).
double polygon_iou(const Polygon& a, const Polygon& b, double cell = 0.01);

}  // namespace indoormap
