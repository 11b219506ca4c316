#include "indoormap/cloud/voxel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "indoormap/core/errors.hpp"
#include "indoormap/core/parallel.hpp"

namespace indoormap::cloud {

namespace {

// A histogram of one axis in bins of `bin` metres, bin `half` starting at `origin` (a sample's
// median), over kMaxExtent metres either side: bounded memory whatever the data.
struct AxisHistogram {
  static constexpr double kMaxExtent = 5000.0;  // metres; far beyond any building
  float origin = 0.0f, inv_bin = 1.0f;
  std::int64_t half = 0;
  std::vector<std::uint64_t> count;

  AxisHistogram() = default;
  AxisHistogram(double origin_m, double bin_m)
      : origin(static_cast<float>(origin_m)),
        inv_bin(static_cast<float>(1.0 / bin_m)),
        half(static_cast<std::int64_t>(std::ceil(kMaxExtent / bin_m))),
        count(static_cast<std::size_t>(2 * half + 1), 0) {}
  void add(float x) {
    const float t = (x - origin) * inv_bin + static_cast<float>(half);
    if (!(t >= 0.0f && t < static_cast<float>(count.size()))) return;  // NaN fails too
    const auto k = static_cast<std::size_t>(t);
    ++count[k];
  }
  void merge(const AxisHistogram& o) {
    for (std::size_t i = 0; i < count.size(); ++i) count[i] += o.count[i];
  }
  float bin_start(std::int64_t k) const { return origin + static_cast<float>(k - half) / inv_bin; }
};

// The bins of the main body of the data along one axis: from `from` (bins known to hold data)
// outward until an empty gap of at least two bins.
std::pair<std::int64_t, std::int64_t> main_body(const AxisHistogram& h, std::int64_t from_lo,
                                                std::int64_t from_hi) {
  auto walk = [&](std::int64_t k, std::int64_t step) {
    std::int64_t last = k;
    int empty = 0;
    while (k + step >= 0 && k + step <= 2 * h.half && empty < 2) {
      k += step;
      if (h.count[static_cast<std::size_t>(k)]) {
        last = k;
        empty = 0;
      } else {
        ++empty;
      }
    }
    return last;
  };
  return {walk(from_lo, -1), walk(from_hi, +1)};
}

// Per axis: a histogram of the points outside the sample's main body (the core); most points
// fall in the core and cost two comparisons.
struct AxisPass {
  float core_lo = 0.0f, core_hi = 0.0f;  // [core_lo, core_hi): the core's values
  AxisHistogram outside;
};

double sample_median(std::vector<float>& v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

void require(bool ok, const char* what) {
  if (!ok) throw UsageError(std::string("invalid parameter ") + what);
}

}  // namespace

void validate(const VoxelParams& vx) {
  require(vx.cell_m >= 0.001 && vx.cell_m <= 10, "voxel.cell_m: must be in [0.001, 10] m");
  require(vx.max_cells > 0, "voxel.max_cells: must be > 0");
  require(vx.bounds_gap_m > 0, "voxel.bounds_gap_m: must be > 0");
  require(vx.bounds_sample > 0 && vx.bounds_sample <= 100'000'000,
          "voxel.bounds_sample: must be in [1, 1e8]");
}

void validate(const LayerParams& ly) {
  require(ly.min_points_per_voxel >= 1 && ly.min_points_per_voxel <= 65535,
          "layers.min_points_per_voxel: must be in [1, 65535]");
  require(ly.isolated_min_points >= 1, "layers.isolated_min_points: must be >= 1");
  require(ly.floor_min_fraction > 0 && ly.floor_min_fraction <= 1,
          "layers.floor_min_fraction: must be in (0, 1]");
  require(ly.ceiling_min_fraction > 0 && ly.ceiling_min_fraction <= 1,
          "layers.ceiling_min_fraction: must be in (0, 1]");
  require(ly.wall_band_m > 0, "layers.wall_band_m: must be > 0");
  require(ly.wall_min_extent_m >= 0 && ly.wall_min_extent_m <= ly.wall_band_m,
          "layers.wall_min_extent_m: must be in [0, layers.wall_band_m]");
  require(ly.furniture_max_height_m > 0, "layers.furniture_max_height_m: must be > 0");
  require(ly.low_wall_band_m >= 0 && ly.low_wall_band_m <= 1,
          "layers.low_wall_band_m: must be in [0, 1]");
  require(std::isfinite(ly.low_wall_min_length_m) && ly.low_wall_min_length_m >= 0,
          "layers.low_wall_min_length_m: must be >= 0");
  require(ly.surface_block_m >= 0 && ly.surface_block_m <= 2,
          "layers.surface_block_m: must be in [0, 2]");
  require(ly.ceiling_onset_factor > 1, "layers.ceiling_onset_factor: must be > 1");
  require(ly.min_room_height_m >= 0, "layers.min_room_height_m: must be >= 0");
  require(ly.floor_clearance_m >= 0 && ly.ceiling_clearance_m >= 0,
          "layers.*_clearance_m: must be >= 0");
}

Bounds3 robust_bounds(const std::vector<Eigen::Vector3f>& points, const VoxelParams& params) {
  validate(params);
  const std::size_t max_sample = std::max<std::size_t>(1, params.bounds_sample);
  const double step = std::max(1.0, static_cast<double>(points.size()) / max_sample);
  std::vector<float> axis[3];
  for (auto& a : axis) a.reserve(std::min(points.size(), max_sample));
  for (double i = 0; i < points.size(); i += step) {
    const auto& p = points[static_cast<std::size_t>(i)];
    if (!p.allFinite()) continue;
    for (int d = 0; d < 3; ++d) axis[d].push_back(p[d]);
  }
  if (axis[0].empty()) throw InputError("", "the cloud has no finite points");

  // The sample's main body (the core) has no gap in the whole cloud either; beyond it, the
  // walk goes on over a histogram of every point, so a far wall with few points (a corridor's end
  // 20 m from its scanner, missed by the sample) stays while a gap still cuts off what lies
  // beyond.
  const double bin = params.bounds_gap_m / 2.0;
  std::array<AxisPass, 3> proto;
  std::array<std::pair<std::int64_t, std::int64_t>, 3> core;
  for (int d = 0; d < 3; ++d) {
    AxisHistogram sample(sample_median(axis[d]), bin);
    for (float x : axis[d]) sample.add(x);
    core[d] = main_body(sample, sample.half, sample.half);
    proto[d].core_lo = sample.bin_start(core[d].first);
    proto[d].core_hi = sample.bin_start(core[d].second + 1);
    proto[d].outside = AxisHistogram(sample.origin, bin);
  }
  // One pass: the extent of the points inside the core's box, and the histograms of the
  // coordinates outside it. Usually the walk below ends at the core, and that extent is the
  // answer; when it goes on (a far wall the sample missed), a second pass takes the extent of
  // the points inside the larger box.
  struct Part {
    Eigen::Vector3f mn = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity()),
                    mx = -mn;
    bool any = false;
  };
  struct FirstPass {
    std::array<AxisPass, 3> axes;
    Part core_extent;
  };
  auto passes = parallel_parts(points.size(), 1 << 20, [&](std::size_t i0, std::size_t i1) {
    FirstPass f{proto, {}};
    for (std::size_t i = i0; i < i1; ++i) {
      bool in_core = true;
      for (int d = 0; d < 3; ++d) {
        const float x = points[i][d];
        if (x >= f.axes[d].core_lo && x <= f.axes[d].core_hi) continue;
        f.axes[d].outside.add(x);
        in_core = false;
      }
      if (!in_core) continue;
      f.core_extent.any = true;
      f.core_extent.mn = f.core_extent.mn.cwiseMin(points[i]);
      f.core_extent.mx = f.core_extent.mx.cwiseMax(points[i]);
    }
    return f;
  });
  float box_lo[3], box_hi[3];  // the main body's bins, per axis
  bool beyond_core = false;
  for (int d = 0; d < 3; ++d) {
    AxisHistogram& h = passes[0].axes[d].outside;
    for (std::size_t k = 1; k < passes.size(); ++k) h.merge(passes[k].axes[d].outside);
    for (std::int64_t k = core[d].first; k <= core[d].second; ++k)  // the core holds data
      h.count[static_cast<std::size_t>(k)] += 1;
    const auto [k0, k1] = main_body(h, core[d].first, core[d].second);
    beyond_core = beyond_core || k0 < core[d].first || k1 > core[d].second;
    box_lo[d] = std::min(h.bin_start(k0), proto[d].core_lo);
    box_hi[d] = std::max(h.bin_start(k1 + 1), proto[d].core_hi);
  }
  // The exact extent of the points inside the main body's box (on every axis at once: a point
  // seen through a window far above the room does not widen the room's x range).
  std::vector<Part> parts;
  if (!beyond_core) {
    for (const FirstPass& f : passes) parts.push_back(f.core_extent);
  } else {
    parts = parallel_parts(points.size(), 1 << 20, [&](std::size_t i0, std::size_t i1) {
      Part r;
      for (std::size_t i = i0; i < i1; ++i) {
        const float x = points[i].x(), y = points[i].y(), z = points[i].z();
        if (!(x >= box_lo[0] && x <= box_hi[0] && y >= box_lo[1] && y <= box_hi[1] &&
              z >= box_lo[2] && z <= box_hi[2]))
          continue;
        r.any = true;
        r.mn = r.mn.cwiseMin(points[i]);
        r.mx = r.mx.cwiseMax(points[i]);
      }
      return r;
    });
  }
  Bounds3 b;
  b.lo_m.setConstant(std::numeric_limits<double>::infinity());
  b.hi_m.setConstant(-std::numeric_limits<double>::infinity());
  Eigen::Vector3f mn = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity()), mx = -mn;
  bool any = false;
  for (const Part& r : parts) {
    if (!r.any) continue;
    any = true;
    mn = mn.cwiseMin(r.mn);
    mx = mx.cwiseMax(r.mx);
  }
  if (!any) return b;  // infinite bounds: voxelize reports "no points inside"
  b.lo_m = mn.cast<double>();
  b.hi_m = mx.cast<double>();
  return b;
}

VoxelGrid voxelize(const std::vector<Eigen::Vector3f>& points, const Bounds3& bounds,
                   const VoxelParams& params) {
  validate(params);
  if (!bounds.lo_m.allFinite() || !bounds.hi_m.allFinite() ||
      (bounds.hi_m.array() < bounds.lo_m.array()).any())
    throw InputError("", "no points inside the grid bounds");
  VoxelGrid g;
  g.cell_m = params.cell_m;
  // The origin is snapped to the cell size so that grids of overlapping clouds align.
  std::int64_t dims[3];
  for (int d = 0; d < 3; ++d) {
    const double lo = std::floor(bounds.lo_m[d] / params.cell_m) * params.cell_m;
    const double cells = std::floor((bounds.hi_m[d] - lo) / params.cell_m) + 1.0;
    if (!(cells <= 1e9))  // also catches NaN
      throw BudgetError("grid dimension of " + std::to_string(cells) + " cells is too large");
    g.origin_m[d] = lo;
    dims[d] = static_cast<std::int64_t>(cells);
  }
  g.nx = dims[0];
  g.ny = dims[1];
  g.nz = dims[2];
  const double total = static_cast<double>(g.nx) * static_cast<double>(g.ny) * g.nz;
  if (total > static_cast<double>(params.max_cells) || g.nx > std::numeric_limits<int>::max() / 2 ||
      g.ny > std::numeric_limits<int>::max() / 2) {
    std::ostringstream msg;
    msg << "the voxel grid would be " << g.nx << " x " << g.ny << " x " << g.nz
        << " = "
        // (total can exceed what an int64 holds: casting it then is undefined behaviour)
        << (total < 9e18 ? std::to_string(static_cast<std::int64_t>(total)) : std::to_string(total))
        << " cells of " << params.cell_m << " m, above the budget of " << params.max_cells
        << " cells (voxel.max_cells); raise the budget, use a larger cell_m, or crop the cloud";
    throw BudgetError(msg.str());
  }
  g.counts.assign(static_cast<std::size_t>(total), 0);

  // Hot loop: one multiply-add per axis, a range check that also rejects NaN, one increment.
  const VoxelBinner binner(g);
  std::uint16_t* counts = g.counts.data();
  std::uint64_t inside = 0;
  for (const auto& p : points) {
    const std::int64_t idx = binner.index_of(p);
    if (idx < 0) continue;
    const std::uint16_t c = counts[idx];
    counts[idx] = static_cast<std::uint16_t>(c + (c != 0xFFFF));
    ++inside;
  }
  g.points_inside = inside;
  g.points_outside = points.size() - inside;
  return g;
}

namespace {

HeightBand make_band(const VoxelGrid& g, double lo, double hi) {
  HeightBand b;
  b.lo_m = lo;
  b.hi_m = hi;
  b.lo_layer = std::max<std::int64_t>(0, g.layer_of(lo + 1e-9));
  b.hi_layer = std::min<std::int64_t>(
      g.nz - 1, static_cast<std::int64_t>(std::ceil(g.to_layer_coord(hi) - 1e-9)) - 1);
  return b;
}

std::string fmt_m(double v) {
  std::ostringstream s;
  s.precision(3);
  s << std::fixed << v << " m";
  return s.str();
}

// The first layer from min_layer up whose count exceeds factor x the median count of the wall
// layers between 0.5 m above the floor and min_layer: where a sloped ceiling begins.
std::optional<std::int64_t> ceiling_onset(const std::vector<std::int64_t>& h,
                                          std::int64_t floor_layer, std::int64_t min_layer,
                                          std::int64_t last, const VoxelGeometry& g,
                                          double factor) {
  const std::int64_t lo = floor_layer + static_cast<std::int64_t>(std::ceil(g.to_cells(0.5)));
  if (min_layer - lo < 3 || min_layer > last) return std::nullopt;
  std::vector<std::int64_t> walls(h.begin() + lo, h.begin() + min_layer);
  std::nth_element(walls.begin(), walls.begin() + static_cast<std::ptrdiff_t>(walls.size() / 2),
                   walls.end());
  const double baseline = static_cast<double>(walls[walls.size() / 2]);
  if (baseline <= 0) return std::nullopt;
  for (std::int64_t z = min_layer; z <= last; ++z)
    if (static_cast<double>(h[z]) >= factor * baseline) return z;
  return std::nullopt;
}

// Occupied blocks of b x b cells per layer (b = 1: occupied cells).
std::vector<std::int64_t> blocks_per_layer(const VoxelGrid& g, std::uint16_t min_pts, int b) {
  std::vector<std::int64_t> out(static_cast<std::size_t>(g.nz), 0);
  const std::int64_t bw = (g.nx + b - 1) / b, bh = (g.ny + b - 1) / b;
  std::vector<std::uint8_t> hit(static_cast<std::size_t>(bw * bh));
  for (std::int64_t z = 0; z < g.nz; ++z) {
    const std::uint16_t* layer = g.counts.data() + z * g.layer_size();
    std::fill(hit.begin(), hit.end(), 0);
    for (std::int64_t y = 0; y < g.ny; ++y)
      for (std::int64_t x = 0; x < g.nx; ++x)
        if (layer[y * g.nx + x] >= min_pts) hit[static_cast<std::size_t>((y / b) * bw + x / b)] = 1;
    out[static_cast<std::size_t>(z)] = std::count(hit.begin(), hit.end(), 1);
  }
  return out;
}

}  // namespace

double floor_fill(const VoxelGrid& v, std::int64_t floor_layer) {
  const std::int64_t b = std::max<std::int64_t>(1, std::lround(0.2 / v.cell_m));
  const std::int64_t bw = (v.nx + b - 1) / b, bh = (v.ny + b - 1) / b;
  std::vector<std::uint8_t> block(static_cast<std::size_t>(bw * bh), 0);
  std::int64_t cells = 0;
  for (std::int64_t y = 0; y < v.ny; ++y)
    for (std::int64_t x = 0; x < v.nx; ++x) {
      bool hit = false;
      for (std::int64_t z = std::max<std::int64_t>(0, floor_layer - 1);
           z <= std::min(v.nz - 1, floor_layer + 1) && !hit; ++z)
        hit = v.counts[static_cast<std::size_t>((z * v.ny + y) * v.nx + x)] > 0;
      if (!hit) continue;
      ++cells;
      block[static_cast<std::size_t>((y / b) * bw + x / b)] = 1;
    }
  const auto blocks = std::count(block.begin(), block.end(), 1);
  return blocks ? static_cast<double>(cells) / static_cast<double>(blocks * b * b) : 1.0;
}

LayerAnalysis analyse_layers(const VoxelGrid& g, const LayerParams& p) {
  validate(p);
  LayerAnalysis a;
  a.occupied_per_layer.assign(static_cast<std::size_t>(g.nz), 0);
  const std::int64_t nxy = g.layer_size();
  const auto min_pts = static_cast<std::uint16_t>(std::clamp(p.min_points_per_voxel, 1, 65535));
  for (std::int64_t z = 0; z < g.nz; ++z) {
    const std::uint16_t* layer = g.counts.data() + z * nxy;
    std::int64_t n = 0;
    for (std::int64_t i = 0; i < nxy; ++i) n += layer[i] >= min_pts;
    a.occupied_per_layer[static_cast<std::size_t>(z)] = n;
  }
  const auto& h = a.occupied_per_layer;
  std::int64_t first = -1, last = -1, max_count = 0;
  for (std::int64_t z = 0; z < g.nz; ++z) {
    if (h[z] > 0) {
      if (first < 0) first = z;
      last = z;
    }
    max_count = std::max(max_count, h[z]);
  }
  if (first < 0 || last - first < 2)
    throw InputError("", "all points lie at one height (within " +
                             fmt_m((std::max<std::int64_t>(last - first, 0) + 1) * g.cell_m) +
                             "): no floor, furniture and walls to tell apart");

  // Floor: the first strong layer from below, then up to its local peak. Strength is the layer's
  // occupied cells; when that leaves no room for a ceiling above the floor (a sparse scan: the
  // far floor's cells mostly empty, the nearer ceiling's full), its occupied blocks of
  // surface_block_m, for the floor and the ceiling alike.
  std::vector<std::int64_t> strength = h;
  auto floor_from = [&](const std::vector<std::int64_t>& st) {
    const std::int64_t max_st = *std::max_element(st.begin(), st.end());
    std::int64_t z = first;
    while (z < last && static_cast<double>(st[z]) < p.floor_min_fraction * max_st) ++z;
    while (z < last && h[z + 1] > h[z]) ++z;
    return z;
  };
  const std::int64_t room_layers =
      static_cast<std::int64_t>(std::ceil(g.to_cells(p.min_room_height_m)));
  if (p.floor_z_m) {
    a.floor_z_m = *p.floor_z_m;
    a.floor_layer = std::clamp<std::int64_t>(g.layer_of(a.floor_z_m), 0, g.nz - 1);
  } else {
    a.floor_layer = floor_from(h);
    const int block = static_cast<int>(std::lround(g.to_cells(p.surface_block_m)));
    if (a.floor_layer + room_layers > last && block > 1) {
      strength = blocks_per_layer(g, min_pts, block);
      a.floor_layer = floor_from(strength);
    }
    a.floor_z_m = g.layer_center_m(a.floor_layer);
  }
  const std::int64_t max_strength = *std::max_element(strength.begin(), strength.end());

  // Ceiling: the first strong layer from above, then down to its local peak; it must lie at
  // least min_room_height above the floor.
  const std::int64_t min_ceiling_layer = a.floor_layer + room_layers;
  if (p.ceiling_z_m) {
    a.ceiling_found = true;
    a.ceiling_z_m = *p.ceiling_z_m;
    a.ceiling_layer = std::clamp<std::int64_t>(g.layer_of(a.ceiling_z_m), 0, g.nz - 1);
  } else {
    std::int64_t z = last;
    while (z > min_ceiling_layer &&
           static_cast<double>(strength[z]) < p.ceiling_min_fraction * max_strength)
      --z;
    while (z > min_ceiling_layer && h[z - 1] > h[z]) --z;
    if (z >= min_ceiling_layer && z <= last &&
        static_cast<double>(strength[z]) >= p.ceiling_min_fraction * max_strength) {
      a.ceiling_found = true;
      a.ceiling_layer = z;
      a.ceiling_z_m = g.layer_center_m(z);
    } else if (auto onset = ceiling_onset(h, a.floor_layer, min_ceiling_layer, last, g,
                                          p.ceiling_onset_factor)) {
      a.ceiling_found = true;
      a.ceiling_sloped = true;
      a.ceiling_layer = *onset;
      a.ceiling_z_m = g.layer_bottom_m(*onset);
      a.warnings.push_back("the ceiling is not flat (sloped or stepped); its lowest part, at " +
                           fmt_m(a.ceiling_z_m) + ", sets the wall band");
    } else {
      a.ceiling_found = false;
      a.ceiling_layer = last;
      a.ceiling_z_m = g.layer_bottom_m(last + 1);
      a.warnings.push_back("no ceiling detected; using the top of the data (" +
                           fmt_m(a.ceiling_z_m) + ") as the ceiling height");
    }
  }
  if (a.ceiling_z_m <= a.floor_z_m)
    throw UsageError("ceiling height (" + fmt_m(a.ceiling_z_m) + ") is not above the floor (" +
                     fmt_m(a.floor_z_m) + ")");

  double wall_hi = p.wall_band_hi_m.value_or(a.ceiling_z_m - p.ceiling_clearance_m);
  double wall_lo = p.wall_band_lo_m.value_or(wall_hi - p.wall_band_m);
  const double furn_lo = p.furniture_band_lo_m.value_or(a.floor_z_m + p.floor_clearance_m);
  // A low room (or a low fallback ceiling) must still leave a furniture band of one layer.
  if (!p.wall_band_lo_m && wall_lo < furn_lo + g.cell_m) {
    wall_lo = furn_lo + g.cell_m;
    a.warnings.push_back("room is low: wall band starts at " + fmt_m(wall_lo));
  }
  if (wall_hi <= wall_lo) wall_hi = wall_lo + g.cell_m;
  // Objects hanging lower than the wall band (lamps) are not furniture: the band stops at
  // furniture_max_height_m above the floor.
  const double furn_hi =
      p.furniture_band_hi_m.value_or(std::min(wall_lo, a.floor_z_m + p.furniture_max_height_m));
  a.wall_band = make_band(g, wall_lo, wall_hi);
  a.furniture_band = make_band(g, furn_lo, furn_hi);
  const double low_lo = furn_hi + g.cell_m, low_hi = low_lo + p.low_wall_band_m;
  if (p.low_wall_band_m > 0 && low_hi <= wall_lo) a.low_wall_band = make_band(g, low_lo, low_hi);
  return a;
}

Grid<std::uint8_t> project_band(const VoxelGrid& g, const HeightBand& band, int min_points,
                                int isolated_min_points, int min_extent_layers) {
  const int w = static_cast<int>(g.nx), h = static_cast<int>(g.ny);
  Grid<std::uint32_t> sum(w, h, 0);
  const auto min_pts = static_cast<std::uint16_t>(std::clamp(min_points, 1, 65535));
  const std::int64_t nxy = g.layer_size();
  const std::int64_t z_lo = std::max<std::int64_t>(band.lo_layer, 0),
                     z_hi = std::min(band.hi_layer, g.nz - 1);
  // Lowest occupied layer per column (relative to z_lo), for the vertical extent.
  Grid<std::int32_t> first(w, h, -1);
  for (std::int64_t z = z_lo; z <= z_hi; ++z) {
    const std::uint16_t* layer = g.counts.data() + z * nxy;
    for (std::int64_t i = 0; i < nxy; ++i)
      if (layer[i] >= min_pts) {
        if (min_extent_layers > 1) {
          auto& f = first.data[static_cast<std::size_t>(i)];
          if (f < 0) f = static_cast<std::int32_t>(z - z_lo);
          // A column reaches the extent once a layer min_extent_layers - 1 above its first one
          // holds points; until then its sum stays zero.
          if (z - z_lo - f + 1 < min_extent_layers) {
            continue;
          }
        }
        sum.data[i] += layer[i];
      }
  }
  Grid<std::uint8_t> out(w, h, 0);
  const auto isolated_min = static_cast<std::uint32_t>(std::max(isolated_min_points, 1));
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const std::uint32_t n = sum.at(c, r);
      if (n == 0) continue;
      bool ok = n >= isolated_min;
      for (int dr = -1; dr <= 1 && !ok; ++dr)
        for (int dc = -1; dc <= 1 && !ok; ++dc)
          ok = (dr || dc) && sum.contains(c + dc, r + dr) && sum.at(c + dc, r + dr) > 0;
      out.at(c, r) = ok;
    }
  return out;
}

}  // namespace indoormap::cloud
