// The closure composed (border.hpp): steps 1-4 (marking.cpp, trace.cpp), the choice of the room
// border, the polygon (faces.cpp, snap.cpp), the openings (openings.cpp) and the open-scan test.
#include "indoormap/border/border.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "indoormap/core/errors.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "internal.hpp"

namespace indoormap::border {

using namespace detail;

namespace {

std::string fmt_xy(const Eigen::Vector2d& p) {
  std::ostringstream s;
  s.precision(2);
  s << std::fixed << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

Polygon cell_polygon(const std::vector<CellIndex>& chain) {
  Polygon p;
  p.reserve(chain.size());
  for (const auto& c : chain) p.emplace_back(c.col, c.row);
  return p;
}

// Cell units (cell (c, r) at (c, r)) of a map-frame point, and back.
Eigen::Vector2d to_cell_units(const GridGeometry& geo, const Eigen::Vector2d& p) {
  return geo.to_cell_coords(p) - Eigen::Vector2d(0.5, 0.5);
}
Polygon to_map(const GridGeometry& geo, const Polygon& p) {
  Polygon q;
  for (const auto& v : p) q.push_back(geo.from_cell_coords(v + Eigen::Vector2d(0.5, 0.5)));
  return q;
}

void check_inputs(const Grid<Cell>& layout, const GridGeometry& geo, const BorderParams& params,
                  const Grid<std::uint8_t>* open_below) {
  params.validate();
  if (layout.width != geo.width() || layout.height != geo.height() ||
      layout.size() !=
          static_cast<std::size_t>(layout.width) * static_cast<std::size_t>(layout.height))
    throw Error("close_border: layout and geometry differ in size");
  if (open_below && (open_below->width != layout.width || open_below->height != layout.height))
    throw Error("close_border: open_below mask and layout differ in size");
  if (geo.cell_count() > params.max_cells)
    throw BudgetError("close_border: layout of " + std::to_string(geo.cell_count()) +
                      " cells exceeds border.max_cells = " + std::to_string(params.max_cells));
}

// Step 4 for every ring candidate; those that do not close become objects, with the reason.
// Returns the indices of the closed rings.
std::vector<std::size_t> trace_rings(BorderResult& res) {
  std::vector<std::size_t> rings;
  for (std::size_t i = 0; i < res.components.size(); ++i) {
    auto& comp = res.components[i];
    if (comp.kind != ComponentKind::kRing) continue;
    RingTrace t = trace_ring(res.lee, comp);
    if (t) {
      comp.chain = std::move(t.chain);
      rings.push_back(i);
    } else {
      comp.kind = ComponentKind::kObject;
      comp.note = std::move(t.why);
    }
  }
  return rings;
}

// Step 5: the room border, the smallest ring whose polygon contains a scanner (paper, section 4);
// without scanners the largest ring. Returns its component index, or -1.
int choose_room(BorderResult& res, const std::vector<std::size_t>& rings, const GridGeometry& geo,
                const std::vector<Eigen::Vector2d>& scanners_map) {
  int room = -1;
  for (const auto& s : scanners_map) {
    double best_area = std::numeric_limits<double>::infinity();
    for (const auto i : rings) {
      const Polygon poly = cell_polygon(res.components[i].chain);
      if (!contains(poly, to_cell_units(geo, s))) continue;
      const double a = std::abs(signed_area(poly));
      if (a < best_area) {
        best_area = a;
        room = static_cast<int>(i);
      }
    }
    if (room >= 0) {
      res.scanner_m = s;
      break;
    }
  }
  if (scanners_map.empty() && !rings.empty()) {
    double best_area = -1.0;
    for (const auto i : rings) {
      const double a = std::abs(chain_signed_area(res.components[i].chain));
      if (a > best_area) {
        best_area = a;
        room = static_cast<int>(i);
      }
    }
    res.warnings.push_back("no scanner position: the largest closed border was taken as the room");
  }
  return room;
}

void add_interior_objects(BorderResult& res, int room, const GridGeometry& geo) {
  for (std::size_t i = 0; i < res.components.size(); ++i) {
    auto& comp = res.components[i];
    if (static_cast<int>(i) == room) {
      comp.kind = ComponentKind::kRoomBorder;
      continue;
    }
    InteriorObject o;
    o.min = comp.min;
    o.max = comp.max;
    o.min_m = geo.center_of(comp.min) - Eigen::Vector2d::Constant(0.5 * geo.cell_m());
    o.max_m = geo.center_of(comp.max) + Eigen::Vector2d::Constant(0.5 * geo.cell_m());
    o.cells = comp.cells;
    o.kind = comp.kind;
    res.interior_objects.push_back(o);
  }
}

std::string no_room_reason(const BorderResult& res, const std::vector<std::size_t>& rings,
                           const std::vector<Eigen::Vector2d>& scanners_map) {
  if (res.components.empty()) return "no border: the layout has no marked cells";
  if (rings.empty())
    return "the border is open: none of the " + std::to_string(res.components.size()) +
           " border components closes into a ring (a gap wider than the morphology bridges)";
  return "none of the " + std::to_string(rings.size()) +
         " closed borders contains the scanner at " + fmt_xy(scanners_map.front());
}

// A closed cell-unit polygon simplified by simplify_tolerance_m, counter-clockwise; a
// simplification that self-intersects is retried with half the tolerance, down to raw itself.
Polygon simplified_ccw(const Polygon& raw, const GridGeometry& geo, const BorderParams& params) {
  Polygon poly = raw;
  for (double tol = geo.to_cells(params.simplify_tolerance_m); tol >= 0.25; tol *= 0.5) {
    Polygon s = simplify_closed(raw, tol);
    if (is_simple(s)) {
      poly = std::move(s);
      break;
    }
  }
  if (signed_area(poly) < 0) std::reverse(poly.begin(), poly.end());
  return poly;
}

// poly (cell units) without its slivers: the outline turning back on itself, either at one
// vertex (its two edges within max_rad of antiparallel) or across one edge of at most max_width
// cells (the edges before and after it antiparallel). Such a sliver is a strip of a room's cells
// one or two cells wide (in a gap of a wall, between a wall and a parapet); a face lies along
// each of its sides, and the fit would take them for the room's. Its vertices are dropped until
// none is left.
Polygon without_slivers(Polygon poly, double max_rad, double max_width) {
  const double cos_back = -std::cos(max_rad);
  const auto back = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.norm() < 1e-9 || b.norm() < 1e-9 || a.normalized().dot(b.normalized()) < cos_back;
  };
  for (bool changed = true; changed && poly.size() > 4;) {
    changed = false;
    for (std::size_t i = 0; i < poly.size() && poly.size() > 4; ++i) {
      const std::size_t n = poly.size(), i1 = (i + 1) % n;
      const Eigen::Vector2d before = poly[i] - poly[(i + n - 1) % n], edge = poly[i1] - poly[i],
                            after = poly[(i + 2) % n] - poly[i1];
      if (back(before, edge)) {  // a tip
        poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
      } else if (edge.norm() <= max_width && back(before, after)) {  // a blunt end
        poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(std::max(i, i1)));
        poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(std::min(i, i1)));
        changed = true;
      }
    }
  }
  return poly;
}

// Step 6: chain_polygon_m and polygon_m of the room's chain. Returns the shadows polygon_m runs
// across (cell units).
std::vector<Polygon> room_polygon(BorderResult& res, const Grid<Cell>& layout,
                                  const GridGeometry& geo, const BorderParams& params,
                                  const CellParams& cp) {
  // Simplified in cell units (the raw chain is simple).
  const Polygon poly = simplified_ccw(cell_polygon(res.chain), geo, params);
  res.chain_polygon_m = to_map(geo, poly);
  res.polygon_m = res.chain_polygon_m;
  if (params.face_snap_max_m <= 0) return {};
  FaceFit fit = fit_to_faces(poly, layout, cp);
  if (fit.polygon) {
    res.polygon_m = to_map(geo, *fit.polygon);
    return std::move(fit.shadows);
  }
  // The fallbacks follow the chain round every shadow.
  if (auto snapped = snap_to_faces(poly, layout, cp.max_shift)) {
    res.polygon_m = to_map(geo, *snapped);
    res.warnings.push_back(
        "the polygon could not be fitted to the wall faces; its edges were moved to them");
  } else {
    res.warnings.push_back(
        "the polygon could not be moved to the wall faces; it follows the chain");
  }
  return {};
}

// An opening that runs along a shadow the polygon bridged (every chain cell of it on the
// shadow's region, within shadow_chain_tol) is no gap in the room's border but the edge of what
// an object in the room hid from the scanner; it is dropped.
void drop_shadow_openings(BorderResult& res, const std::vector<Polygon>& shadows,
                          double shadow_chain_tol) {
  std::erase_if(res.openings, [&](const Opening& o) {
    for (const auto& region : shadows) {
      bool all = true;
      for (std::size_t i = o.chain_first;; i = (i + 1) % res.chain.size()) {
        const Eigen::Vector2d p(res.chain[i].col, res.chain[i].row);
        all &= contains(region, p) || distance_to_boundary(region, p) <= shadow_chain_tol;
        if (!all || i == o.chain_last) break;
      }
      if (all) return true;
    }
    return false;
  });
}

// Step 8: the morphology closes a band around any marked region, so an open scan (free space
// running out of the data) still yields a ring; it is recognised by how much of it has no
// obstacle. Length along the chain (not the chord) of the open runs, against the chain's length.
void check_open_fraction(BorderResult& res, const BorderParams& params) {
  double open_m = 0.0, chain_len = 0.0;
  const std::size_t n = res.chain_m.size();
  for (std::size_t i = 0; i < n; ++i)
    chain_len += (res.chain_m[(i + 1) % n] - res.chain_m[i]).norm();
  for (const auto& o : res.openings)
    for (std::size_t i = o.chain_first; i != o.chain_last; i = (i + 1) % n)
      open_m += (res.chain_m[(i + 1) % n] - res.chain_m[i]).norm();
  if (chain_len > 0 && open_m > params.max_open_fraction * chain_len) {
    res.closed = false;
    std::ostringstream why;
    why.precision(0);
    why << std::fixed << "the border is open: " << 100.0 * open_m / chain_len
        << " % of its length has no wall or furniture (border.max_open_fraction = "
        << 100.0 * params.max_open_fraction << " %)";
    res.reason = why.str();
  }
}

}  // namespace

BorderResult close_border(const Grid<Cell>& layout, const GridGeometry& geo,
                          const std::vector<Eigen::Vector2d>& scanners_map,
                          const BorderParams& params, const Grid<std::uint8_t>* open_below) {
  check_inputs(layout, geo, params, open_below);
  const CellParams cp = to_cell_params(params, geo);

  BorderResult res;
  res.heavy = heavy_border(layout, params);
  LeeMarking mk = mark_border_components(layout, res.heavy);
  res.lee = std::move(mk.lee);
  res.components = std::move(mk.components);
  const std::vector<std::size_t> rings = trace_rings(res);
  const int room = choose_room(res, rings, geo, scanners_map);
  add_interior_objects(res, room, geo);
  if (room < 0) {
    res.reason = no_room_reason(res, rings, scanners_map);
    return res;
  }

  res.closed = true;
  res.room_component = room;
  res.chain = res.components[static_cast<std::size_t>(room)].chain;
  res.chain_m.reserve(res.chain.size());
  for (const auto& c : res.chain) res.chain_m.push_back(geo.center_of(c));
  const std::vector<Polygon> shadows = room_polygon(res, layout, geo, params, cp);
  res.area_m2 = signed_area(res.polygon_m);
  res.perimeter_m = perimeter(res.polygon_m);
  res.openings = find_openings(res.chain, layout, geo, params, open_below);
  drop_shadow_openings(res, shadows, cp.shadow_chain_tol);
  check_open_fraction(res, params);
  return res;
}

BorderResult close_border(const layout::MapResult& m, const BorderParams& params) {
  params.validate();
  std::vector<Eigen::Vector2d> scanners;
  for (const auto& s : m.cloud_map.scanners) scanners.emplace_back(s.x(), s.y());
  if (scanners.empty())
    for (const auto& s : m.layout.seeds) scanners.push_back(m.geometry.center_of(s));
  const Grid<std::uint8_t> below = open_below_mask(m, scanners, params);
  return close_border(m.layout.layout, m.geometry, scanners, params, &below);
}

std::optional<Polygon> fit_to_wall_faces(const Polygon& outline_m, const Grid<Cell>& layout,
                                         const GridGeometry& geo, const BorderParams& params) {
  params.validate();
  if (outline_m.size() < 3 || params.face_snap_max_m <= 0) return std::nullopt;
  Polygon raw;
  raw.reserve(outline_m.size());
  for (const auto& v : outline_m) raw.push_back(to_cell_units(geo, v));
  CellParams cp = to_cell_params(params, geo);
  cp.drop_stray_lines = true;
  Polygon poly = without_slivers(simplified_ccw(raw, geo, params), cp.parallel_max, 3.0);
  if (poly.size() < 3 || !is_simple(poly)) return std::nullopt;
  FaceFit fit = fit_to_faces(poly, layout, cp);
  if (!fit.polygon) return std::nullopt;
  return to_map(geo, *fit.polygon);
}

}  // namespace indoormap::border
