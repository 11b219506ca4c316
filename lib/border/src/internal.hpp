#pragma once
// What the stages of the border closure share (not installed; the contract is border.hpp):
// M_Lee marks as grid values, the 8-neighbourhood, the thresholds in cells, and the face lines
// that the fit to the wall faces (faces.cpp, face_steps.cpp) and the shadows (shadows.cpp) work
// on. Geometry in "cell units": cell (col, row) at (col, row).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "indoormap/border/border.hpp"

namespace indoormap::border::detail {

// M_Lee marks as the grid stores them.
inline constexpr std::int32_t kBorder = lee_value(LeeMark::kBorder);
inline constexpr std::int32_t kOpenStart = lee_value(LeeMark::kOpenStart);
inline constexpr std::int32_t kOpenEnd = lee_value(LeeMark::kOpenEnd);
inline constexpr std::int32_t kRoom = lee_value(LeeMark::kRoom);
inline constexpr std::int32_t kVirgin = lee_value(LeeMark::kVirgin);
inline constexpr std::int32_t kFirstLabel = kFirstLeeLabel;

// 8-neighbourhood, orthogonal steps first so that ties prefer them deterministically.
inline constexpr int kDc[8] = {1, 0, -1, 0, 1, -1, -1, 1};
inline constexpr int kDr[8] = {0, 1, 0, -1, 1, 1, -1, -1};

inline bool adjacent8(CellIndex a, CellIndex b) {
  return std::max(std::abs(a.col - b.col), std::abs(a.row - b.row)) == 1;
}

template <class T>
bool has_neighbour(const Grid<T>& g, CellIndex c, T value) {
  for (int k = 0; k < 8; ++k) {
    const int nc = c.col + kDc[k], nr = c.row + kDr[k];
    if (g.contains(nc, nr) && g.at(nc, nr) == value) return true;
  }
  return false;
}

/// Twice the signed area of a closed chain (cell units), halved: > 0 counter-clockwise.
double chain_signed_area(const std::vector<CellIndex>& chain);

/// BorderParams' thresholds for one layout: lengths in cells (GridGeometry::to_cells), angles in
/// radians. Made once by the entry point (to_cell_params) and passed to every stage.
struct CellParams {
  double max_shift = 0;         ///< face_snap_max_m
  double out_reach = 0;         ///< face_out_reach_m
  double in_reach = 0;          ///< face_snap_max_m + face_in_margin_m
  double tol = 0;               ///< face_tol_m
  double chamfer_max = 0;       ///< 2 face_snap_max_m + chamfer_margin_m
  double max_bump = 0;          ///< door_max_m + 2 face_snap_max_m + recess_margin_m
  double max_shadow = 0;        ///< shadow_max_m
  double shadow_chain_tol = 0;  ///< shadow_chain_tol_m
  double max_turn_cos = 1;      ///< cos(face_max_turn_deg)
  double same_face_max = 0;     ///< [rad] same_face_max_deg
  double parallel_max = 0;      ///< [rad] parallel_max_deg
  double corner_turn_min = 0;   ///< [rad] corner_shadow_min_turn_deg
  double corner_turn_max = 0;   ///< [rad] corner_shadow_max_turn_deg
  double shadow_min_unknown_share = 0;
  /// A stray corner drops its weaker line instead of failing the fit (fit_to_wall_faces: a
  /// room's outline from cells has short lines at door passages and sills that the closure's
  /// chain does not).
  bool drop_stray_lines = false;
};
CellParams to_cell_params(const BorderParams& params, const GridGeometry& geo);

// ---- Face lines (faces.cpp) ---------------------------------------------------------------------

/// A straight wall face: the line through c along the unit vector u (the room lies to its left).
struct FaceLine {
  Eigen::Vector2d c = Eigen::Vector2d::Zero(), u = Eigen::Vector2d::UnitX();
  std::vector<Eigen::Vector2d> inliers;  ///< the face points it was fitted to (empty: not fitted)
  Eigen::Vector2d a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero();  ///< chain edge
  Eigen::Vector2d normal() const { return {-u.y(), u.x()}; }
  double length() const { return (b - a).norm(); }
};

/// Fewer face points beside an edge than this: no line is fitted (the edge has no face of its own).
inline constexpr std::size_t kMinFacePoints = 4;

/// Total least squares line through pts; the direction is oriented along hint.
void fit_tls(const std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& hint, FaceLine& line);
std::optional<Eigen::Vector2d> intersect(const FaceLine& l1, const FaceLine& l2);
double angle_between(const FaceLine& l1, const FaceLine& l2);
/// The standard error (cell units) of the line fitted to l's face points (total least squares)
/// where it reaches p: its offset's error and its direction's, which grows with the distance from
/// the points' centre. The residuals' spread is taken as at least a cell's quantisation
/// (1/12 cell^2). Infinite with fewer than 3 points.
double extrapolation_error(const FaceLine& l, const Eigen::Vector2d& p);
/// The line through line.inliers (at least kMinFacePoints): total least squares where the points
/// fix its direction along the whole chain edge (extrapolation_error at most max_error at line.a
/// and line.b), otherwise along `along` through their centre. A few face points at one end of a
/// long edge (where another wall meets it) would turn it at random.
void fit_face_line(FaceLine& line, const Eigen::Vector2d& along, double max_error);
/// Moves the end of line's chain edge to b (the edge now reaches over a dropped line's): a fitted
/// line is fitted again (fit_face_line), an unfitted one follows the new edge at its old depth.
void extend_to(FaceLine& line, const Eigen::Vector2d& b, double max_error);

/// The polygon fitted to the wall faces (cell units), and the shadows it runs across.
struct FaceFit {
  std::optional<Polygon> polygon;  ///< nullopt: the fit failed (the shadows are then void too)
  std::vector<Polygon> shadows;    ///< regions cut off by the shadow bridges (cell units)
};
/// The polygon from the wall faces; poly is the simplified counter-clockwise chain polygon in
/// cell units (faces.cpp describes the steps).
FaceFit fit_to_faces(const Polygon& poly, const Grid<Cell>& layout, const CellParams& cp);

/// The fallback: every edge of poly moved inwards to the wall face (snap.cpp).
std::optional<Polygon> snap_to_faces(const Polygon& poly, const Grid<Cell>& layout,
                                     double max_shift);

// ---- Steps of fit_to_faces (face_steps.cpp); each returns whether it changed lines ------------

bool merge_same_face(std::vector<FaceLine>& lines, const CellParams& cp);
bool bridge_recess(std::vector<FaceLine>& lines, const CellParams& cp);
bool bridge_shadow(std::vector<FaceLine>& lines, const Grid<Cell>& layout, const CellParams& cp,
                   std::vector<Polygon>& shadows);
bool bridge_corner_shadow(std::vector<FaceLine>& lines, const Grid<Cell>& layout,
                          const CellParams& cp, std::vector<Polygon>& shadows);
bool drop_explained_line(std::vector<FaceLine>& lines, const CellParams& cp);

// ---- Shadows (shadows.cpp)
// -----------------------------------------------------------------------

/// A shadow on a straight wall: the face line across it and the detour closed along that line.
struct Shadow {
  FaceLine joint;
  Polygon region;  ///< cell units
};
std::optional<Shadow> shadow_bridge(const std::vector<FaceLine>& lines, std::size_t i,
                                    std::size_t k, const Grid<Cell>& layout, const CellParams& cp);

/// A shadow over a convex corner: the walls' crossing and the detour closed through it.
struct CornerShadow {
  Eigen::Vector2d corner = Eigen::Vector2d::Zero();
  Polygon region;  ///< cell units
};
std::optional<CornerShadow> corner_shadow_bridge(const std::vector<FaceLine>& lines, std::size_t i,
                                                 std::size_t k, const Grid<Cell>& layout,
                                                 const CellParams& cp);

double distance_to_boundary(const Polygon& poly, const Eigen::Vector2d& p);

// ---- Openings (openings.cpp)
// ---------------------------------------------------------------------

/// The openings of a closed chain: maximal cyclic runs of chain cells with no obstacle within
/// opening_search_m, measured between the nearest obstacle cells on either side.
std::vector<Opening> find_openings(const std::vector<CellIndex>& chain, const Grid<Cell>& layout,
                                   const GridGeometry& geo, const BorderParams& params,
                                   const Grid<std::uint8_t>* open_below);

}  // namespace indoormap::border::detail
