#pragma once
// Small 2D polygon helpers shared by the simulator, the ground truth and the evaluation.
// Polygons are vertex lists without a repeated closing vertex, in metres.
#include <Eigen/Core>
#include <vector>

namespace indoormap::sim {

using Polygon2 = std::vector<Eigen::Vector2d>;

/// Signed area (positive for counter-clockwise order).
double signed_area(const Polygon2& poly);

/// Even-odd point-in-polygon test; works for non-convex simple polygons.
bool contains(const Polygon2& poly, const Eigen::Vector2d& p);

/// True when no two non-adjacent edges intersect and no edge has zero length.
bool is_simple(const Polygon2& poly);

/// True for a counter-clockwise convex polygon (collinear vertices allowed).
bool is_convex_ccw(const Polygon2& poly);

/// Keeps the part of a convex polygon where n . p <= offset.
Polygon2 clip_halfplane(const Polygon2& poly, const Eigen::Vector2d& n, double offset);

/// Axis-aligned bounding box as (min, max).
std::pair<Eigen::Vector2d, Eigen::Vector2d> bounds(const Polygon2& poly);

/// Rectangle of the given full size centred at c, rotated by yaw (radians), counter-clockwise.
Polygon2 rectangle(const Eigen::Vector2d& c, const Eigen::Vector2d& size, double yaw_rad);

/// Regular n-gon with the same area as the circle of radius r, counter-clockwise.
Polygon2 circle_polygon(const Eigen::Vector2d& c, double r, int n = 32);

/// Symmetric Hausdorff distance between the boundaries of two polygons, both sampled every
/// step_m along their edges (vertices included).
double boundary_hausdorff(const Polygon2& a, const Polygon2& b, double step_m = 0.01);

/// Intersection-over-union of two simple polygons, by rasterising both at cell_m.
double polygon_iou(const Polygon2& a, const Polygon2& b, double cell_m = 0.01);

}  // namespace indoormap::sim
