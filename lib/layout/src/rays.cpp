#include "rays.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "indoormap/core/parallel.hpp"

namespace indoormap::layout::detail {

namespace {

// One ray of cast_from: where it ended (cells from the position) and whether an occupied cell
// stopped it before the farthest low-seen column of its bin.
struct RayEnd {
  float end = 0.0f;
  bool blocked = false;
  float reach = 0.0f;  ///< the farthest low-seen column of the bin
};

// Cells without data between two occupied cells of a low obstacle, at most this many apart
// along a ray, are part of it (a cabinet's top seen at a grazing angle holds a point in every
// second or third cell), not floor behind it.
constexpr int kTopGapCells = 3;

// Walks from the position along angle a up to len cells, marking the cells crossed; stops at the
// first occupied cell beyond clear_cells that is neither `raised` (empty: none is) nor a low
// obstacle the beams passed over (BeamHeights), and returns where the first occupied cell stopped
// it or would have (the shadows are cast from there). Behind a low obstacle the beams that saw
// what lies beyond passed over the line joining the position to the highest top so far (the
// horizon): a cell more than kTopGapCells behind the last low obstacle, where that line lies
// below max_hidden, is marked in `over` (inferred: an object lower than the line could hide
// there). Steps of a quarter cell: simple, and it visits every cell a ray crosses but for corner
// grazes (the neighbouring bins cover those).
RayEnd walk(const Eigen::Vector3d& s, double a, double len, const Grid<std::uint8_t>& occupied,
            const std::vector<std::uint8_t>& raised, double clear_cells, const BeamHeights& beams,
            std::vector<std::uint8_t>& marked, std::vector<std::uint8_t>& over) {
  const int w = occupied.width, h = occupied.height;
  const double dx = std::cos(a), dy = std::sin(a);
  constexpr double kNoHorizon = -std::numeric_limits<double>::infinity();
  double slope = kNoHorizon;         // layers per cell of the line over the highest top passed
  std::vector<std::size_t> pending;  // cells behind the last low obstacle, kTopGapCells at most
  int behind = 0;                    // cells since the last low obstacle
  int last = -1;
  std::optional<RayEnd> first;  // the first occupied cell on the way
  for (double t = 0.0; t <= len; t += 0.25) {
    const int c = static_cast<int>(std::floor(s.x() + t * dx));
    const int r = static_cast<int>(std::floor(s.y() + t * dy));
    if (c < 0 || r < 0 || c >= w || r >= h) return first.value_or(RayEnd{static_cast<float>(t)});
    const int idx = r * w + c;
    if (idx == last) continue;
    last = idx;
    const auto i = static_cast<std::size_t>(idx);
    if (occupied.data[i] && t > clear_cells) {
      if (!first) first = RayEnd{static_cast<float>(t), true};
      if (!raised.empty() && raised[i]) continue;  // beneath a raised obstacle: the ray goes on
      const double top = beams.tops.empty() ? -1.0 : beams.tops[i];
      if (top < 0.0 || top > s.z() - 1.0) return *first;
      slope = std::max(slope, (top - s.z()) / t);  // over a low one
      pending.clear();
      behind = 0;
      continue;
    }
    if (slope != kNoHorizon && beams.lows[i] >= 0.0 && beams.lows[i] < s.z() - 1.0) {
      if (beams.tops[i] > s.z() - 1.0) return *first;  // something over the band, as high as us
      slope = std::max(slope, (beams.tops[i] - s.z()) / t);
      pending.clear();
      behind = 0;
      continue;
    }
    if (slope == kNoHorizon) {
      marked[i] = 1;
      continue;
    }
    const bool below = s.z() + slope * t <= beams.max_hidden;
    if (++behind <= kTopGapCells) {
      if (below) pending.push_back(i);
      continue;
    }
    for (const std::size_t j : pending) over[j] = 1;
    pending.clear();
    if (below) over[i] = 1;
  }
  return first.value_or(RayEnd{static_cast<float>(len)});
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

// The shadow of a free-standing obstacle (docs/pipeline.md, "Shadows"): a run of neighbouring
// rays that stop on one obstacle (stop points within two cells of each other), every stop on a
// ShadowLimits::compact cell, at most max_width_cells wide, where the nearest blocked rays on
// both sides of the run go on at least min_depth_cells beyond its farthest stop. The floor behind
// it is taken to go on as on both sides: each ray of the run is walked on from behind the
// obstacle to the line joining the two side rays' ends (walk_shadow), stopping at the next
// occupied cell. A pillar in mid-room hides a wedge of floor; a wall seen end-on, or a cabinet
// touching it, is part of the wall's piece, and a cabinet has the wall within min_depth behind
// it. Returns the cells marked.
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

}  // namespace

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

// 2D rays from one position: per azimuth bin, to the farthest low-seen column of the bin,
// stopping at the first occupied cell (outside the position's own clearance); then the shadows
// of narrow obstacles (fill_shadows) into `shadow`.
std::size_t cast_from(const Eigen::Vector3d& s_cells, const std::vector<std::uint8_t>& low_seen,
                      const Grid<std::uint8_t>& occupied, const std::vector<std::uint8_t>& raised,
                      double max_range_cells, double clear_cells,
                      const std::vector<std::uint8_t>& floor_seen, const ShadowLimits& shadows,
                      const BeamHeights& beams, std::vector<std::uint8_t>& crossed,
                      std::vector<std::uint8_t>& shadow, std::vector<std::uint8_t>& over) {
  const int w = occupied.width, h = occupied.height;
  const int c0 = std::max(0, static_cast<int>(std::floor(s_cells.x() - max_range_cells)));
  const int c1 = std::min(w - 1, static_cast<int>(std::ceil(s_cells.x() + max_range_cells)));
  const int r0 = std::max(0, static_cast<int>(std::floor(s_cells.y() - max_range_cells)));
  const int r1 = std::min(h - 1, static_cast<int>(std::ceil(s_cells.y() + max_range_cells)));
  if (c0 > c1 || r0 > r1) return 0;
  // Squared distances, and atan2 in float: this loop visits every column of the window for every
  // position (most of a storey's cost of the rays).
  const auto sx = static_cast<float>(s_cells.x()), sy = static_cast<float>(s_cells.y());
  float r2_max = 0.0f;
  for (int r = r0; r <= r1; ++r) {
    const float dy = r + 0.5f - sy;
    for (int c = c0; c <= c1; ++c)
      if (low_seen[static_cast<std::size_t>(r) * w + c]) {
        const float dx = c + 0.5f - sx;
        r2_max = std::max(r2_max, dx * dx + dy * dy);
      }
  }
  const double r_max = std::min<double>(std::sqrt(r2_max), max_range_cells);
  if (r_max < 1.0) return 0;
  // Bins half a cell wide at the farthest range, so neighbouring rays leave no cell out.
  const int bins =
      std::clamp(static_cast<int>(std::ceil(4.0 * std::numbers::pi * r_max)), 64, 1 << 16);
  std::vector<float> reach(static_cast<std::size_t>(bins), 0.0f);  // squared, then not
  const double to_bin = bins / (2.0 * std::numbers::pi);
  const auto to_bin_f = static_cast<float>(to_bin), r2_in = static_cast<float>(r_max * r_max);
  constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
  for (int r = r0; r <= r1; ++r) {
    const float dy = r + 0.5f - sy;
    for (int c = c0; c <= c1; ++c) {
      if (!low_seen[static_cast<std::size_t>(r) * w + c]) continue;
      const float dx = c + 0.5f - sx, d2 = dx * dx + dy * dy;
      if (d2 > r2_in) continue;
      float a = std::atan2(dy, dx);
      if (a < 0) a += kTwoPi;
      const int b = std::min(bins - 1, static_cast<int>(a * to_bin_f));
      reach[static_cast<std::size_t>(b)] = std::max(reach[static_cast<std::size_t>(b)], d2);
    }
  }
  for (float& d : reach) d = std::sqrt(d);
  std::size_t rays = 0;
  std::vector<RayEnd> ends(static_cast<std::size_t>(bins));
  for (int b = 0; b < bins; ++b) {
    const double len = reach[static_cast<std::size_t>(b)];
    if (len <= 0.0) continue;
    ++rays;
    ends[static_cast<std::size_t>(b)] =
        walk(s_cells, (b + 0.5) / to_bin, len, occupied, raised, clear_cells, beams, crossed, over);
    ends[static_cast<std::size_t>(b)].reach = static_cast<float>(len);
  }
  fill_shadows(s_cells.head<2>(), ends, to_bin, occupied, floor_seen, shadows, shadow);
  return rays;
}

namespace {

// The top face of the run of occupied voxels of column (x, y) from layer z up, gaps of one layer
// bridged.
std::int64_t run_top(const cloud::VoxelGrid& g, std::int64_t x, std::int64_t y, std::int64_t z) {
  for (std::int64_t k = z + 1; k < g.nz && k <= z + 2; ++k)
    if (g.count(x, y, k)) z = k;
  return z + 1;
}

}  // namespace

BeamHeights beam_heights(const cloud::VoxelGrid& g, const std::vector<std::int32_t>& hi,
                         const std::vector<std::int8_t>& off, std::int64_t body_hi,
                         const std::vector<Eigen::Vector3d>& scanners,
                         const Grid<std::uint8_t>& occupied,
                         const std::vector<std::uint8_t>& raised) {
  std::int64_t cap = 0;  // the highest position's layer
  for (const Eigen::Vector3d& s : scanners)
    if (s.allFinite()) cap = std::max(cap, g.layer_of(s.z()));
  BeamHeights b{std::vector<float>(occupied.size(), -1.0f),
                std::vector<float>(occupied.size(), -1.0f), 0.0};
  const std::int64_t w = occupied.width;
  for (std::size_t i = 0; i < b.tops.size(); ++i) {
    const std::int64_t x = static_cast<std::int64_t>(i) % w, y = static_cast<std::int64_t>(i) / w;
    if (occupied.data[i]) {
      if (!raised[i] && hi[i] >= 0)
        b.tops[i] = static_cast<float>(run_top(g, x, y, hi[i] + off[i]));
      continue;
    }
    for (std::int64_t z = std::max<std::int64_t>(0, body_hi + 1 + off[i]); z < std::min(cap, g.nz);
         ++z)
      if (g.count(x, y, z)) {
        b.lows[i] = static_cast<float>(z);
        b.tops[i] = static_cast<float>(run_top(g, x, y, z));
        break;
      }
  }
  return b;
}

RayMarks cast_all(const cloud::VoxelGrid& g, const std::vector<Eigen::Vector3d>& scanners,
                  const std::vector<std::uint8_t>& low_seen, const Grid<std::uint8_t>& occupied,
                  const std::vector<std::uint8_t>& raised, const RayReach& reach,
                  const std::vector<std::uint8_t>& floor_seen, const ShadowLimits& shadows,
                  const BeamHeights& beams) {
  const auto parts = parallel_parts(scanners.size(), 1, [&](std::size_t k0, std::size_t k1) {
    RayMarks part(occupied.size());
    for (std::size_t k = k0; k < k1; ++k) {
      const Eigen::Vector3d v = g.to_voxel_coords(scanners[k]);
      if (!v.allFinite()) continue;
      ++part.positions;
      part.rays +=
          cast_from(v, low_seen, occupied, raised, reach.max_range_cells, reach.clear_cells,
                    floor_seen, shadows, beams, part.crossed, part.shadow, part.over);
    }
    return part;
  });
  RayMarks all(occupied.size());
  for (const RayMarks& part : parts) {
    all.positions += part.positions;
    all.rays += part.rays;
    for (std::size_t i = 0; i < all.crossed.size(); ++i) {
      all.crossed[i] |= part.crossed[i];
      all.shadow[i] |= part.shadow[i];
      all.over[i] |= part.over[i];
    }
  }
  return all;
}

}  // namespace indoormap::layout::detail
