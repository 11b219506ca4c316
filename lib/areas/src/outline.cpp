// Outline polygons (the cell edges around each area), doors and the area graph.
#include "outline.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <opencv2/imgproc.hpp>

#include "indoormap/core/cell_rings.hpp"

namespace indoormap::areas::detail {
namespace {

/// A ring in map metres.
Polygon to_map(const CellRing& ring, const GridGeometry& g) {
  Polygon p;
  p.reserve(ring.size());
  for (const auto& q : ring) p.push_back(g.from_cell_coords(q));
  return p;
}

int find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

/// The largest cluster of boundary midpoints (points at most 1.5 cells apart are one cluster):
/// two areas may touch in several places; the door is the longest stretch.
std::vector<Eigen::Vector2d> largest_stretch(const std::vector<Eigen::Vector2d>& pts) {
  const int n = static_cast<int>(pts.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if ((pts[i] - pts[j]).squaredNorm() <= 2.25) parent[find(parent, i)] = find(parent, j);
  std::vector<int> size(n, 0);
  int best = 0;
  for (int i = 0; i < n; ++i)
    if (++size[find(parent, i)] > size[best]) best = find(parent, i);
  std::vector<Eigen::Vector2d> out;
  for (int i = 0; i < n; ++i)
    if (find(parent, i) == best) out.push_back(pts[i]);
  return out;
}

}  // namespace

void build_outlines(AreasResult& r, const GridGeometry& g, int min_hole_cells) {
  const Grid<std::uint16_t>& lab = r.labels;
  const int n = static_cast<int>(r.areas.size());
  std::vector<cv::Rect> box(n + 1);
  std::vector<int> cells(n + 1, 0);
  for (int y = 0; y < lab.height; ++y)
    for (int x = 0; x < lab.width; ++x) {
      const int l = lab.at(x, y);
      if (!l) continue;
      box[l] = cells[l] ? (box[l] | cv::Rect(x, y, 1, 1)) : cv::Rect(x, y, 1, 1);
      ++cells[l];
    }
  const double cell_area = g.cell_m() * g.cell_m();
  for (Area& a : r.areas) {
    a.cells = cells[a.id];
    a.area_m2 = a.cells * cell_area;
    if (!a.cells) continue;
    const cv::Rect b = box[a.id];
    // The cells' own edges (cell_rings.hpp): neighbouring areas share their borders exactly.
    const CellRings rings = trace_cell_rings(b.x, b.y, b.width, b.height,
                                             [&](int x, int y) { return lab.at(x, y) == a.id; });
    // The outer ring of largest area (an area is one 4-connected piece; should it not be, its
    // smaller pieces get no polygon of their own).
    const CellRing* outer = nullptr;
    for (const auto& ring : rings.outer)
      if (!outer || signed_area(ring) > signed_area(*outer)) outer = &ring;
    if (!outer) continue;
    a.outline_m = to_map(*outer, g);
    for (const auto& hole : rings.holes)
      if (-signed_area(hole) >= min_hole_cells) a.holes_m.push_back(to_map(hole, g));
  }
}

void build_graph(AreasResult& r, const GridGeometry& g) {
  const Grid<std::uint16_t>& lab = r.labels;
  // Shared boundary cells of each pair: the midpoints between 4-adjacent cells of a and b.
  std::map<std::pair<int, int>, std::vector<Eigen::Vector2d>> shared;
  for (int y = 0; y < lab.height; ++y)
    for (int x = 0; x < lab.width; ++x) {
      const int a = lab.at(x, y);
      if (!a) continue;
      const int nb[2][2] = {{x + 1, y}, {x, y + 1}};
      for (const auto& q : nb) {
        if (!lab.contains(q[0], q[1])) continue;
        const int b = lab.at(q[0], q[1]);
        if (!b || b == a) continue;
        shared[{std::min(a, b), std::max(a, b)}].push_back(
            {0.5 * (x + q[0]) + 0.5, 0.5 * (y + q[1]) + 0.5});
      }
    }
  const int n = static_cast<int>(r.areas.size());
  std::vector<int> parent(n + 1);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [pair, all] : shared) {
    if (all.size() < 2) continue;  // a diagonal touch is no passage
    const std::vector<Eigen::Vector2d> pts = largest_stretch(all);
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const auto& p : pts) mean += p;
    mean /= static_cast<double>(pts.size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (const auto& p : pts) cov += (p - mean) * (p - mean).transpose();
    const Eigen::Vector2d axis =
        (cov(0, 0) >= cov(1, 1)) ? Eigen::Vector2d(1, 0) : Eigen::Vector2d(0, 1);
    Eigen::Vector2d dir = axis;
    if (cov.norm() > 0.0) {
      const double ang = 0.5 * std::atan2(2.0 * cov(0, 1), cov(0, 0) - cov(1, 1));
      dir = {std::cos(ang), std::sin(ang)};
    }
    double lo = 1e300, hi = -1e300;
    for (const auto& p : pts) {
      lo = std::min(lo, (p - mean).dot(dir));
      hi = std::max(hi, (p - mean).dot(dir));
    }
    Door d;
    d.a = pair.first;
    d.b = pair.second;
    d.end0_m = g.from_cell_coords(mean + lo * dir);
    d.end1_m = g.from_cell_coords(mean + hi * dir);
    d.width_m = (d.end1_m - d.end0_m).norm() + g.cell_m();
    d.shared_cells = static_cast<int>(all.size());
    r.doors.push_back(d);
    r.areas[d.a - 1].neighbours.push_back(d.b);
    r.areas[d.b - 1].neighbours.push_back(d.a);
    parent[find(parent, d.a)] = find(parent, d.b);
  }
  for (Area& a : r.areas) std::sort(a.neighbours.begin(), a.neighbours.end());
  r.graph_components = 0;
  for (int i = 1; i <= n; ++i)
    if (find(parent, i) == i) ++r.graph_components;
}

}  // namespace indoormap::areas::detail
