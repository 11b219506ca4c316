// Step 6 of the closure: the room polygon fitted to the wall faces beside the chain (the
// steps that simplify the face lines are in face_steps.cpp, the shadows in shadows.cpp).
#include <cmath>
#include <limits>

#include "internal.hpp"

namespace indoormap::border::detail {

namespace {

// The wall face lies inside the wall cells that touch room space: a wall cell is marked when a
// point of the face falls in it, so the face runs through those cells and their centres are an
// unbiased sample of it (the room-side cell boundary is half a cell too far in, on average).

struct FacePoint {
  Eigen::Vector2d p;         // wall cell centre (cell units)
  Eigen::Vector2d room_dir;  // unit direction towards its room-space 8-neighbours
};

bool room_space(Cell v) {
  return v == Cell::kFree || v == Cell::kFurniture;
}

// Wall cells with a room-space 4-neighbour inside the box [lo, hi] (cell units, clamped to one
// cell beyond the grid). Cells just outside the grid count as wall cells: the map's robust bounds
// crop the outermost points, so a room touching the map edge has its wall face there.
std::vector<FacePoint> face_points(const Grid<Cell>& layout, const Eigen::Vector2d& lo,
                                   const Eigen::Vector2d& hi) {
  std::vector<FacePoint> out;
  const int c0 = std::max(-1, static_cast<int>(std::floor(lo.x()))),
            r0 = std::max(-1, static_cast<int>(std::floor(lo.y())));
  const int c1 = std::min(layout.width, static_cast<int>(std::ceil(hi.x()))),
            r1 = std::min(layout.height, static_cast<int>(std::ceil(hi.y())));
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      if (layout.contains(c, r) && layout.at(c, r) != Cell::kWall) continue;
      bool touches = false;
      Eigen::Vector2d dir = Eigen::Vector2d::Zero();
      for (int k = 0; k < 8; ++k) {
        const int nc = c + kDc[k], nr = r + kDr[k];
        if (!layout.contains(nc, nr) || !room_space(layout.at(nc, nr))) continue;
        dir += Eigen::Vector2d(kDc[k], kDr[k]).normalized();
        if (k < 4) touches = true;
      }
      if (!touches || dir.squaredNorm() < 1e-12) continue;
      out.push_back({Eigen::Vector2d(c, r), dir.normalized()});
    }
  return out;
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Robust fit of one edge's wall face: the face points beside the edge (from out_reach outside the
// chain to in_reach inside it) whose room lies on the inner side, a median start, then total least
// squares with outliers beyond 2.5 robust sigmas (at least 1 cell) dropped. The direction may turn
// by at most face_max_turn_deg from the edge's; otherwise it keeps the edge's direction.
void fit_edge(const std::vector<FacePoint>& faces, const CellParams& cp, FaceLine& line) {
  const double out_reach = cp.out_reach, in_reach = cp.in_reach;
  const Eigen::Vector2d a = line.a, t = (line.b - line.a).normalized();
  const Eigen::Vector2d n(-t.y(), t.x());
  const double len = (line.b - line.a).norm();
  std::vector<Eigen::Vector2d> cand;
  std::vector<double> offs;
  for (const auto& f : faces) {
    const Eigen::Vector2d d = f.p - a;
    const double s = d.dot(t), o = d.dot(n);
    if (s < -1.0 || s > len + 1.0 || o < -out_reach || o > in_reach) continue;
    if (f.room_dir.dot(n) < 0.5) continue;  // the room is not on this edge's inner side
    cand.push_back(f.p);
    offs.push_back(o);
  }
  line.inliers.clear();
  if (cand.size() < kMinFacePoints) return;
  const double o_med = median_of(offs);
  line.u = t;
  line.c = a + n * o_med;
  double th = 2.0;
  for (int iter = 0; iter < 4; ++iter) {
    std::vector<Eigen::Vector2d> in;
    const Eigen::Vector2d ln = line.normal();
    for (const auto& p : cand)
      if (std::abs((p - line.c).dot(ln)) <= th) in.push_back(p);
    if (in.size() < kMinFacePoints) return;
    line.inliers = in;
    fit_tls(in, t, line);
    if (line.u.dot(t) < cp.max_turn_cos) {  // keep the edge's direction
      line.u = t;
      Eigen::Vector2d mean = Eigen::Vector2d::Zero();
      for (const auto& p : in) mean += p;
      line.c = mean / static_cast<double>(in.size());
    }
    std::vector<double> r2;
    for (const auto& p : in) r2.push_back(std::abs((p - line.c).dot(line.normal())));
    th = std::max(1.0, 2.5 * 1.4826 * median_of(r2));
  }
}

}  // namespace

// Total least squares line through pts; the direction is oriented along hint.
void fit_tls(const std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& hint, FaceLine& line) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  double sxx = 0, sxy = 0, syy = 0;
  for (const auto& p : pts) {
    const Eigen::Vector2d d = p - mean;
    sxx += d.x() * d.x();
    sxy += d.x() * d.y();
    syy += d.y() * d.y();
  }
  const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);
  Eigen::Vector2d u(std::cos(angle), std::sin(angle));
  if (u.dot(hint) < 0) u = -u;
  line.c = mean;
  line.u = u;
}

// Ordinary regression's prediction error of the line's offset at p, with the residuals' variance
// s2 (at least a cell's quantisation) from the points' spread about the line.
double extrapolation_error(const FaceLine& l, const Eigen::Vector2d& p) {
  const double n = static_cast<double>(l.inliers.size());
  if (n < 3) return std::numeric_limits<double>::infinity();
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& q : l.inliers) mean += q;
  mean /= n;
  double stt = 0.0, srr = 0.0;
  for (const auto& q : l.inliers) {
    stt += std::pow((q - mean).dot(l.u), 2);
    srr += std::pow((q - l.c).dot(l.normal()), 2);
  }
  const double s2 = std::max(srr / (n - 2.0), 1.0 / 12.0);
  if (!(stt > 0)) return std::numeric_limits<double>::infinity();
  return std::sqrt(s2 / n + std::pow((p - mean).dot(l.u), 2) * s2 / stt);
}

void fit_face_line(FaceLine& line, const Eigen::Vector2d& along, double max_error) {
  fit_tls(line.inliers, along, line);
  if (std::max(extrapolation_error(line, line.a), extrapolation_error(line, line.b)) <= max_error)
    return;
  line.u = along.normalized();
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : line.inliers) mean += p;
  line.c = mean / static_cast<double>(line.inliers.size());
}

void extend_to(FaceLine& line, const Eigen::Vector2d& b, double max_error) {
  if (!line.inliers.empty()) {
    line.b = b;
    fit_face_line(line, line.b - line.a, max_error);
    return;
  }
  const double depth = (line.c - line.a).dot(line.normal());
  line.b = b;
  line.u = (line.b - line.a).normalized();
  line.c = line.a + line.normal() * depth;
}

std::optional<Eigen::Vector2d> intersect(const FaceLine& l1, const FaceLine& l2) {
  const double cr = l1.u.x() * l2.u.y() - l1.u.y() * l2.u.x();
  if (std::abs(cr) < 1e-9) return std::nullopt;
  const Eigen::Vector2d d = l2.c - l1.c;
  const double t = (d.x() * l2.u.y() - d.y() * l2.u.x()) / cr;
  return l1.c + l1.u * t;
}

double angle_between(const FaceLine& l1, const FaceLine& l2) {
  return std::acos(std::clamp(l1.u.dot(l2.u), -1.0, 1.0));
}

namespace {

// Step 1: one line per edge of poly, fitted to the face points beside it (fit_edge); an edge
// without face points (a door's mouth, a gap in the scan) lies at the median depth of the fitted
// ones. nullopt when no edge has face points.
std::optional<std::vector<FaceLine>> edge_lines(const Polygon& poly, const Grid<Cell>& layout,
                                                const CellParams& cp) {
  const std::size_t n0 = poly.size();
  const double out_reach = cp.out_reach;
  Eigen::Vector2d lo = poly[0], hi = poly[0];
  for (const auto& v : poly) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const auto faces = face_points(layout, lo.array() - out_reach - 1, hi.array() + out_reach + 1);
  std::vector<FaceLine> lines(n0);
  std::vector<double> depth;
  for (std::size_t i = 0; i < n0; ++i) {
    lines[i].a = poly[i];
    lines[i].b = poly[(i + 1) % n0];
    fit_edge(faces, cp, lines[i]);
    if (!lines[i].inliers.empty())
      depth.push_back((lines[i].c - lines[i].a).dot(lines[i].normal()));
  }
  if (depth.empty()) return std::nullopt;
  const double global = std::clamp(median_of(depth), 0.0, cp.max_shift);
  for (auto& l : lines)
    if (l.inliers.empty()) {
      l.u = (l.b - l.a).normalized();
      l.c = l.a + l.normal() * global;
    }
  return lines;
}

// Step 6: the vertices, the intersections of consecutive lines. Nearly parallel neighbours (a step
// in the wall) are joined where the chain joins them. A line whose two corners come out in reverse
// order along it (a short line at a corner whose neighbours cross before reaching it) is dropped,
// and the corners recomputed. A corner that strays more than 2 chamfer_max from the chain: nullopt,
// or with cp.drop_stray_lines the one of its two lines with fewer face points is dropped too.
std::optional<Polygon> corners(std::vector<FaceLine>& lines, const CellParams& cp) {
  Polygon out;
  while (lines.size() >= 3) {
    const std::size_t m = lines.size();
    std::vector<Eigen::Vector2d> start(m), end(m);
    std::vector<std::uint8_t> step(m, 0);  // 1: lines[i - 1] and lines[i] are joined by a step
    std::optional<std::size_t> stray;      // drop_stray_lines: the weaker line of a stray corner
    for (std::size_t i = 0; i < m; ++i) {
      const std::size_t p = (i + m - 1) % m;
      const FaceLine& prev = lines[p];
      const FaceLine& cur = lines[i];
      const auto x = intersect(prev, cur);
      if (!x || angle_between(prev, cur) < cp.parallel_max) {
        // Nearly parallel neighbours (a step in the wall): joined where the chain joins them.
        end[p] = prev.c + prev.u * (prev.b - prev.c).dot(prev.u);
        start[i] = cur.c + cur.u * (cur.a - cur.c).dot(cur.u);
        step[i] = 1;
        continue;
      }
      if ((*x - cur.a).norm() > 2.0 * cp.chamfer_max) {
        if (!cp.drop_stray_lines) return std::nullopt;
        stray = lines[p].inliers.size() < cur.inliers.size() ? p : i;
        break;
      }
      end[p] = start[i] = *x;
    }
    std::optional<std::size_t> reversed = stray;
    for (std::size_t i = 0; i < m && !stray; ++i)
      if ((end[i] - start[i]).dot(lines[i].u) < 0 &&
          (!reversed || lines[i].inliers.size() < lines[*reversed].inliers.size()))
        reversed = i;
    if (!reversed) {
      for (std::size_t i = 0; i < m; ++i) {
        if (step[i]) out.push_back(end[(i + m - 1) % m]);
        out.push_back(start[i]);
      }
      break;
    }
    extend_to(lines[(*reversed + m - 1) % m], lines[*reversed].b, cp.tol);
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(*reversed));
  }
  return out;
}

// Drops repeated vertices; nullopt unless the result is a simple counter-clockwise polygon.
std::optional<Polygon> cleaned(const Polygon& out) {
  Polygon clean;
  for (const auto& v : out)
    if (clean.empty() || (v - clean.back()).norm() > 1e-6) clean.push_back(v);
  while (clean.size() > 1 && (clean.front() - clean.back()).norm() <= 1e-6) clean.pop_back();
  for (const auto& v : clean)
    if (!v.allFinite()) return std::nullopt;
  if (clean.size() < 3 || !is_simple(clean) || !(signed_area(clean) > 0)) return std::nullopt;
  return clean;
}

}  // namespace

// The polygon from the wall faces (cell units; poly is the simplified counter-clockwise chain
// polygon, which gives the order of the faces):
//  1. every edge of poly is fitted to the face points beside it (edge_lines);
//  2. consecutive lines of one straight face are merged (merge_same_face);
//  3. a bump of at most max_bump cells between two lines of one face (a door recess) is bridged
//     along that face (bridge_recess);
//  4. an inward detour of at most max_shadow cells (wide and deep) between two lines of one face
//     round a mostly unknown region is bridged along that face, or to the walls' crossing over a
//     convex corner: the shadow of an object standing in the room (bridge_shadow,
//     bridge_corner_shadow; max_shadow = 0: off); the regions cut off are the fit's shadows;
//  5. the weakest line its neighbours explain is dropped, so that the neighbours meet at their
//     intersection: the corners the chain cuts (convex or concave), chamfers fitted to the two
//     walls of a corner, wiggles of the chain at windows (drop_explained_line);
//  6. the vertices are the intersections of consecutive lines (corners).
// Steps 2-5 repeat, the first that changes the lines first, until none does. No polygon when a
// corner strays far from the chain, or the result is not simple or not counter-clockwise (the
// caller then falls back to snap_to_faces).
FaceFit fit_to_faces(const Polygon& poly, const Grid<Cell>& layout, const CellParams& cp) {
  if (poly.size() < 3 || cp.max_shift <= 0) return {};
  auto fitted = edge_lines(poly, layout, cp);
  if (!fitted) return {};
  std::vector<FaceLine>& lines = *fitted;
  FaceFit fit;
  while (lines.size() > 3 &&
         (merge_same_face(lines, cp) || bridge_recess(lines, cp) ||
          (cp.max_shadow > 0 && (bridge_shadow(lines, layout, cp, fit.shadows) ||
                                 bridge_corner_shadow(lines, layout, cp, fit.shadows))) ||
          drop_explained_line(lines, cp))) {
  }
  const auto out = corners(lines, cp);
  if (!out) return {};
  fit.polygon = cleaned(*out);
  if (!fit.polygon) return {};
  return fit;
}

}  // namespace indoormap::border::detail
