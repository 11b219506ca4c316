#include "indoormap/layout/storeys.hpp"

#include <algorithm>
#include <cmath>

#include "indoormap/core/errors.hpp"
#include "stopwatch.hpp"

namespace indoormap::layout {

void validate(const StoreyParams& p) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw UsageError("invalid parameter " + what);
  };
  require(p.surface_min_fraction > 0 && p.surface_min_fraction <= 1,
          "storeys.surface_min_fraction: must be in (0, 1]");
  require(p.slab_max_fraction >= 0 && p.slab_max_fraction < 1,
          "storeys.slab_max_fraction: must be in [0, 1)");
  require(std::isfinite(p.min_slab_m) && p.min_slab_m > 0, "storeys.min_slab_m: must be > 0");
  require(std::isfinite(p.min_height_m) && p.min_height_m > 0, "storeys.min_height_m: must be > 0");
}

namespace {

// The layers [lo, hi] of one storey: its floor and ceiling, the first layer from below and from
// above whose occupied cells reach `fraction` of the storey's fullest layer.
std::pair<std::int64_t, std::int64_t> floor_and_ceiling(const std::vector<std::int64_t>& occ,
                                                        std::int64_t lo, std::int64_t hi,
                                                        double fraction) {
  std::int64_t top = 0;
  for (std::int64_t z = lo; z <= hi; ++z) top = std::max(top, occ[static_cast<std::size_t>(z)]);
  const double need = fraction * static_cast<double>(top);
  std::int64_t f = lo, c = hi;
  while (f < hi && static_cast<double>(occ[static_cast<std::size_t>(f)]) < need) ++f;
  while (c > f && static_cast<double>(occ[static_cast<std::size_t>(c)]) < need) --c;
  return {f, c};
}

}  // namespace

std::vector<Storey> detect_storeys(const std::vector<std::int64_t>& occ, const VoxelGeometry& g,
                                   const StoreyParams& p) {
  validate(p);
  const double lo = g.layer_bottom_m(0), hi = g.layer_bottom_m(g.nz);
  const std::int64_t nz = static_cast<std::int64_t>(occ.size());
  Storey whole{lo, hi, lo, hi};
  if (!p.enabled || nz == 0) return {whole};
  const std::int64_t top = *std::max_element(occ.begin(), occ.end());
  const double empty = p.slab_max_fraction * static_cast<double>(top);
  const auto min_h = static_cast<std::int64_t>(std::ceil(g.to_cells(p.min_height_m)));
  const auto min_slab = std::max<std::int64_t>(1, std::llround(g.to_cells(p.min_slab_m)));
  // Slabs: runs of (nearly) empty layers, at least min_slab thick, with at least min_height of
  // data below (since the last cut) and above. Inside a storey every layer holds the walls.
  std::vector<std::int64_t> cuts;  // first layer of each storey above the lowest
  std::int64_t first = 0;
  while (first < nz && static_cast<double>(occ[static_cast<std::size_t>(first)]) <= empty) ++first;
  std::int64_t last = nz - 1;
  while (last > first && static_cast<double>(occ[static_cast<std::size_t>(last)]) <= empty) --last;
  std::int64_t base = first;
  for (std::int64_t z = first; z <= last;) {
    if (static_cast<double>(occ[static_cast<std::size_t>(z)]) > empty) {
      ++z;
      continue;
    }
    std::int64_t e = z;
    while (e <= last && static_cast<double>(occ[static_cast<std::size_t>(e)]) <= empty) ++e;
    if (e - z >= min_slab && z - base >= min_h && last - e + 1 >= min_h) {
      cuts.push_back((z + e) / 2);
      base = e;
    }
    z = e;
  }
  if (cuts.empty()) return {whole};
  std::vector<Storey> out;
  for (std::size_t k = 0; k <= cuts.size(); ++k) {
    const std::int64_t a = k == 0 ? first : cuts[k - 1];
    const std::int64_t b = k == cuts.size() ? last : cuts[k] - 1;
    const auto [f, c] = floor_and_ceiling(occ, a, b, p.surface_min_fraction);
    Storey st;
    st.floor_z_m = g.layer_center_m(f);
    st.ceiling_z_m = g.layer_center_m(c);
    st.lo_z_m = k == 0 ? lo : g.layer_bottom_m(a);
    st.hi_z_m = k == cuts.size() ? hi : g.layer_bottom_m(b + 1);
    out.push_back(st);
  }
  return out;
}

namespace {

// The points (and their scanners and origin spans) with z in [lo, hi).
PointCloud slice(const PointCloud& c, double lo, double hi) {
  PointCloud out;
  out.scanners_on_path = c.scanners_on_path;
  auto in = [&](float z) { return z >= lo && z < hi; };
  std::vector<std::size_t> scanner_index(c.scanners.size(), static_cast<std::size_t>(-1));
  for (std::size_t k = 0; k < c.scanners.size(); ++k)
    if (c.scanners[k].z() >= lo && c.scanners[k].z() < hi) {
      scanner_index[k] = out.scanners.size();
      out.scanners.push_back(c.scanners[k]);
    }
  std::size_t n = 0;
  for (const auto& p : c.points) n += in(p.z());
  out.points.reserve(n);
  if (c.origins.empty()) {
    for (const auto& p : c.points)
      if (in(p.z())) out.points.push_back(p);
    return out;
  }
  for (const auto& o : c.origins) {
    const std::size_t first = out.points.size();
    for (std::size_t i = o.first; i < o.first + o.count && i < c.points.size(); ++i)
      if (in(c.points[i].z())) out.points.push_back(c.points[i]);
    const std::size_t s =
        o.scanner < scanner_index.size() ? scanner_index[o.scanner] : static_cast<std::size_t>(-1);
    out.origins.push_back({first, out.points.size() - first, s});
  }
  return out;
}

std::vector<std::int64_t> occupied_per_layer(const cloud::VoxelGrid& g) {
  std::vector<std::int64_t> occ(static_cast<std::size_t>(g.nz), 0);
  const std::size_t n = static_cast<std::size_t>(g.layer_size());
  for (std::int64_t z = 0; z < g.nz; ++z) {
    const std::uint16_t* layer = g.counts.data() + g.index(0, 0, z);
    occ[static_cast<std::size_t>(z)] = std::count_if(layer, layer + n, [](auto v) { return v; });
  }
  return occ;
}

}  // namespace

StoreyMaps make_storey_maps(PointCloud cloud, const MapParams& params, const StoreyParams& sp,
                            int only) {
  validate(params);
  validate(sp);
  MapResult first;
  detail::Stopwatch sw;
  first.level = level_cloud(cloud, params, first.warnings);
  first.timings.push_back({"level", sw.lap_ms()});
  first.bounds = cloud::robust_bounds(cloud.points, params.voxel);
  first.voxels = cloud::voxelize(cloud.points, first.bounds, params.voxel);
  first.timings.push_back({"voxelize", sw.lap_ms()});
  StoreyMaps out;
  out.storeys = detect_storeys(occupied_per_layer(first.voxels), first.voxels, sp);
  first.timings.push_back({"storeys", sw.lap_ms()});
  const int n = static_cast<int>(out.storeys.size());
  if (only >= n)
    throw UsageError("--storey " + std::to_string(only) + ": the cloud has " + std::to_string(n) +
                     (n == 1 ? " storey (0)" : " storeys (0-" + std::to_string(n - 1) + ")"));
  if (n == 1) {  // today's pipeline on the whole cloud, its voxels reused
    map_voxelized(std::move(cloud), params, first);
    out.storeys[0].floor_z_m = first.layers.floor_z_m;  // the layer analysis' own heights
    out.storeys[0].ceiling_z_m = first.layers.ceiling_z_m;
    out.mapped.push_back(0);
    out.maps.push_back(std::move(first));
    return out;
  }
  first.voxels = {};  // the whole grid is not needed any more
  for (int k = 0; k < n; ++k) {
    if (only >= 0 && k != only) continue;
    const Storey& st = out.storeys[static_cast<std::size_t>(k)];
    MapResult r;
    r.level = first.level;
    r.warnings = first.warnings;
    r.timings = first.timings;  // level, voxelize and storeys of the whole cloud
    sw.lap_ms();                // not the storeys mapped before
    PointCloud part = slice(cloud, st.lo_z_m, st.hi_z_m);
    if (part.points.empty()) continue;
    r.bounds = cloud::robust_bounds(part.points, params.voxel);
    r.voxels = cloud::voxelize(part.points, r.bounds, params.voxel);
    r.timings.push_back({"storey_voxelize", sw.lap_ms()});
    map_voxelized(std::move(part), params, r);
    out.mapped.push_back(k);
    out.maps.push_back(std::move(r));
  }
  return out;
}

}  // namespace indoormap::layout
