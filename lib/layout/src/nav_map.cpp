#include "indoormap/layout/nav_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "floor_holes.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/core/parallel.hpp"

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
  require(std::isfinite(p.max_range_m) && p.max_range_m > 0, "nav.max_range_m: must be > 0");
  require(std::isfinite(p.scanner_clear_m) && p.scanner_clear_m >= 0,
          "nav.scanner_clear_m: must be >= 0");
  require(std::isfinite(p.shadow_max_width_m) && p.shadow_max_width_m >= 0,
          "nav.shadow_max_width_m: must be >= 0");
  require(std::isfinite(p.shadow_min_depth_m) && p.shadow_min_depth_m >= 0,
          "nav.shadow_min_depth_m: must be >= 0");
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
            std::vector<std::uint8_t>(n, 0)};
  const auto [dmin, dmax] = std::minmax_element(off.begin(), off.end());
  const std::int64_t z0 = std::max<std::int64_t>(0, floor_lo + (n ? *dmin : 0));
  const std::int64_t z1 = std::min<std::int64_t>(g.nz - 1, body_hi + (n ? *dmax : 0));
  for (std::int64_t z = z0; z <= z1; ++z) {
    const std::uint16_t* layer = g.counts.data() + g.index(0, 0, z);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint16_t k = layer[i];
      if (!k) continue;
      const std::int64_t zr = z - off[i];  // the layer as if the column's floor were f0
      if (zr < floor_lo || zr > body_hi) continue;
      c.low_seen[i] = 1;
      if (zr < body_lo) {
        c.floor_seen[i] = 1;
        continue;
      }
      c.points[i] += k;
      ++c.layers[i];
      c.bits[i] |= std::uint64_t{1} << ((zr - body_lo) % 64);
      if (c.lo[i] < 0) c.lo[i] = static_cast<std::int32_t>(zr);
      c.hi[i] = static_cast<std::int32_t>(zr);
    }
  }
  return c;
}

// The body-band columns that are obstacles (docs/pipeline.md, "Specks"): at least min_points
// points, or min_span layers, or part of a surface: min_neighbours of the 8 neighbours hold
// body-band points. floor: the seen floor, or empty when the ghost filter ran with every point's
// own origin (then no veil is left). Where the floor below the column was seen, the neighbours
// must hold a point within one layer of one of the column's own: a far table top or a wall row
// is level across its cells. And a scatter column (seen floor around, no three consecutive
// layers) with two scatter neighbours at other heights is no obstacle at all: the veil of mixed
// pixels in a doorway, points at random heights over a floor seen through them.
Grid<std::uint8_t> occupied_columns(const Columns& col, const std::vector<std::uint8_t>& floor,
                                    int w, int h, const NavParams& p, std::int32_t min_span,
                                    std::int64_t& specks) {
  Grid<std::uint8_t> occupied(w, h, 0);
  const auto seen = [&](std::size_t i) { return !floor.empty() && floor[i]; };
  // Scatter: no three consecutive layers hold points, over seen floor that goes on in all four
  // directions (a wall's face has its unseen inside on one side).
  std::vector<std::uint8_t> scatter(occupied.size(), 0);
  for (int row = 1; row + 1 < h; ++row)
    for (int c = 1; c + 1 < w; ++c) {
      const std::size_t i = static_cast<std::size_t>(row) * w + c;
      const auto wu = static_cast<std::size_t>(w);
      const std::uint64_t b = col.bits[i];
      scatter[i] = col.lo[i] >= 0 && !(b & (b << 1) & (b << 2)) && seen(i) && seen(i - 1) &&
                   seen(i + 1) && seen(i - wu) && seen(i + wu);
    }
  const auto spread = [](std::uint64_t b) { return b | (b << 1) | (b >> 1); };
  // Veils first: a scatter column with two scatter neighbours at other heights.
  std::vector<std::uint8_t> veil(occupied.size(), 0);
  for (int row = 0; row < h; ++row)
    for (int c = 0; c < w; ++c) {
      const std::size_t i = static_cast<std::size_t>(row) * w + c;
      if (!scatter[i]) continue;
      const std::uint64_t near = spread(col.bits[i]);
      int scattered = 0;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          if ((!dr && !dc) || !occupied.contains(c + dc, row + dr)) continue;
          const std::size_t j = static_cast<std::size_t>(row + dr) * w + c + dc;
          // Columns at the same heights (each layer within one of the other's) are pieces of
          // one sparse surface, not scatter.
          const bool same = !(col.bits[j] & ~near) && !(col.bits[i] & ~spread(col.bits[j]));
          scattered += scatter[j] && !same;
        }
      veil[i] = scattered >= 2;
    }
  // Then the obstacles; a veil column is no neighbour of a surface (a speck among veil columns
  // at its own height is part of the veil, not of a table top).
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

// Columns holding a point more than kDropM below the floor: a hole in the floor (a stairwell, a
// shaft) shows what lies below it; such a gap in the floor's returns is no floor hole to fill.
constexpr double kDropM = 0.3;

std::vector<std::uint8_t> drops(const cloud::VoxelGrid& g, double floor_z_m) {
  std::vector<std::uint8_t> d(static_cast<std::size_t>(g.layer_size()), 0);
  const std::int64_t top = std::min<std::int64_t>(g.nz, g.layer_of(floor_z_m - kDropM));
  for (std::int64_t z = 0; z < top; ++z) {
    const std::uint16_t* layer = g.counts.data() + g.index(0, 0, z);
    for (std::size_t i = 0; i < d.size(); ++i) d[i] |= layer[i] != 0;
  }
  return d;
}

// fill_shadows' limits, in cells.
struct ShadowLimits {
  double max_width_cells = 0.0;  ///< 0: no shadow filled
  double min_depth_cells = 0.0;
  /// 1 on the occupied cells of free-standing obstacles: 8-connected pieces at most
  /// max_width_cells across (bounding box). A wall seen end-on is narrow but belongs to the
  /// whole wall; so does a cabinet standing against it.
  std::vector<std::uint8_t> compact;
};

// ShadowLimits::compact of an occupancy grid.
std::vector<std::uint8_t> compact_obstacles(const Grid<std::uint8_t>& occupied, double max_cells) {
  std::vector<std::uint8_t> out(occupied.size(), 0);
  if (max_cells <= 0.0 || occupied.size() == 0) return out;
  cv::Mat m(occupied.height, occupied.width, CV_8U,
            const_cast<std::uint8_t*>(occupied.data.data())),  // read only
      labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(m, labels, stats, centroids, 8, CV_32S);
  std::vector<std::uint8_t> small(static_cast<std::size_t>(n), 0);
  for (int l = 1; l < n; ++l)
    small[static_cast<std::size_t>(l)] =
        std::max(stats.at<int>(l, cv::CC_STAT_WIDTH), stats.at<int>(l, cv::CC_STAT_HEIGHT)) <=
        max_cells;
  for (int r = 0; r < occupied.height; ++r)
    for (int c = 0; c < occupied.width; ++c)
      out[static_cast<std::size_t>(r) * occupied.width + c] =
          small[static_cast<std::size_t>(labels.at<int>(r, c))];
  return out;
}

// One ray of cast_from: where it ended (cells from the position) and whether an occupied cell
// stopped it before the farthest low-seen column of its bin.
struct RayEnd {
  float end = 0.0f;
  bool blocked = false;
  float reach = 0.0f;  ///< the farthest low-seen column of the bin
};

// Walks from the position along angle a up to len cells, marking the cells crossed; stops at the
// first occupied cell beyond clear_cells. Steps of a quarter cell: simple, and it visits every
// cell a ray crosses but for corner grazes (the neighbouring bins cover those).
RayEnd walk(const Eigen::Vector2d& s, double a, double from, double len,
            const Grid<std::uint8_t>& occupied, double clear_cells,
            std::vector<std::uint8_t>& marked) {
  const int w = occupied.width, h = occupied.height;
  const double dx = std::cos(a), dy = std::sin(a);
  int last = -1;
  for (double t = from; t <= len; t += 0.25) {
    const int c = static_cast<int>(std::floor(s.x() + t * dx));
    const int r = static_cast<int>(std::floor(s.y() + t * dy));
    if (c < 0 || r < 0 || c >= w || r >= h) return {static_cast<float>(t), false};
    const int idx = r * w + c;
    if (idx == last) continue;
    last = idx;
    if (occupied.data[static_cast<std::size_t>(idx)] && t > clear_cells)
      return {static_cast<float>(t), true};
    marked[static_cast<std::size_t>(idx)] = 1;
  }
  return {static_cast<float>(len), false};
}

// One ray of a shadow, from t0 cells on along u: every cell up to len (the line joining the
// side rays' ends), and beyond it up to the bin's own reach only as far as the last cell whose
// floor was seen: the unknown cells of a doorway between the shadow and the floor seen through
// it from elsewhere, not the inside of a wall whose face the obstacle hid. Stops at the first
// occupied cell. Returns the cells marked.
std::size_t walk_shadow(const Eigen::Vector2d& s, const Eigen::Vector2d& u, double t0, double len,
                        double reach, const Grid<std::uint8_t>& occupied,
                        const std::vector<std::uint8_t>& floor_seen,
                        std::vector<std::uint8_t>& shadow) {
  const int w = occupied.width, h = occupied.height;
  std::vector<std::size_t> cells;
  std::size_t keep = 0;
  int last = -1;
  for (double t = t0; t <= std::max(len, reach); t += 0.25) {
    const int c = static_cast<int>(std::floor(s.x() + t * u.x()));
    const int r = static_cast<int>(std::floor(s.y() + t * u.y()));
    if (c < 0 || r < 0 || c >= w || r >= h) break;
    const int idx = r * w + c;
    if (idx == last) continue;
    last = idx;
    const auto i = static_cast<std::size_t>(idx);
    if (occupied.data[i]) break;
    cells.push_back(i);
    if (t <= len || floor_seen[i]) keep = cells.size();
  }
  for (std::size_t k = 0; k < keep; ++k) shadow[cells[k]] = 1;
  return keep;
}

// The shadow of a narrow obstacle (docs/pipeline.md, "Shadows"): a run of neighbouring bins whose
// rays stop on one obstacle (stop points within two cells of each other) at most max_width_cells
// wide, where the rays on both sides of the run go on at least min_depth_cells beyond its
// farthest stop. The floor behind it is taken to go on as on both sides: each ray of the run is
// walked on from behind the obstacle to the line joining the two side rays' ends, stopping at the
// next occupied cell. A pillar in mid-room hides a wedge of floor; a cabinet against a wall has
// the wall within min_depth behind it, and a wall is wider than max_width.
std::size_t fill_shadows(const Eigen::Vector2d& s, const std::vector<RayEnd>& ends, double to_bin,
                         const Grid<std::uint8_t>& occupied,
                         const std::vector<std::uint8_t>& floor_seen, const ShadowLimits& lim,
                         std::vector<std::uint8_t>& shadow) {
  const int bins = static_cast<int>(ends.size());
  if (lim.max_width_cells <= 0.0) return 0;
  // The rays cast: near the position most bins hold no column and cast none.
  std::vector<int> cast;
  for (int b = 0; b < bins; ++b)
    if (ends[static_cast<std::size_t>(b)].end > 0.0f) cast.push_back(b);
  const int n = static_cast<int>(cast.size());
  if (n < 3) return 0;
  const auto angle = [&](int b) { return (b + 0.5) / to_bin; };
  const auto bin = [&](int k) { return cast[static_cast<std::size_t>(((k % n) + n) % n)]; };
  const auto at = [&](int k) -> const RayEnd& { return ends[static_cast<std::size_t>(bin(k))]; };
  const auto point = [&](int k) {
    const double a = angle(bin(k));
    return Eigen::Vector2d(s + at(k).end * Eigen::Vector2d(std::cos(a), std::sin(a)));
  };
  const auto occ = [&](const Eigen::Vector2d& c) {
    const int col = static_cast<int>(std::floor(c.x())), row = static_cast<int>(std::floor(c.y()));
    return occupied.contains(col, row) &&
           occupied.data[static_cast<std::size_t>(row) * occupied.width + col];
  };
  // The occupied cell a blocked ray stopped on (its end lies in it, a quarter cell deep at most).
  const auto compact_at = [&](const Eigen::Vector2d& c) {
    const int col = static_cast<int>(std::floor(c.x())), row = static_cast<int>(std::floor(c.y()));
    return occupied.contains(col, row) &&
           lim.compact[static_cast<std::size_t>(row) * occupied.width + col];
  };
  // Start at the longest unblocked ray, so that no run wraps around the start.
  int start = -1;
  for (int k = 0; k < n; ++k)
    if (!at(k).blocked && (start < 0 || at(k).end > at(start).end)) start = k;
  if (start < 0) return 0;
  std::size_t filled = 0;
  for (int k = start + 1; k < start + n;) {
    if (!at(k).blocked) {
      ++k;
      continue;
    }
    // The run: blocked rays with stop points close together; a ray between them that ended
    // unblocked before reaching the obstacle (no column beyond it in its narrow bin) tells
    // nothing of what lies behind and is passed over.
    const auto short_of = [&](int j, double t) { return !at(j).blocked && at(j).end <= t + 1.0; };
    const int k0 = k;
    double far = at(k0).end;
    bool free_standing = compact_at(point(k0));
    int k1 = k0;
    for (int j = k0 + 1; j < start + n; ++j) {
      if (at(j).blocked && (point(j) - point(k1)).norm() <= 2.0) {
        k1 = j;
        far = std::max(far, static_cast<double>(at(j).end));
        free_standing = free_standing && compact_at(point(j));
      } else if (!short_of(j, at(k1).end)) {
        break;
      }
    }
    k = k1 + 1;
    if (!free_standing) continue;
    // The side rays: the nearest that ended on an obstacle (the floor goes on up to there);
    // one that ran out of columns in its narrow bin is only a lower bound.
    int kl = k0 - 1, kr = k1 + 1;
    while (kl > k1 - n && !at(kl).blocked) --kl;
    while (kr < k0 + n && !at(kr).blocked) ++kr;
    const RayEnd &left = at(kl), &right = at(kr);
    const double width = (point(k1) - point(k0)).norm();
    if (width > lim.max_width_cells || left.end < far + lim.min_depth_cells ||
        right.end < far + lim.min_depth_cells)
      continue;
    const Eigen::Vector2d pl = point(kl), pr = point(kr), e = pr - pl, q = pl - s;
    const auto unwrapped = [&](int j) { return bin(j) < bin(k0) ? bin(j) + bins : bin(j); };
    for (int bb = bin(k0), j = k0, jb = k0; bb <= unwrapped(k1); ++bb) {
      const int b = bb % bins;
      while (j < k1 && unwrapped(j + 1) <= bb)  // the obstacle's stop: the last blocked ray
        if (at(++j).blocked) jb = j;
      // The ray s + t u meets the segment pl-pr where cross(q + v e, u) = 0.
      const Eigen::Vector2d u(std::cos(angle(b)), std::sin(angle(b)));
      const double den = e.x() * u.y() - e.y() * u.x();
      const double v = std::abs(den) > 1e-9 ? (u.x() * q.y() - u.y() * q.x()) / den : -1.0;
      const double len =
          v >= 0.0 && v <= 1.0 ? (q + v * e).dot(u) : std::min<double>(left.end, right.end);
      // Behind the obstacle, taken as deep as it is wide (its back is mostly unseen: a pillar's
      // inside must not become free), then over a back face seen from elsewhere.
      double t = at(jb).end + width;
      const double t_max = t + lim.max_width_cells;
      while (t < t_max && occ(s + t * u)) t += 0.25;
      if (t >= t_max || t >= len) continue;
      filled += walk_shadow(s, u, t, len, ends[static_cast<std::size_t>(b)].reach, occupied,
                            floor_seen, shadow);
    }
  }
  return filled;
}

// 2D rays from one position: per azimuth bin, to the farthest low-seen column of the bin,
// stopping at the first occupied cell (outside the position's own clearance); then the shadows
// of narrow obstacles (fill_shadows) into `shadow`.
std::size_t cast_from(const Eigen::Vector2d& s_cells, const std::vector<std::uint8_t>& low_seen,
                      const Grid<std::uint8_t>& occupied, double max_range_cells,
                      double clear_cells, const std::vector<std::uint8_t>& floor_seen,
                      const ShadowLimits& shadows, std::vector<std::uint8_t>& crossed,
                      std::vector<std::uint8_t>& shadow) {
  const int w = occupied.width, h = occupied.height;
  double r_max = 0.0;
  const int c0 = std::max(0, static_cast<int>(std::floor(s_cells.x() - max_range_cells)));
  const int c1 = std::min(w - 1, static_cast<int>(std::ceil(s_cells.x() + max_range_cells)));
  const int r0 = std::max(0, static_cast<int>(std::floor(s_cells.y() - max_range_cells)));
  const int r1 = std::min(h - 1, static_cast<int>(std::ceil(s_cells.y() + max_range_cells)));
  if (c0 > c1 || r0 > r1) return 0;
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c)
      if (low_seen[static_cast<std::size_t>(r) * w + c])
        r_max = std::max(r_max, std::hypot(c + 0.5 - s_cells.x(), r + 0.5 - s_cells.y()));
  r_max = std::min(r_max, max_range_cells);
  if (r_max < 1.0) return 0;
  // Bins half a cell wide at the farthest range, so neighbouring rays leave no cell out.
  const int bins =
      std::clamp(static_cast<int>(std::ceil(4.0 * std::numbers::pi * r_max)), 64, 1 << 16);
  std::vector<float> reach(static_cast<std::size_t>(bins), 0.0f);
  const double to_bin = bins / (2.0 * std::numbers::pi);
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      if (!low_seen[static_cast<std::size_t>(r) * w + c]) continue;
      const double dx = c + 0.5 - s_cells.x(), dy = r + 0.5 - s_cells.y();
      const double d = std::hypot(dx, dy);
      if (d > r_max) continue;
      double a = std::atan2(dy, dx);
      if (a < 0) a += 2.0 * std::numbers::pi;
      const int b = std::min(bins - 1, static_cast<int>(a * to_bin));
      reach[static_cast<std::size_t>(b)] =
          std::max(reach[static_cast<std::size_t>(b)], static_cast<float>(d));
    }
  std::size_t rays = 0;
  std::vector<RayEnd> ends(static_cast<std::size_t>(bins));
  for (int b = 0; b < bins; ++b) {
    const double len = reach[static_cast<std::size_t>(b)];
    if (len <= 0.0) continue;
    ++rays;
    ends[static_cast<std::size_t>(b)] =
        walk(s_cells, (b + 0.5) / to_bin, 0.0, len, occupied, clear_cells, crossed);
    ends[static_cast<std::size_t>(b)].reach = static_cast<float>(len);
  }
  fill_shadows(s_cells, ends, to_bin, occupied, floor_seen, shadows, shadow);
  return rays;
}

}  // namespace

NavResult build_nav_map(const cloud::VoxelGrid& g, double floor_z_m,
                        const std::vector<Eigen::Vector3d>& scanners, const NavParams& p,
                        bool veils_cleared) {
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
  const Grid<std::uint8_t> occupied = occupied_columns(col, veils_cleared ? no_floor : floor_seen,
                                                       w, h, p, min_span, r.specks_dropped);
  for (std::size_t i = 0; i < floor_seen.size(); ++i) floor_seen[i] &= !occupied.data[i];
  std::vector<std::uint8_t> crossed(occupied.size(), 0), shadow(occupied.size(), 0);
  const ShadowLimits shadow_limits{
      g.to_cells(p.shadow_max_width_m), g.to_cells(p.shadow_min_depth_m),
      compact_obstacles(occupied, p.rays ? g.to_cells(p.shadow_max_width_m) : 0.0)};
  if (p.rays) {
    // The positions are split between the cores, each part marking its own copy of the grid;
    // the copies are OR-ed in part order (the same map whatever the timing).
    struct Part {
      std::vector<std::uint8_t> crossed, shadow;
      std::size_t positions = 0, rays = 0;
    };
    const auto parts = parallel_parts(scanners.size(), 1, [&](std::size_t k0, std::size_t k1) {
      Part part{std::vector<std::uint8_t>(occupied.size(), 0),
                std::vector<std::uint8_t>(occupied.size(), 0)};
      for (std::size_t k = k0; k < k1; ++k) {
        const Eigen::Vector3d v = g.to_voxel_coords(scanners[k]);
        if (!v.allFinite()) continue;
        ++part.positions;
        part.rays += cast_from(v.head<2>(), col.low_seen, occupied, g.to_cells(p.max_range_m),
                               g.to_cells(p.scanner_clear_m), floor_seen, shadow_limits,
                               part.crossed, part.shadow);
      }
      return part;
    });
    for (const Part& part : parts) {
      r.positions += part.positions;
      r.rays += part.rays;
      for (std::size_t i = 0; i < crossed.size(); ++i) {
        crossed[i] |= part.crossed[i];
        shadow[i] |= part.shadow[i];
      }
    }
  }
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
  // Shadows and floor holes are inferred: free in the map, not the layout's evidence.
  for (std::size_t i = 0; i < state.size(); ++i)
    if (shadow[i] && state[i] == detail::NavState::kUnknown) {
      state[i] = detail::NavState::kFree;
      ++r.cells_shadow_filled;
    }
  const double cell_m2 = geo.cell_m() * geo.cell_m();
  r.cells_hole_filled =
      detail::fill_floor_holes(state, drops(g, floor_z_m), w, h,
                               {p.floor_hole_max_m2 / cell_m2, p.floor_hole_min_free_share});
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

}  // namespace indoormap::layout
