// The shadows an object standing in the room casts on a wall or over a corner of the room, as the
// fit to the wall faces bridges them (docs/border-closure.md, "Shadows").
//
// A detour of the chain is taken for the shadow of an object standing in the room when more than
// shadow_min_unknown_share of the cells it cuts off (between the detour and the wall line) is
// unknown: the scanner did not see them. Architecture the chain runs round (a column, a chimney
// breast) shows its faces and the floor beside them; a hollow column, whose inside is unknown too,
// is told apart by its flanks (below).
#include <cmath>
#include <limits>

#include "internal.hpp"

namespace indoormap::border::detail {

double distance_to_boundary(const Polygon& poly, const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
    const Eigen::Vector2d a = poly[i], d = poly[(i + 1) % n] - a;
    const double t =
        d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (a + d * t - p).norm());
  }
  return best;
}

namespace {

// Whether more than min_share of the cells (cell units: cell (c, r) at (c, r)) inside region and
// on the room side (room_side(p) > 0) are unknown, or off the layout.
template <class RoomSide>
bool mostly_unknown(const Polygon& region, const Grid<Cell>& layout, double min_share,
                    RoomSide room_side) {
  Eigen::Vector2d lo = region[0], hi = region[0];
  for (const auto& v : region) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  std::int64_t cells = 0, unknown = 0;
  for (int r = static_cast<int>(std::floor(lo.y())); r <= static_cast<int>(std::ceil(hi.y())); ++r)
    for (int c = static_cast<int>(std::floor(lo.x())); c <= static_cast<int>(std::ceil(hi.x()));
         ++c) {
      const Eigen::Vector2d p(c, r);
      if (!(room_side(p) > 0.0) || !contains(region, p)) continue;
      ++cells;
      unknown += !layout.contains(c, r) || layout.at(c, r) == Cell::kUnknown;
    }
  return cells > 0 && static_cast<double>(unknown) > min_share * static_cast<double>(cells);
}

}  // namespace

// Whether the chain's detour between lines[i] and lines[i + k] (cyclic, k >= 2; both fitted) is
// the shadow of an object standing in the room, cast on the wall behind it (a pillar 1 m before
// a wall hides a wedge of the floor and of the wall: the wedge is unknown in the layout, and the
// chain runs round it and the object). It is when
//  - the two lines are one straight face: within same_face_max_deg, and the face points of each lie
//    within tol (face_tol_m) of the line fitted to both, on average;
//  - the detour runs into the room (some chain vertex lies more than tol inside that line) and
//    not behind the wall by more than out_max (chamfer_max: the chain's depth behind the face);
//  - it is at most max_size (shadow_max_m) wide along the line and deep across it;
//  - more than shadow_min_unknown_share of the cells between the detour and the line are unknown;
//  - its two flanks (the first and the last line of the detour) have fewer than kMinFacePoints
//    face points off the line: a shadow's flanks are rays grazing the object, free space against
//    unknown, while the sides of a column are seen wall faces.
// Returns the line through both faces' points and the region cut off, or nullopt.
std::optional<Shadow> shadow_bridge(const std::vector<FaceLine>& lines, std::size_t i,
                                    std::size_t k, const Grid<Cell>& layout, const CellParams& cp) {
  const double tol = cp.tol, out_max = cp.chamfer_max, max_size = cp.max_shadow;
  const std::size_t m = lines.size();
  const FaceLine& l1 = lines[i];
  const FaceLine& l2 = lines[(i + k) % m];
  if (angle_between(l1, l2) > cp.same_face_max) return std::nullopt;
  FaceLine joint = l1;
  joint.b = l2.b;
  joint.inliers.insert(joint.inliers.end(), l2.inliers.begin(), l2.inliers.end());
  fit_tls(joint.inliers, joint.b - joint.a, joint);
  const Eigen::Vector2d n = joint.normal();  // towards the room
  auto offset = [&](const Eigen::Vector2d& p) { return (p - joint.c).dot(n); };
  auto along = [&](const Eigen::Vector2d& p) { return (p - joint.c).dot(joint.u); };
  for (const FaceLine* l : {&l1, &l2}) {
    double mean = 0.0;
    for (const auto& p : l->inliers) mean += offset(p);
    if (std::abs(mean / static_cast<double>(l->inliers.size())) > tol) return std::nullopt;
  }
  // The detour: the chain vertices from the end of l1 to the start of l2.
  Polygon detour{l1.b};
  for (std::size_t q = 1; q < k; ++q) detour.push_back(lines[(i + q) % m].b);
  const double s0 = along(detour.front()), s1 = along(detour.back());
  if (s1 - s0 <= 0.0 || s1 - s0 > max_size) return std::nullopt;
  double deepest = -std::numeric_limits<double>::infinity();
  for (const auto& v : detour) {
    const double o = offset(v), s = along(v);
    if (o < -out_max || o > max_size || s < s0 - out_max || s > s1 + out_max) return std::nullopt;
    deepest = std::max(deepest, o);
  }
  if (deepest <= tol) return std::nullopt;
  // Flanks: face points of the first and the last detour line that are not on the wall line.
  for (const std::size_t q : {std::size_t{1}, k - 1}) {
    std::size_t off = 0;
    for (const auto& p : lines[(i + q) % m].inliers) off += std::abs(offset(p)) > tol;
    if (off >= kMinFacePoints) return std::nullopt;
  }
  // The cells cut off: inside the detour closed along the line, on the room side of the line.
  Polygon region = detour;
  region.push_back(joint.c + joint.u * s1);
  region.push_back(joint.c + joint.u * s0);
  if (!mostly_unknown(region, layout, cp.shadow_min_unknown_share, offset)) return std::nullopt;
  return Shadow{std::move(joint), std::move(region)};
}

// Whether the chain's detour between lines[i] and lines[i + k] (cyclic, k >= 2; both fitted) is
// the shadow of an object standing in the room that hides a convex corner of the room (a pillar
// before a corner, seen from the far side of the room: the corner and the ends of both walls are
// unknown, and the chain cuts across the room round the object). It is when
//  - the two lines turn left (counter-clockwise) by corner_shadow_min_turn_deg to
//    corner_shadow_max_turn_deg, and cross at X;
//  - the detour runs from l1's end to l2's start within the corner: each vertex lies no more than
//    out_max behind either line, and X lies at most max_size beyond both ends (along the lines);
//  - the detour runs into the room: some vertex lies more than tol inside both lines;
//  - more than shadow_min_unknown_share of the cells between the detour and X are unknown;
//  - its two flanks have fewer than kMinFacePoints face points off both lines (as shadow_bridge);
//  - both lines reach X within tol (extrapolation_error): a wall seen over a few cells (where
//    another wall meets it) gives no direction to carry it a metre further.
// Returns the corner X and the region cut off (the detour closed through X), or nullopt.
std::optional<CornerShadow> corner_shadow_bridge(const std::vector<FaceLine>& lines, std::size_t i,
                                                 std::size_t k, const Grid<Cell>& layout,
                                                 const CellParams& cp) {
  const double tol = cp.tol, out_max = cp.chamfer_max, max_size = cp.max_shadow;
  const std::size_t m = lines.size();
  const FaceLine& l1 = lines[i];
  const FaceLine& l2 = lines[(i + k) % m];
  const double turn = std::atan2(l1.u.x() * l2.u.y() - l1.u.y() * l2.u.x(), l1.u.dot(l2.u));
  if (turn < cp.corner_turn_min || turn > cp.corner_turn_max) return std::nullopt;
  const auto x = intersect(l1, l2);
  if (!x) return std::nullopt;
  auto offset = [](const FaceLine& l, const Eigen::Vector2d& p) {
    return (p - l.c).dot(l.normal());
  };
  Polygon detour{l1.b};
  for (std::size_t q = 1; q < k; ++q) detour.push_back(lines[(i + q) % m].b);
  // X beyond both ends: past l1's end along l1, before l2's start along l2.
  const double beyond1 = (*x - detour.front()).dot(l1.u);
  const double beyond2 = (detour.back() - *x).dot(l2.u);
  if (beyond1 < -out_max || beyond1 > max_size || beyond2 < -out_max || beyond2 > max_size)
    return std::nullopt;
  double deepest = -std::numeric_limits<double>::infinity();
  for (const auto& v : detour) {
    const double o1 = offset(l1, v), o2 = offset(l2, v);
    if (o1 < -out_max || o2 < -out_max || o1 > max_size || o2 > max_size) return std::nullopt;
    deepest = std::max(deepest, std::min(o1, o2));
  }
  if (deepest <= tol) return std::nullopt;
  for (const std::size_t q : {std::size_t{1}, k - 1}) {
    std::size_t off = 0;
    for (const auto& p : lines[(i + q) % m].inliers)
      off += std::abs(offset(l1, p)) > tol && std::abs(offset(l2, p)) > tol;
    if (off >= kMinFacePoints) return std::nullopt;
  }
  Polygon region = detour;
  region.push_back(*x);
  if (!mostly_unknown(region, layout, cp.shadow_min_unknown_share, [&](const Eigen::Vector2d& p) {
        return std::min(offset(l1, p), offset(l2, p));
      }))
    return std::nullopt;
  if (extrapolation_error(l1, *x) > tol || extrapolation_error(l2, *x) > tol) return std::nullopt;
  return CornerShadow{*x, std::move(region)};
}

}  // namespace indoormap::border::detail
