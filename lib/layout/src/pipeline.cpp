#include "indoormap/layout/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <span>

#include "hidden_bodies.hpp"
#include "indoormap/layout/nearest_origin.hpp"
#include "stopwatch.hpp"

namespace indoormap::layout {

namespace {

using detail::Stopwatch;

// The share of points without a known scanner up to which the ghost filter by origin still counts
// as exact (ghost_origins_exact): the upper storey's slice of a two-storey building holds 5 % of
// such points, the ceilings of the taller rooms below seen from their own positions, under its
// floor and far from the body band the exactness matters for.
constexpr double kMaxUnknownOriginShare = 0.1;

// Rays need the scanner each point came from: one scanner sees everything; several need the
// cloud's origin spans; where the input has none (a merged cloud with --scanner, a trajectory),
// each point is taken as seen from its nearest position (nearest_origin.hpp) and the run says so.
void run_ghost_filter(const PointCloud& cloud, const cloud::GhostParams& params, MapResult& r) {
  if (cloud.scanners.size() == 1) {
    r.ghosts = cloud::remove_ghost_voxels(r.voxels, cloud.points, cloud.scanners[0], params);
    r.ghost_origins_exact = r.ghosts.applied;
    return;
  }
  if (!params.enabled || cloud.scanners.empty()) return;
  if (cloud.origins.empty()) {
    const std::size_t stride = cloud::ghost_ray_stride(cloud.points.size(), params);
    const NearestOriginSamples est = sample_by_nearest_origin(cloud, stride);
    if (!est.applied) {
      r.warnings.push_back("ghost filter skipped: " + std::to_string(cloud.scanners.size()) +
                           " scanner positions and no record of which point came from which");
      return;
    }
    r.warnings.push_back("ghost filter: " + std::to_string(cloud.scanners.size()) +
                         " scanner positions and no record of which point came from which: "
                         "each point taken as seen from its nearest position");
    std::vector<cloud::RaySource> samples;
    for (std::size_t k = 0; k < est.points.size(); ++k)
      if (!est.points[k].empty()) samples.push_back({est.points[k], cloud.scanners[k]});
    r.ghosts = cloud::remove_presampled_ghost_voxels(r.voxels, samples, stride, params);
    return;
  }
  std::vector<cloud::RaySource> sources;
  std::size_t covered = 0;
  const std::span<const Eigen::Vector3f> all(cloud.points);
  for (const auto& o : cloud.origins) {
    if (o.scanner >= cloud.scanners.size() || o.first + o.count > all.size()) continue;
    sources.push_back({all.subspan(o.first, o.count), cloud.scanners[o.scanner]});
    covered += o.count;
  }
  // Points of unknown origin (in a storey's slice, those seen from another storey's positions)
  // cast no ray: they add no evidence of free space, so the filter clears no voxel because of
  // them. With most of the rays known it is still the exact filter.
  if (sources.empty()) {
    r.warnings.push_back("ghost filter skipped: " + std::to_string(cloud.scanners.size()) +
                         " scanner positions and the origin of every point unknown");
    return;
  }
  r.ghosts = cloud::remove_ghost_voxels_by_origin(r.voxels, sources, params);
  const double unknown = 1.0 - static_cast<double>(covered) / static_cast<double>(all.size());
  r.ghost_origins_exact = r.ghosts.applied && unknown <= kMaxUnknownOriginShare;
  if (r.ghosts.applied && !r.ghost_origins_exact) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f%%", 100.0 * unknown);
    r.warnings.push_back(std::string("ghost filter: the origin of ") + buf +
                         " of the points unknown; their rays not traced");
  }
}

// A single position with no origin spans is taken as the origin of every point (rays, ghost
// filter). A mobile scanner's merged cloud has one VIEWPOINT (the first pose, or nothing
// meaningful): most of its points lie behind walls from there. Then the position is dropped and
// the run says so: free space from the observed floor alone, no ghost filter from a wrong origin.
void drop_implausible_viewpoint(PointCloud& cloud, const ViewpointCheckParams& p, MapResult& r) {
  if (!p.enabled || cloud.scanners.size() != 1) return;
  const ViewpointCheck c = check_viewpoint(r.voxels, cloud.points, cloud.scanners[0], p);
  r.viewpoint_occluded_share = c.share();
  if (c.sampled == 0 || c.share() <= p.max_occluded_share) return;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.0f%%", 100.0 * c.share());
  r.warnings.push_back(std::string("the one scanner position (VIEWPOINT) cannot be the origin of "
                                   "the cloud: ") +
                       buf +
                       " of sampled points lie behind occupied voxels from it; position dropped "
                       "(no rays, no ghost filter; give --trajectory for a mobile scan)");
  cloud.scanners.clear();
  r.viewpoint_dropped = true;
}

// Furniture with points above the lowest scanner position less 0.1 m: no scanner saw its top
// (LayoutParams::hidden_body_max_depth_m). Without scanner positions, all furniture: the scan
// cannot tell which tops were seen (a mobile scanner, its path not given, sees a cabinet taller
// than itself as a ring of faces whose unseen end lets the flood into its body).
Grid<std::uint8_t> tall_furniture(const MapResult& r, const std::vector<Eigen::Vector3d>& scanners,
                                  const cloud::LayerParams& lp) {
  if (scanners.empty()) return r.furniture;
  double eye = scanners.front().z();
  for (const auto& s : scanners) eye = std::min(eye, s.z());
  cloud::HeightBand band = r.layers.furniture_band;
  band.lo_layer = std::max(band.lo_layer, r.voxels.layer_of(eye - 0.1));
  if (band.hi_layer < band.lo_layer) return {};
  Grid<std::uint8_t> tall =
      cloud::project_band(r.voxels, band, lp.min_points_per_voxel, lp.isolated_min_points);
  for (std::size_t i = 0; i < tall.size(); ++i) tall.data[i] &= r.furniture.data[i];
  return tall;
}

// Clears every 8-connected piece of the low wall band's mask that is shorter than min_cells on
// both sides of its bounding box and stands on nothing: fewer than half of its cells have points
// in at least half of the furniture band's layers below (LayerParams::low_wall_min_length_m). A
// lamp hangs over air and a desk; a wall, however short, goes on down to the floor.
void drop_hanging_pieces(Grid<std::uint8_t>& mask, const cloud::VoxelGrid& g,
                         const cloud::HeightBand& below, int min_points, double min_cells) {
  if (min_cells <= 1.0 || mask.width == 0 || mask.height == 0) return;
  cv::Mat m(mask.height, mask.width, CV_8U, mask.data.data()), labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(m, labels, stats, centroids, 8, CV_32S);
  std::vector<int> cells(static_cast<std::size_t>(n), 0), standing(cells.size(), 0);
  const std::int64_t z0 = std::max<std::int64_t>(0, below.lo_layer);
  const std::int64_t z1 = std::min(below.hi_layer, g.nz - 1);
  for (int r = 0; r < mask.height; ++r)
    for (int c = 0; c < mask.width; ++c) {
      const auto l = static_cast<std::size_t>(labels.at<int>(r, c));
      if (l == 0) continue;
      ++cells[l];
      std::int64_t filled = 0;
      for (std::int64_t z = z0; z <= z1; ++z) filled += g.count(c, r, z) >= min_points;
      standing[l] += 2 * filled >= z1 - z0 + 1;
    }
  std::vector<std::uint8_t> keep(cells.size(), 1);
  for (int l = 1; l < n; ++l) {
    const bool shortish = std::max(stats.at<int>(l, cv::CC_STAT_WIDTH),
                                   stats.at<int>(l, cv::CC_STAT_HEIGHT)) < min_cells;
    keep[static_cast<std::size_t>(l)] = !shortish || 2 * standing[static_cast<std::size_t>(l)] >=
                                                         cells[static_cast<std::size_t>(l)];
  }
  for (int r = 0; r < mask.height; ++r)
    for (int c = 0; c < mask.width; ++c)
      if (!keep[static_cast<std::size_t>(labels.at<int>(r, c))])
        mask.data[static_cast<std::size_t>(r) * mask.width + c] = 0;
}

}  // namespace

void validate(const MapParams& params) {
  cloud::validate(params.level);
  cloud::validate(params.align_walls);
  cloud::validate(params.voxel);
  cloud::validate(params.ghosts);
  cloud::validate(params.layers);
  validate(params.layout);
  validate(params.nav);
  validate(params.viewpoint_check);
}

cloud::LevelResult level_cloud(PointCloud& cloud, const MapParams& params,
                               std::vector<std::string>& warnings) {
  cloud::LevelResult level = cloud::estimate_level(cloud.points, params.level, cloud.scanners);
  warnings.insert(warnings.end(), level.warnings.begin(), level.warnings.end());
  if (!level.levelled && params.level.enabled) warnings.push_back("not levelled: " + level.note);
  if (params.align_walls.enabled) {
    level.align =
        cloud::estimate_wall_alignment(cloud.points, params.align_walls, level.map_from_input);
    if (level.align.applied)
      level.map_from_input = level.align.rotation * level.map_from_input;
    else
      warnings.push_back("walls not aligned: " + level.align.note);
  } else {
    level.align.note = "wall alignment disabled";
  }
  if (level.levelled || level.align.applied) cloud::rotate(cloud, level.map_from_input);
  return level;
}

MapResult make_map(PointCloud cloud, const MapParams& params) {
  validate(params);  // every check before the heavy stages
  MapResult r;
  Stopwatch sw;
  r.level = level_cloud(cloud, params, r.warnings);
  r.timings.push_back({"level", sw.lap_ms()});
  r.bounds = cloud::robust_bounds(cloud.points, params.voxel);
  r.voxels = cloud::voxelize(cloud.points, r.bounds, params.voxel);
  r.timings.push_back({"voxelize", sw.lap_ms()});
  map_voxelized(std::move(cloud), params, r);
  return r;
}

void map_voxelized(PointCloud cloud, const MapParams& params, MapResult& r) {
  Stopwatch sw;
  drop_implausible_viewpoint(cloud, params.viewpoint_check, r);
  if (r.viewpoint_occluded_share) r.timings.push_back({"viewpoint_check", sw.lap_ms()});
  run_ghost_filter(cloud, params.ghosts, r);
  if (r.ghosts.applied) r.timings.push_back({"ghosts", sw.lap_ms()});

  r.layers = cloud::analyse_layers(r.voxels, params.layers);
  for (const auto& w : r.layers.warnings) r.warnings.push_back(w);
  r.timings.push_back({"layers", sw.lap_ms()});

  r.geometry = r.voxels.geometry2d();
  const auto& lp = params.layers;
  r.walls = cloud::project_band(
      r.voxels, r.layers.wall_band, lp.min_points_per_voxel, lp.isolated_min_points,
      std::max(1, static_cast<int>(std::lround(r.voxels.to_cells(lp.wall_min_extent_m)))));
  // The walls of a room lower than the storey's ceiling stand through the low wall band.
  const cloud::HeightBand& lb = r.layers.low_wall_band;
  if (lb.hi_layer >= lb.lo_layer) {
    auto low = cloud::project_band(r.voxels, lb, lp.min_points_per_voxel, lp.isolated_min_points,
                                   static_cast<int>(lb.hi_layer - lb.lo_layer + 1));
    drop_hanging_pieces(low, r.voxels, r.layers.furniture_band, lp.min_points_per_voxel,
                        r.voxels.to_cells(lp.low_wall_min_length_m));
    for (std::size_t i = 0; i < low.size(); ++i) r.walls.data[i] |= low.data[i];
  }
  r.furniture = cloud::project_band(r.voxels, r.layers.furniture_band, lp.min_points_per_voxel,
                                    lp.isolated_min_points);
  // The slice just below the wall band tells hanging objects (lamps) from walls and pillars.
  const cloud::HeightBand& wb = r.layers.wall_band;
  cloud::HeightBand below;
  below.hi_layer = wb.lo_layer - 1;
  below.lo_layer = std::max<std::int64_t>(
      r.layers.furniture_band.lo_layer,
      below.hi_layer -
          static_cast<std::int64_t>(std::ceil(r.voxels.to_cells(params.layout.hanging_gap_m))) + 1);
  auto support =
      cloud::project_band(r.voxels, below, lp.min_points_per_voxel, lp.isolated_min_points);
  // So does a column standing through most of the wall band: the wall above a window, where
  // nothing is below it, is a wall, not a lamp.
  const auto tall = cloud::project_band(
      r.voxels, wb, lp.min_points_per_voxel, lp.isolated_min_points,
      static_cast<int>(std::lround(0.6 * static_cast<double>(wb.hi_layer - wb.lo_layer + 1))));
  for (std::size_t i = 0; i < support.size(); ++i) support.data[i] |= tall.data[i];
  r.timings.push_back({"project", sw.lap_ms()});

  std::vector<Eigen::Vector2d> seeds;
  for (const auto& s : cloud.scanners) seeds.emplace_back(s.x(), s.y());
  // The navigation map first: its free cells (observed floor, rays) are the layout's evidence.
  r.nav = build_nav_map(r.voxels, r.layers.floor_z_m, cloud.scanners, params.nav,
                        r.ghost_origins_exact, &r.walls);
  for (const auto& w : r.nav.warnings) r.warnings.push_back(w);
  r.timings.push_back({"nav_map", sw.lap_ms()});
  // Only for a sparse scan (LayoutParams::sparse_floor_fill): on a dense one the rule cost
  // object precision (seeds 21-40: 0.82 to 0.77) for nothing. And for a moving scanner's path:
  // its beams leave the ends and tops of cabinets unseen, the flood ran in through them, while
  // the rays from along its path show the free floor (docs/pipeline.md, step 5).
  r.floor_fill = cloud::floor_fill(r.voxels, r.layers.floor_layer);
  r.dense_scan = r.floor_fill >= params.layout.sparse_floor_fill;
  const Grid<std::uint8_t>& evidence = r.nav.observed_free;  // not the filled floor holes
  r.free_from_evidence =
      params.layout.free_needs_evidence && (r.floor_fill < params.layout.sparse_floor_fill ||
                                            (cloud.scanners_on_path && !cloud.scanners.empty()));
  // On a dense scan the flood runs everywhere but into the unseen bodies of tall furniture.
  Grid<std::uint8_t> not_hidden;
  if (!r.free_from_evidence && params.layout.free_needs_evidence) {
    not_hidden = detail::hidden_bodies(evidence, tall_furniture(r, cloud.scanners, lp), r.walls,
                                       r.geometry.cell_m(), params.layout.hidden_body_max_depth_m);
    bool any = false;
    for (auto& v : not_hidden.data) any = any || v, v = !v;
    if (!any) not_hidden = {};
  }
  const Grid<std::uint8_t>* flood_evidence = r.free_from_evidence ? &evidence
                                             : not_hidden.size()  ? &not_hidden
                                                                  : nullptr;
  // Veils of mixed pixels the ghost filter left (origins estimated: section 3c) are no furniture
  // where the flood runs over evidence only; elsewhere a veil cell taken out of a shelf's sparse
  // face opened it to the flood, which ran into the unseen body (docs/pipeline.md, step 5).
  if (!r.ghost_origins_exact && r.free_from_evidence)
    r.furniture = without_veils(r.furniture, r.walls, r.nav.map, evidence, &r.veil_cells_dropped);
  r.layout = build_layout(r.walls, r.furniture, r.geometry, seeds, params.layout, &support,
                          flood_evidence, &evidence);
  for (const auto& w : r.layout.warnings) r.warnings.push_back(w);
  r.timings.push_back({"layout", sw.lap_ms()});
  r.cloud_map = std::move(cloud);
}

}  // namespace indoormap::layout
