// The steps of fit_to_faces (faces.cpp) that simplify the face lines: merging lines of one
// face, bridging door recesses and shadows, dropping lines their neighbours explain. Each makes at
// most one change and says whether it made one; fit_to_faces repeats them until none does.
#include <cmath>

#include "internal.hpp"

namespace indoormap::border::detail {

namespace {

// A face point explained by its neighbours' lines: at least this share of them
// (drop_explained_line).
constexpr double kExplainedMinShare = 0.8;
// A door recess is bridged across at most this many lines less one (bridge_recess).
constexpr std::size_t kRecessMaxLines = 4;

bool supported(const FaceLine& l) {
  return !l.inliers.empty();
}

double dist(const FaceLine& l, const Eigen::Vector2d& p) {
  return std::abs((p - l.c).dot(l.normal()));
}

// One straight face: nearly the same direction and each line through the other's points.
bool same_face(const FaceLine& l1, const FaceLine& l2, const CellParams& cp) {
  if (angle_between(l1, l2) > cp.same_face_max) return false;
  return dist(l1, l2.c) <= cp.tol && dist(l2, l1.c) <= cp.tol;
}

void refit(FaceLine& l, const CellParams& cp) {
  if (l.inliers.size() >= 2) fit_face_line(l, l.b - l.a, cp.tol);
}

// Replaces lines[i .. i + k] (cyclic) by joint, which spans from lines[i].a to lines[i + k].b.
void join_across(std::vector<FaceLine>& lines, std::size_t i, std::size_t k, FaceLine joint) {
  const std::size_t m = lines.size();
  std::vector<FaceLine> kept;
  for (std::size_t q = 0; q < m; ++q) {
    bool drop = false;
    for (std::size_t d = 1; d <= k; ++d) drop |= q == (i + d) % m;
    if (q == i)
      kept.push_back(std::move(joint));
    else if (!drop)
      kept.push_back(std::move(lines[q]));
  }
  lines = std::move(kept);
}

}  // namespace

// Merges two consecutive fitted lines of one face.
bool merge_same_face(std::vector<FaceLine>& lines, const CellParams& cp) {
  const std::size_t m = lines.size();
  for (std::size_t i = 0; i < m; ++i) {
    FaceLine& l1 = lines[i];
    FaceLine& l2 = lines[(i + 1) % m];
    if (!supported(l1) || !supported(l2) || !same_face(l1, l2, cp)) continue;
    l1.b = l2.b;
    l1.inliers.insert(l1.inliers.end(), l2.inliers.begin(), l2.inliers.end());
    refit(l1, cp);
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>((i + 1) % m));
    return true;
  }
  return false;
}

// A bump of the chain between two lines of one face (a door recess without a lintel: the chain
// runs round the jambs and across the door's mouth): its edges are short or have no face of
// their own, and the two lines are joined across it. A door recess lies behind the face (the
// chain crosses the door's mouth where the free space stops, a few cells inside at most); a bump
// that runs further into the room than the chain's largest depth behind the face (max_shift) is
// a column standing out of the wall, whose notch stays (or a shadow: bridge_shadow).
bool bridge_recess(std::vector<FaceLine>& lines, const CellParams& cp) {
  const std::size_t m = lines.size();
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t k = 2; k <= kRecessMaxLines && k + 1 < m; ++k) {
      const std::size_t j = (i + k) % m;
      if (!supported(lines[i]) || !supported(lines[j]) || !same_face(lines[i], lines[j], cp))
        continue;
      double span = 0.0;
      bool weak = true, inward = false;
      for (std::size_t q = 1; q < k; ++q) {
        const FaceLine& l = lines[(i + q) % m];
        span += l.length();
        weak &= !supported(l) || l.length() <= cp.chamfer_max;
        inward |= (l.b - lines[i].c).dot(lines[i].normal()) > cp.max_shift;
      }
      if (!weak || inward || span > cp.max_bump) continue;
      FaceLine joint = lines[i];
      joint.b = lines[j].b;
      joint.inliers.insert(joint.inliers.end(), lines[j].inliers.begin(), lines[j].inliers.end());
      refit(joint, cp);
      join_across(lines, i, k, std::move(joint));
      return true;
    }
  }
  return false;
}

// An inward detour of the chain between two lines of one face round the shadow of an object
// standing in the room (shadow_bridge): the two lines are joined across it, and the region cut
// off is added to shadows. The chain runs behind the face by up to chamfer_max.
bool bridge_shadow(std::vector<FaceLine>& lines, const Grid<Cell>& layout, const CellParams& cp,
                   std::vector<Polygon>& shadows) {
  const std::size_t m = lines.size();
  for (std::size_t i = 0; i < m; ++i) {
    if (!supported(lines[i])) continue;
    for (std::size_t k = 2; k + 3 <= m; ++k) {
      if (!supported(lines[(i + k) % m])) continue;
      if (auto sh = shadow_bridge(lines, i, k, layout, cp)) {
        join_across(lines, i, k, std::move(sh->joint));
        shadows.push_back(std::move(sh->region));
        return true;
      }
    }
  }
  return false;
}

// The same round a room's corner (corner_shadow_bridge): the lines between the two walls are
// dropped, and the walls meet at their crossing.
bool bridge_corner_shadow(std::vector<FaceLine>& lines, const Grid<Cell>& layout,
                          const CellParams& cp, std::vector<Polygon>& shadows) {
  const std::size_t m = lines.size();
  for (std::size_t i = 0; i < m; ++i) {
    if (!supported(lines[i])) continue;
    for (std::size_t k = 2; k + 2 <= m; ++k) {
      if (!supported(lines[(i + k) % m])) continue;
      auto sh = corner_shadow_bridge(lines, i, k, layout, cp);
      if (!sh) continue;
      lines[i].b = sh->corner;
      lines[(i + k) % m].a = sh->corner;
      std::vector<FaceLine> kept;
      for (std::size_t q = 0; q < m; ++q)
        if ((q + m - i) % m == 0 || (q + m - i) % m >= k) kept.push_back(std::move(lines[q]));
      lines = std::move(kept);
      shadows.push_back(std::move(sh->region));
      return true;
    }
  }
  return false;
}

// Drops the weakest line that its neighbours explain: an unfitted edge between two lines of one
// face or between two lines meeting near it (a corner the chain cuts, convex or concave); a
// fitted one whose face points (at least kExplainedMinShare) lie on its neighbours' lines (a
// chamfer fitted to the two walls of a corner, a wiggle of the chain at a window).
bool drop_explained_line(std::vector<FaceLine>& lines, const CellParams& cp) {
  const std::size_t m = lines.size();
  const double tol = cp.tol;
  std::vector<std::size_t> order(m);
  for (std::size_t i = 0; i < m; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return lines[x].inliers.size() < lines[y].inliers.size();
  });
  for (const std::size_t i : order) {
    FaceLine& prev = lines[(i + m - 1) % m];
    FaceLine& cur = lines[i];
    FaceLine& next = lines[(i + 1) % m];
    const bool parallel = angle_between(prev, next) < cp.parallel_max;
    if (parallel && !same_face(prev, next, cp)) continue;  // a step: cur joins the two faces
    if (!parallel) {
      const auto x = intersect(prev, next);
      if (!x || (*x - cur.a).norm() > cp.chamfer_max || (*x - cur.b).norm() > cp.chamfer_max)
        continue;
    }
    if (supported(cur)) {
      if (cur.inliers.size() > std::min(prev.inliers.size(), next.inliers.size())) continue;
      std::size_t explained = 0;
      for (const auto& p : cur.inliers) explained += std::min(dist(prev, p), dist(next, p)) <= tol;
      if (explained < kExplainedMinShare * static_cast<double>(cur.inliers.size())) continue;
      for (const auto& p : cur.inliers) {
        if (dist(prev, p) <= dist(next, p)) {
          if (dist(prev, p) <= tol) prev.inliers.push_back(p);
        } else if (dist(next, p) <= tol) {
          next.inliers.push_back(p);
        }
      }
      if (supported(next)) refit(next, cp);
    }
    extend_to(prev, cur.b, tol);  // the chain edge of prev now reaches over cur's (and is refitted)
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i));
    return true;
  }
  return false;
}

}  // namespace indoormap::border::detail
