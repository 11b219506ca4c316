#include "indoormap/layout/nav_map.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <utility>

#include "floor_holes.hpp"
#include "indoormap/core/errors.hpp"
#include "level_tops.hpp"
#include "rays.hpp"

namespace indoormap::layout {

void validate(const NavParams& p) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw UsageError("invalid parameter " + what);
  };
  require(std::isfinite(p.min_obstacle_height_m) && p.min_obstacle_height_m >= 0,
          "robot.min_obstacle_height_m: must be >= 0");
  require(std::isfinite(p.height_m) && p.height_m > p.min_obstacle_height_m,
          "robot.height_m: must be > robot.min_obstacle_height_m");
  require(p.min_points >= 1, "nav.min_points: must be >= 1");
  require(p.floor_closing_cells >= 0 && p.floor_closing_cells <= 10,
          "nav.floor_closing_cells: must be in [0, 10]");
  require(p.min_neighbours >= 0 && p.min_neighbours <= 8, "nav.min_neighbours: must be in [0, 8]");
  require(std::isfinite(p.min_column_m) && p.min_column_m >= 0, "nav.min_column_m: must be >= 0");
  require(std::isfinite(p.floor_tolerance_m) && p.floor_tolerance_m >= 0,
          "nav.floor_tolerance_m: must be >= 0");
  require(std::isfinite(p.floor_max_offset_m) && p.floor_max_offset_m >= 0,
          "nav.floor_max_offset_m: must be >= 0");
  require(std::isfinite(p.floor_tile_m) && p.floor_tile_m > 0, "nav.floor_tile_m: must be > 0");
  require(std::isfinite(p.floor_hole_max_m2) && p.floor_hole_max_m2 >= 0,
          "nav.floor_hole_max_m2: must be >= 0");
  require(p.floor_hole_min_free_share >= 0 && p.floor_hole_min_free_share <= 1,
          "nav.floor_hole_min_free_share: must be in [0, 1]");
  require(p.floor_hole_min_free_share_no_rays >= 0 && p.floor_hole_min_free_share_no_rays <= 1,
          "nav.floor_hole_min_free_share_no_rays: must be in [0, 1]");
  require(std::isfinite(p.max_range_m) && p.max_range_m > 0, "nav.max_range_m: must be > 0");
  require(std::isfinite(p.scanner_clear_m) && p.scanner_clear_m >= 0,
          "nav.scanner_clear_m: must be >= 0");
  require(std::isfinite(p.ray_under_min_m) && p.ray_under_min_m >= 0,
          "nav.ray_under_min_m: must be >= 0");
  require(std::isfinite(p.shadow_max_width_m) && p.shadow_max_width_m >= 0,
          "nav.shadow_max_width_m: must be >= 0");
  require(std::isfinite(p.shadow_min_depth_m) && p.shadow_min_depth_m >= 0,
          "nav.shadow_min_depth_m: must be >= 0");
  require(
      std::isfinite(p.over_low_max_m) && p.over_low_max_m >= 0 && p.over_low_max_m <= p.height_m,
      "nav.over_low_max_m: must be in [0, robot.height_m]");
}

namespace {

// Per column: body-band points, lowest and highest occupied body layer, and whether the floor
// (or anything below height_m) was seen there.
struct Columns {
  std::vector<std::uint32_t> points;
  std::vector<std::int32_t> lo, hi;
  std::vector<std::uint16_t> layers;  ///< body-band layers holding points
  std::vector<std::uint64_t> bits;    ///< those layers, bit (layer - body_lo) % 64
  std::vector<std::uint8_t> floor_seen, low_seen;
  /// The most points in two neighbouring body-band layers, and those layers' bits: the column's
  /// piece of a level surface (a table top, a seat), if it has one.
  std::vector<std::uint32_t> dense;
  std::vector<std::uint64_t> dense_bits;
};

// The floor's layer per column as an offset from the global floor layer f0: per tile of
// tile_cells, the most frequent lowest occupied layer of its columns within [f0 - below,
// f0 + above], when at least a quarter of the tile's columns have one; else 0. A levelling
// residual of 0.3 degrees raises the floor 10 cm across a 20 m building: with one floor height,
// the far rooms' floors would lie in the body band.
std::vector<std::int8_t> floor_offsets(const cloud::VoxelGrid& g, std::int64_t f0, int below,
                                       int above, int tile_cells) {
  const int w = static_cast<int>(g.nx), h = static_cast<int>(g.ny);
  std::vector<std::int8_t> off(static_cast<std::size_t>(w) * h, 0);
  std::vector<std::int8_t> lowest(off.size(), -128);
  for (int d = -below; d <= above; ++d) {
    const std::int64_t z = f0 + d;
    if (z < 0 || z >= g.nz) continue;
    const std::uint16_t* layer = g.counts.data() + g.index(0, 0, z);
    for (std::size_t i = 0; i < off.size(); ++i)
      if (layer[i] && lowest[i] == -128) lowest[i] = static_cast<std::int8_t>(d);
  }
  std::vector<int> hist(static_cast<std::size_t>(below + above + 1));
  for (int r0 = 0; r0 < h; r0 += tile_cells)
    for (int c0 = 0; c0 < w; c0 += tile_cells) {
      std::fill(hist.begin(), hist.end(), 0);
      int cells = 0;
      for (int r = r0; r < std::min(h, r0 + tile_cells); ++r)
        for (int c = c0; c < std::min(w, c0 + tile_cells); ++c, ++cells)
          if (const int d = lowest[static_cast<std::size_t>(r) * w + c]; d != -128)
            ++hist[static_cast<std::size_t>(d + below)];
      const auto best = std::max_element(hist.begin(), hist.end());
      if (4 * *best < cells) continue;
      const auto d = static_cast<std::int8_t>(best - hist.begin() - below);
      for (int r = r0; r < std::min(h, r0 + tile_cells); ++r)
        for (int c = c0; c < std::min(w, c0 + tile_cells); ++c)
          off[static_cast<std::size_t>(r) * w + c] = d;
    }
  return off;
}

// Layers relative to each column's floor: [floor_lo, body_lo) is floor, [body_lo, body_hi] body.
Columns scan_columns(const cloud::VoxelGrid& g, std::int64_t floor_lo, std::int64_t body_lo,
                     std::int64_t body_hi, const std::vector<std::int8_t>& off) {
  const std::size_t n = static_cast<std::size_t>(g.layer_size());
  Columns c{std::vector<std::uint32_t>(n, 0), std::vector<std::int32_t>(n, -1),
            std::vector<std::int32_t>(n, -1), std::vector<std::uint16_t>(n, 0),
            std::vector<std::uint64_t>(n, 0), std::vector<std::uint8_t>(n, 0),
            std::vector<std::uint8_t>(n, 0),  std::vector<std::uint32_t>(n, 0),
            std::vector<std::uint64_t>(n, 0)};
  std::vector<std::uint16_t> below(n, 0);  // points in the column's previous body layer
  const auto [dmin, dmax] = std::minmax_element(off.begin(), off.end());
  const std::int64_t z0 = std::max<std::int64_t>(0, floor_lo + (n ? *dmin : 0));
  const std::int64_t z1 = std::min<std::int64_t>(g.nz - 1, body_hi + (n ? *dmax : 0));
  for (std::int64_t z = z0; z <= z1; ++z) {
    const std::uint16_t* layer = g.counts.data() + g.index(0, 0, z);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint16_t k = layer[i];
      const std::uint16_t under = std::exchange(below[i], 0);
      if (!k) continue;
      const std::int64_t zr = z - off[i];  // the layer as if the column's floor were f0
      if (zr < floor_lo || zr > body_hi) continue;
      c.low_seen[i] = 1;
      if (zr < body_lo) {
        c.floor_seen[i] = 1;
        continue;
      }
      below[i] = k;
      const std::uint64_t bit = std::uint64_t{1} << ((zr - body_lo) % 64);
      if (const std::uint32_t pair = std::uint32_t{k} + under; pair > c.dense[i]) {
        c.dense[i] = pair;
        c.dense_bits[i] = bit | (under ? std::uint64_t{1} << ((zr - 1 - body_lo) % 64) : 0);
      }
      c.points[i] += k;
      ++c.layers[i];
      c.bits[i] |= bit;
      if (c.lo[i] < 0) c.lo[i] = static_cast<std::int32_t>(zr);
      c.hi[i] = static_cast<std::int32_t>(zr);
    }
  }
  return c;
}

// Each layer within one of its own, set.
std::uint64_t spread(std::uint64_t b) {
  return b | (b << 1) | (b >> 1);
}

// A piece of a level surface seen from above (a table top, a seat): at least min_points points
// in two neighbouring layers, and at least min_neighbours of the 8 neighbours holding points
// within one layer of those. The mixed pixels along the surface's edge add points at other
// heights to its columns; they do not make the surface a veil.
bool level_surface(const Columns& col, int c, int row, int w, int h, const NavParams& p) {
  const std::size_t i = static_cast<std::size_t>(row) * w + c;
  if (col.dense[i] < static_cast<std::uint32_t>(p.min_points)) return false;
  const std::uint64_t near = spread(col.dense_bits[i]);
  int level = 0;
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc)
      if ((dr || dc) && c + dc >= 0 && row + dr >= 0 && c + dc < w && row + dr < h)
        level += (col.bits[static_cast<std::size_t>(row + dr) * w + c + dc] & near) != 0;
  return level >= p.min_neighbours;
}

// Scatter columns: no min_span consecutive layers hold points (no piece of surface min_column_m
// tall: five mixed pixels at random heights may well fill three neighbouring 5 cm layers), no
// piece of a level surface, over seen floor that goes on in all four directions (a wall's face
// has its unseen inside on one side).
std::vector<std::uint8_t> scatter_columns(const Columns& col,
                                          const std::function<bool(std::size_t)>& seen, int w,
                                          int h, std::int32_t min_span, const NavParams& p) {
  const auto continuous = [&](std::uint64_t b) {
    std::uint64_t run = b;
    for (std::int32_t k = 1; k < min_span && k < 64; ++k) run &= b << k;
    return run != 0;
  };
  std::vector<std::uint8_t> scatter(static_cast<std::size_t>(w) * h, 0);
  const auto wu = static_cast<std::size_t>(w);
  for (int row = 1; row + 1 < h; ++row)
    for (int c = 1; c + 1 < w; ++c) {
      const std::size_t i = static_cast<std::size_t>(row) * w + c;
      scatter[i] = col.lo[i] >= 0 && !continuous(col.bits[i]) && seen(i) && seen(i - 1) &&
                   seen(i + 1) && seen(i - wu) && seen(i + wu) &&
                   !level_surface(col, c, row, w, h, p);
    }
  return scatter;
}

// Veil columns: scatter columns with two scatter neighbours at other heights; then, a veil being
// sparse, every scatter column with two such veil columns within two cells (a column of five
// mixed pixels in a doorway whose nearest neighbours hold no point). A leg seen every other layer
// stands apart from any veil.
std::vector<std::uint8_t> veil_columns(const Columns& col, const std::vector<std::uint8_t>& scatter,
                                       int w, int h) {
  const auto index = [&](int c, int row) { return static_cast<std::size_t>(row) * w + c; };
  const auto inside = [&](int c, int row) { return c >= 0 && row >= 0 && c < w && row < h; };
  std::vector<std::uint8_t> veil(scatter.size(), 0);
  for (int row = 0; row < h; ++row)
    for (int c = 0; c < w; ++c) {
      const std::size_t i = index(c, row);
      if (!scatter[i]) continue;
      const std::uint64_t near = spread(col.bits[i]);
      int scattered = 0;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          if ((!dr && !dc) || !inside(c + dc, row + dr)) continue;
          const std::size_t j = index(c + dc, row + dr);
          // Columns at the same heights (each layer within one of the other's) are pieces of
          // one sparse surface, not scatter.
          const bool same = !(col.bits[j] & ~near) && !(col.bits[i] & ~spread(col.bits[j]));
          scattered += scatter[j] && !same;
        }
      veil[i] = scattered >= 2;
    }
  std::vector<std::uint8_t> out(veil);
  for (int row = 0; row < h; ++row)
    for (int c = 0; c < w; ++c) {
      if (!scatter[index(c, row)] || veil[index(c, row)]) continue;
      int veils = 0;
      for (int dr = -2; dr <= 2; ++dr)
        for (int dc = -2; dc <= 2; ++dc)
          veils += inside(c + dc, row + dr) && veil[index(c + dc, row + dr)];
      out[index(c, row)] = veils >= 2;
    }
  return out;
}

// The body-band columns that are obstacles (docs/pipeline.md, "Specks"): at least min_points
// points, or min_span layers, or part of a surface: min_neighbours of the 8 neighbours hold
// body-band points. floor: the seen floor, or empty when the ghost filter ran with every point's
// own origin (then no veil is left). Where the floor below the column was seen, the neighbours
// must hold a point within one layer of one of the column's own: a far table top or a wall row
// is level across its cells. And a scatter column (seen floor around, no min_span consecutive
// layers) with two scatter neighbours at other heights, or two such veil columns within two
// cells, is no obstacle at all, nor a surface's neighbour: the veil of mixed pixels in a
// doorway, points at random heights over a floor seen through them. veil: those veil columns.
Grid<std::uint8_t> occupied_columns(const Columns& col, const std::vector<std::uint8_t>& floor,
                                    int w, int h, const NavParams& p, std::int32_t min_span,
                                    std::int64_t& specks, std::vector<std::uint8_t>& veil) {
  Grid<std::uint8_t> occupied(w, h, 0);
  const std::function<bool(std::size_t)> seen = [&](std::size_t i) {
    return !floor.empty() && floor[i];
  };
  veil = veil_columns(col, scatter_columns(col, seen, w, h, min_span, p), w, h);
  // A veil column is no obstacle, nor a surface's neighbour (a speck among veil columns at its
  // own height is part of the veil, not of a table top).
  for (int row = 0; row < h; ++row)
    for (int c = 0; c < w; ++c) {
      const std::size_t i = static_cast<std::size_t>(row) * w + c;
      if (col.lo[i] < 0) continue;
      const std::uint64_t near = spread(col.bits[i]);
      int nb = 0, level = 0;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          if ((!dr && !dc) || !occupied.contains(c + dc, row + dr)) continue;
          const std::size_t j = static_cast<std::size_t>(row + dr) * w + c + dc;
          if (veil[j]) continue;
          nb += col.lo[j] >= 0;
          level += (col.bits[j] & near) != 0;
        }
      const bool surface = nb >= p.min_neighbours && (!seen(i) || level >= p.min_neighbours);
      const bool ok = !veil[i] && (col.points[i] >= static_cast<std::uint32_t>(p.min_points) ||
                                   col.layers[i] >= min_span || surface);
      occupied.data[i] = ok;
      specks += !ok;
    }
  return occupied;
}

// A raised obstacle's points lie within this height: a table top or a seat (5 cm thick, seen a
// layer or two deep), not a wall's face or a backrest.
constexpr double kRaisedMaxSpanM = 0.15;

// Gaps in a raised obstacle's top: a table top seen at a grazing angle holds a point in every
// second or third cell, and the floor below the empty ones was seen between the legs. A cell
// without a body-band point that lies between two raised cells at a shared level, at most
// kTopGapCells empty cells apart along a row, a column or a diagonal, is part of the top.
constexpr int kTopGapCells = 3;

// Sparse tops (detail::fill_level_tops): a table top crossed by a mobile lidar's arcs 0.2-0.5 m
// apart is joined across its gaps; a piece needs this many samples (0.02 m2 at 5 cm cells) to
// be a surface, not a stray point.
constexpr double kLevelTopGapM = 0.25;
constexpr int kLevelTopMinCells = 8;

void close_top_gaps(const Columns& col, int w, int h, Grid<std::uint8_t>& occupied,
                    std::vector<std::uint8_t>& raised) {
  const auto at = [&](int c, int r) { return static_cast<std::size_t>(r) * w + c; };
  // The first cell with body-band points from (c, r) along (dc, dr), within kTopGapCells + 1
  // steps; its index and steps, or steps 0.
  const auto first = [&](int c, int r, int dc, int dr) -> std::pair<std::size_t, int> {
    for (int k = 1; k <= kTopGapCells + 1; ++k) {
      const int cc = c + k * dc, rr = r + k * dr;
      if (cc < 0 || rr < 0 || cc >= w || rr >= h) return {0, 0};
      if (col.lo[at(cc, rr)] >= 0) return {at(cc, rr), k};
    }
    return {0, 0};
  };
  std::vector<std::size_t> fill;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      if (col.lo[at(c, r)] >= 0) continue;
      for (const auto& [dc, dr] : {std::pair{1, 0}, {0, 1}, {1, 1}, {1, -1}}) {
        const auto [a, ka] = first(c, r, dc, dr);
        const auto [b, kb] = first(c, r, -dc, -dr);
        if (!ka || !kb || ka + kb - 1 > kTopGapCells || !raised[a] || !raised[b]) continue;
        if (!(col.bits[a] & spread(col.bits[b]))) continue;
        fill.push_back(at(c, r));
        break;
      }
    }
  for (const std::size_t i : fill) occupied.data[i] = raised[i] = 1;
}

// Raised obstacles, over a floor seen in their own cell: the rays pass beneath them. Only thin
// ones (a top, a seat: points within kRaisedMaxSpanM): a wall's face seen above something
// standing in front of it is no top, and a ray through it would mark the wall's inside seen.
// The gaps of a sampled top are closed, and a sparse top's samples joined (both occupied and
// raised in `occupied`).
std::vector<std::uint8_t> raised_obstacles(const Columns& col, const cloud::VoxelGrid& g,
                                           double floor_z_m, const NavParams& p,
                                           const std::vector<std::uint8_t>& veil,
                                           Grid<std::uint8_t>& occupied) {
  const int w = occupied.width, h = occupied.height;
  std::vector<std::uint8_t> raised(occupied.size(), 0);
  const std::int64_t raised_lo = g.layer_of(floor_z_m + p.ray_under_min_m);
  const auto span = static_cast<std::int32_t>(std::lround(g.to_cells(kRaisedMaxSpanM)));
  for (std::size_t i = 0; i < raised.size(); ++i)
    raised[i] = occupied.data[i] && col.floor_seen[i] && col.lo[i] >= raised_lo &&
                col.hi[i] - col.lo[i] < span;
  close_top_gaps(col, w, h, occupied, raised);
  std::vector<std::uint8_t> under_top = col.floor_seen;  // a veil's points are no top's samples
  for (std::size_t i = 0; i < under_top.size(); ++i) under_top[i] &= !veil[i];
  detail::fill_level_tops(
      col.lo, col.hi, under_top, w, h,
      {static_cast<std::int32_t>(raised_lo), span,
       static_cast<int>(std::lround(g.to_cells(kLevelTopGapM))), kLevelTopMinCells},
      occupied.data, raised);
  return raised;
}

// Columns holding a point more than kDropM below the floor: a hole in the floor (a stairwell, a
// shaft) shows what lies below it; such a gap in the floor's returns is no floor hole to fill.
constexpr double kDropM = 0.3;

std::vector<std::uint8_t> drops(const cloud::VoxelGrid& g, double floor_z_m,
                                const std::vector<std::uint8_t>& floor_seen) {
  std::vector<std::uint8_t> d(static_cast<std::size_t>(g.layer_size()), 0);
  const std::int64_t top = std::min<std::int64_t>(g.nz, g.layer_of(floor_z_m - kDropM));
  for (std::int64_t z = 0; z < top; ++z) {
    const std::uint16_t* layer = g.counts.data() + g.index(0, 0, z);
    for (std::size_t i = 0; i < d.size(); ++i) d[i] |= layer[i] != 0;
  }
  // A piece of such columns (8-connected) whose floor was mostly seen lies under a solid floor:
  // the ceiling of a taller room of the storey below, seen from there (a two-storey building's
  // upper storey begins between the lower storey's ceilings), not a hole.
  cv::Mat m(static_cast<int>(g.ny), static_cast<int>(g.nx), CV_8U, d.data()), labels;
  const int n = cv::connectedComponents(m, labels, 8, CV_32S);
  std::vector<std::int64_t> cells(static_cast<std::size_t>(n), 0), seen(cells.size(), 0);
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto l = static_cast<std::size_t>(labels.at<int>(static_cast<int>(i)));
    ++cells[l];
    seen[l] += floor_seen[i] != 0;
  }
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto l = static_cast<std::size_t>(labels.at<int>(static_cast<int>(i)));
    if (d[i] && 2 * seen[l] >= cells[l]) d[i] = 0;
  }
  return d;
}

}  // namespace

NavResult build_nav_map(const cloud::VoxelGrid& g, double floor_z_m,
                        const std::vector<Eigen::Vector3d>& scanners, const NavParams& p,
                        bool veils_cleared, const Grid<std::uint8_t>* walls) {
  validate(p);
  NavResult r;
  const GridGeometry geo = g.geometry2d();
  const int w = geo.width(), h = geo.height();
  r.map = Grid<Cell>(w, h, Cell::kUnknown);
  r.observed_free = Grid<std::uint8_t>(w, h, 0);
  r.body_lo_m = floor_z_m + p.min_obstacle_height_m;
  r.body_hi_m = floor_z_m + p.height_m;
  if (w == 0 || h == 0 || g.nz == 0) return r;
  const std::int64_t floor_lo = g.layer_of(floor_z_m - p.floor_tolerance_m);
  const std::int64_t body_lo = g.layer_of(r.body_lo_m);
  const std::int64_t body_hi = g.layer_of(r.body_hi_m) - 1;  // layers wholly below height_m
  const std::int64_t f0 = g.layer_of(floor_z_m);
  const auto off = floor_offsets(
      g, f0, static_cast<int>(std::lround(g.to_cells(p.floor_tolerance_m))),
      std::clamp(static_cast<int>(std::lround(g.to_cells(p.floor_max_offset_m))), 0, 100),
      std::max(1, static_cast<int>(std::lround(g.to_cells(p.floor_tile_m)))));
  const Columns col = scan_columns(g, floor_lo, body_lo, body_hi, off);
  const auto min_span =
      static_cast<std::int32_t>(std::max(1L, std::lround(g.to_cells(p.min_column_m))));
  // Far from a scanner the floor's returns thin out into lines with gaps of a cell or two: close
  // them (a square closing of floor_closing_cells); occupied cells are taken out after.
  std::vector<std::uint8_t> floor_seen = col.floor_seen;
  if (p.floor_closing_cells > 0) {
    cv::Mat m(h, w, CV_8U, floor_seen.data());
    const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
    cv::morphologyEx(m, m, cv::MORPH_CLOSE, square, {-1, -1}, p.floor_closing_cells);
  }
  const std::vector<std::uint8_t> no_floor;  // the exact ghost filter cleared the veils
  std::vector<std::uint8_t> veil;
  Grid<std::uint8_t> occupied = occupied_columns(col, veils_cleared ? no_floor : floor_seen, w, h,
                                                 p, min_span, r.specks_dropped, veil);
  const std::vector<std::uint8_t> raised = raised_obstacles(col, g, floor_z_m, p, veil, occupied);
  for (std::size_t i = 0; i < floor_seen.size(); ++i) floor_seen[i] &= !occupied.data[i];
  const detail::ShadowLimits shadow_limits{
      g.to_cells(p.shadow_max_width_m), g.to_cells(p.shadow_min_depth_m),
      detail::compact_obstacles(occupied, p.rays ? g.to_cells(p.shadow_max_width_m) : 0.0)};
  detail::RayMarks marks(occupied.size());
  if (p.rays) {
    detail::BeamHeights beams;
    if (p.over_low_max_m > 0) {
      beams = detail::beam_heights(g, col.hi, off, body_hi, scanners, occupied, raised);
      beams.max_hidden = g.to_layer_coord(floor_z_m + p.over_low_max_m);
    }
    marks = detail::cast_all(g, scanners, col.low_seen, occupied, raised,
                             {g.to_cells(p.max_range_m), g.to_cells(p.scanner_clear_m)}, floor_seen,
                             shadow_limits, beams);
  }
  r.positions = marks.positions;
  r.rays = marks.rays;
  const std::vector<std::uint8_t>&crossed = marks.crossed, &shadow = marks.shadow,
        &over = marks.over;
  if (r.positions == 0)
    r.warnings.push_back(
        "no scanner position known: the navigation map's free space comes from the observed "
        "floor alone (give --scanner or --trajectory for ray evidence)");
  std::vector<detail::NavState> state(occupied.size(), detail::NavState::kUnknown);
  for (std::size_t i = 0; i < state.size(); ++i)
    state[i] = occupied.data[i]                ? detail::NavState::kOccupied
               : (floor_seen[i] || crossed[i]) ? detail::NavState::kFree
                                               : detail::NavState::kUnknown;
  for (std::size_t i = 0; i < state.size(); ++i)
    r.observed_free.data[i] = state[i] == detail::NavState::kFree;
  // Shadows, floor holes and the floor behind low obstacles are inferred: free in the map, not
  // the layout's evidence. The last come after the holes, so that the map without them is the
  // map the rooms are split on (map_without_over_low).
  for (std::size_t i = 0; i < state.size(); ++i)
    if (shadow[i] && state[i] == detail::NavState::kUnknown) {
      state[i] = detail::NavState::kFree;
      ++r.cells_shadow_filled;
    }
  const double cell_m2 = geo.cell_m() * geo.cell_m();
  const std::vector<std::uint8_t> barrier = detail::hole_barrier(
      state, g,
      walls && walls->data.size() == state.size() ? walls->data : std::vector<std::uint8_t>{},
      {g.layer_of(r.body_hi_m), g.layer_of(floor_z_m + detail::kDoorOpenM)});
  r.cells_hole_filled = detail::fill_floor_holes(
      state, barrier, drops(g, floor_z_m, col.floor_seen), w, h,
      {p.floor_hole_max_m2 / cell_m2,
       r.positions ? p.floor_hole_min_free_share : p.floor_hole_min_free_share_no_rays});
  r.over_low = Grid<std::uint8_t>(w, h, 0);
  for (std::size_t i = 0; i < state.size(); ++i)
    if (over[i] && state[i] == detail::NavState::kUnknown) {
      state[i] = detail::NavState::kFree;
      r.over_low.data[i] = 1;
      ++r.cells_over_low;
    }
  for (std::size_t i = 0; i < state.size(); ++i) {
    Cell c = Cell::kUnknown;
    if (state[i] == detail::NavState::kOccupied) {
      c = Cell::kWall;
      ++r.cells_occupied;
    } else if (state[i] == detail::NavState::kFree) {
      c = Cell::kFree;
      ++r.cells_free;
      if (floor_seen[i])
        ++r.cells_floor_seen;
      else if (crossed[i])
        ++r.cells_ray_free;
    } else {
      ++r.cells_unknown;
    }
    r.map.data[i] = c;
  }
  return r;
}

Grid<Cell> map_without_over_low(const NavResult& nav) {
  Grid<Cell> m = nav.map;
  for (std::size_t i = 0; i < m.data.size() && i < nav.over_low.data.size(); ++i)
    if (nav.over_low.data[i]) m.data[i] = Cell::kUnknown;
  return m;
}

}  // namespace indoormap::layout
