// The fallback of the fit to the wall faces: the chain polygon's edges moved inwards to the face.
// Its sampling constants are in cells on purpose: it samples the layout in sub-cell steps.
#include <Eigen/LU>
#include <cmath>

#include "internal.hpp"

namespace indoormap::border::detail {

// Moves every edge of a counter-clockwise polygon (cell units, vertices at cell centres) inwards
// to the wall face: the median, over samples along the edge, of the distance to the first
// room-space (free / furniture) cell. Vertices are the intersections of consecutive moved edges
// (or the vertex moved along the mean normal when they are nearly parallel). Returns nullopt when
// the result is not simple.
std::optional<Polygon> snap_to_faces(const Polygon& poly, const Grid<Cell>& layout,
                                     double max_shift) {
  const std::size_t n = poly.size();
  if (n < 3 || max_shift <= 0) return std::nullopt;
  auto room_at = [&](const Eigen::Vector2d& p) {
    const int c = static_cast<int>(std::lround(p.x())), r = static_cast<int>(std::lround(p.y()));
    if (!layout.contains(c, r)) return false;
    const Cell v = layout.at(c, r);
    return v == Cell::kFree || v == Cell::kFurniture;
  };
  constexpr double step = 0.25;
  std::vector<double> shift(n, -1.0), all_hits;
  std::vector<Eigen::Vector2d> normal(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = poly[i], b = poly[(i + 1) % n];
    const Eigen::Vector2d d = b - a;
    const double len = d.norm();
    normal[i] = Eigen::Vector2d(-d.y(), d.x()) / len;  // inward for counter-clockwise order
    std::vector<double> hits;
    const int samples = std::max(1, static_cast<int>(len));
    for (int k = 0; k <= samples; ++k) {
      const double t = 0.15 + 0.7 * k / samples;  // skip the corners
      const Eigen::Vector2d p = a + d * t;
      for (double s = 0.0; s <= max_shift + 1.0; s += step)
        if (room_at(p + normal[i] * s)) {
          // The face is half a cell before the centre of the first room cell; the hit point lies
          // on average a quarter step past the cell boundary.
          hits.push_back(std::max(0.0, s - 0.5 * step));
          break;
        }
    }
    all_hits.insert(all_hits.end(), hits.begin(), hits.end());
    // Short edges (corner chamfers, door jambs) give noisy medians: they take the global one.
    if (hits.size() < 6) continue;
    std::nth_element(hits.begin(), hits.begin() + hits.size() / 2, hits.end());
    shift[i] = std::min(max_shift, hits[hits.size() / 2]);
  }
  if (all_hits.empty()) return std::nullopt;
  std::nth_element(all_hits.begin(), all_hits.begin() + all_hits.size() / 2, all_hits.end());
  const double global = std::min(max_shift, all_hits[all_hits.size() / 2]);
  for (auto& v : shift)
    if (v < 0) v = global;
  Polygon out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t p = (i + n - 1) % n;  // edge p ends at vertex i, edge i starts there
    const Eigen::Vector2d n1 = normal[p], n2 = normal[i];
    const double c = n1.x() * n2.y() - n1.y() * n2.x();
    if (std::abs(c) < 0.2) {
      const Eigen::Vector2d m = (n1 + n2).normalized();
      out[i] = poly[i] + m * (0.5 * (shift[p] + shift[i]));
      continue;
    }
    // Solve n1.x = n1.v + s1 and n2.x = n2.v + s2 for the moved lines through v = poly[i].
    Eigen::Matrix2d A;
    A << n1.x(), n1.y(), n2.x(), n2.y();
    const Eigen::Vector2d rhs(n1.dot(poly[i]) + shift[p], n2.dot(poly[i]) + shift[i]);
    out[i] = A.inverse() * rhs;
    if ((out[i] - poly[i]).norm() > 3.0 * max_shift + 1.0) return std::nullopt;
  }
  // Corner completion: the shortest path cuts every corner of the ring by up to its width, so a
  // room corner becomes a short chamfer edge. A short edge between two longer ones that turn by
  // more than 45 degrees is replaced by the intersection of those two (the wall corner).
  const double chamfer_max = 2.0 * max_shift + 2.0;
  for (bool changed = true; changed && out.size() > 4;) {
    changed = false;
    const std::size_t m = out.size();
    for (std::size_t i = 0; i < m; ++i) {
      const Eigen::Vector2d a = out[(i + m - 1) % m], b = out[i], c = out[(i + 1) % m],
                            d = out[(i + 2) % m];
      const double len = (c - b).norm();
      if (len > chamfer_max || (b - a).norm() < len || (d - c).norm() < len) continue;
      const Eigen::Vector2d u = (b - a).normalized(), v = (d - c).normalized();
      const double cr = u.x() * v.y() - u.y() * v.x();
      if (std::abs(cr) < std::sin(M_PI / 4)) continue;
      const double t = ((c - a).x() * v.y() - (c - a).y() * v.x()) / cr;  // a + u t on line (c, v)
      const Eigen::Vector2d x = a + u * t;
      if ((x - b).norm() > chamfer_max || (x - c).norm() > chamfer_max) continue;
      Polygon trial = out;
      trial[i] = x;
      trial.erase(trial.begin() + static_cast<std::ptrdiff_t>((i + 1) % m));
      if (!is_simple(trial)) continue;
      out = std::move(trial);
      changed = true;
      break;
    }
  }
  if (!is_simple(out) || signed_area(out) <= 0) return std::nullopt;
  return out;
}

}  // namespace indoormap::border::detail
