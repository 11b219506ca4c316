#include <cmath>
#include <string>

#include "indoormap/core/errors.hpp"
#include "internal.hpp"

namespace indoormap::border {

void BorderParams::validate() const {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw UsageError("invalid parameter border." + what);
  };
  auto odd = [](int v) { return v >= 1 && v % 2 == 1 && v <= 99; };
  require(odd(dilate_full_size), "dilate_full_size: must be odd, in [1, 99]");
  require(odd(dilate_cross_size), "dilate_cross_size: must be odd, in [1, 99]");
  require(odd(erode_full_size) && erode_full_size >= 3, "erode_full_size: must be odd, in [3, 99]");
  require(erode_iterations >= 1 && erode_iterations <= 20, "erode_iterations: must be in [1, 20]");
  require(simplify_tolerance_m >= 0 && std::isfinite(simplify_tolerance_m),
          "simplify_tolerance_m: must be >= 0");
  require(face_snap_max_m >= 0 && face_snap_max_m <= 5, "face_snap_max_m: must be in [0, 5] m");
  require(shadow_max_m >= 0 && shadow_max_m <= 20, "shadow_max_m: must be in [0, 20] m");
  require(opening_search_m >= 0 && opening_search_m <= 10,
          "opening_search_m: must be in [0, 10] m");
  require(opening_min_m >= 0 && std::isfinite(opening_min_m), "opening_min_m: must be >= 0");
  require(door_min_m > 0 && door_min_m <= door_max_m && std::isfinite(door_max_m),
          "door_min_m / door_max_m: need 0 < door_min_m <= door_max_m");
  require(door_clear_height_m > 0 && door_clear_height_m <= 10,
          "door_clear_height_m: must be in (0, 10] m");
  require(door_probe_m > 0 && door_probe_m <= 100, "door_probe_m: must be in (0, 100] m");
  require(max_open_fraction > 0 && max_open_fraction <= 1, "max_open_fraction: must be in (0, 1]");
  require(max_cells > 0, "max_cells: must be > 0");
  auto length = [&](double v, const char* key) {
    require(v >= 0 && v <= 5, std::string(key) + ": must be in [0, 5] m");
  };
  length(face_out_reach_m, "face_out_reach_m");
  length(face_in_margin_m, "face_in_margin_m");
  require(face_tol_m > 0 && face_tol_m <= 5, "face_tol_m: must be in (0, 5] m");
  length(chamfer_margin_m, "chamfer_margin_m");
  length(recess_margin_m, "recess_margin_m");
  length(shadow_chain_tol_m, "shadow_chain_tol_m");
  auto angle = [&](double v, const char* key) {
    require(v >= 0 && v <= 90, std::string(key) + ": must be in [0, 90] degrees");
  };
  angle(face_max_turn_deg, "face_max_turn_deg");
  angle(same_face_max_deg, "same_face_max_deg");
  angle(parallel_max_deg, "parallel_max_deg");
  require(shadow_min_unknown_share >= 0 && shadow_min_unknown_share <= 1,
          "shadow_min_unknown_share: must be in [0, 1]");
  require(corner_shadow_min_turn_deg > 0 &&
              corner_shadow_min_turn_deg <= corner_shadow_max_turn_deg &&
              corner_shadow_max_turn_deg < 180,
          "corner_shadow_min_turn_deg / corner_shadow_max_turn_deg: need 0 < min <= max < 180 "
          "degrees");
}

void validate(const BorderParams& params) {
  params.validate();
}

namespace detail {

CellParams to_cell_params(const BorderParams& p, const GridGeometry& geo) {
  // The expressions keep the operations of the cell-counted originals (4.0 cells = 0.2 m exactly
  // at 0.05 m cells; 0.075 m is 1.4999999999999998 cells, no double gives 1.5 exactly).
  auto rad = [](double deg) { return deg * M_PI / 180.0; };
  CellParams c;
  c.max_shift = geo.to_cells(p.face_snap_max_m);
  c.out_reach = geo.to_cells(p.face_out_reach_m);
  c.in_reach = c.max_shift + geo.to_cells(p.face_in_margin_m);
  c.tol = geo.to_cells(p.face_tol_m);
  c.chamfer_max = 2.0 * c.max_shift + geo.to_cells(p.chamfer_margin_m);
  // A door recess spans the door and its two jambs (each up to the largest move).
  c.max_bump =
      geo.to_cells(p.door_max_m + 2.0 * p.face_snap_max_m) + geo.to_cells(p.recess_margin_m);
  c.max_shadow = geo.to_cells(p.shadow_max_m);
  c.shadow_chain_tol = geo.to_cells(p.shadow_chain_tol_m);
  c.max_turn_cos = std::cos(rad(p.face_max_turn_deg));
  c.same_face_max = rad(p.same_face_max_deg);
  c.parallel_max = rad(p.parallel_max_deg);
  c.corner_turn_min = rad(p.corner_shadow_min_turn_deg);
  c.corner_turn_max = rad(p.corner_shadow_max_turn_deg);
  c.shadow_min_unknown_share = p.shadow_min_unknown_share;
  return c;
}

}  // namespace detail

}  // namespace indoormap::border
