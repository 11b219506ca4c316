#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <opencv2/imgproc.hpp>

#include "indoormap/core/errors.hpp"
#include "objects_internal.hpp"

namespace indoormap::objects {

using namespace detail;

namespace {

// Pieces of fewer than min_cells cells (left by the height split: a monitor on a desk, a noisy
// edge) rejoin the neighbouring piece they share the longest border with, smallest first.
Labels merge_small_pieces(const Labels& in, const Grid<std::uint8_t>& mask, Connectivity conn,
                          std::int64_t min_cells) {
  const int n = in.count;
  if (n < 2) return in;
  std::vector<std::int64_t> area(n + 1, 0);
  for (int v : in.labels.data) ++area[v];
  std::map<std::pair<int, int>, std::int64_t> border;
  const int w = mask.width, h = mask.height;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const int a = in.labels.at(c, r);
      if (!a) continue;
      for (auto [dc, dr] : {std::pair{1, 0}, {0, 1}}) {
        if (!mask.contains(c + dc, r + dr)) continue;
        const int b = in.labels.at(c + dc, r + dr);
        if (b && b != a) ++border[{std::min(a, b), std::max(a, b)}];
      }
    }
  std::vector<int> parent(n + 1);
  for (int i = 0; i <= n; ++i) parent[i] = i;
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i + 1;
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return area[a] < area[b] || (area[a] == area[b] && a < b); });
  std::vector<std::int64_t> set_area = area;
  for (int piece : order) {
    const int root = find(piece);
    if (set_area[root] >= min_cells) continue;
    std::map<int, std::int64_t> shared;  // neighbouring set -> border length
    for (const auto& [pair, len] : border) {
      const int a = find(pair.first), b = find(pair.second);
      if (a == b) continue;
      if (a == root)
        shared[b] += len;
      else if (b == root)
        shared[a] += len;
    }
    if (shared.empty()) continue;
    const int target =
        std::max_element(shared.begin(), shared.end(), [](const auto& x, const auto& y) {
          return x.second < y.second || (x.second == y.second && x.first > y.first);
        })->first;
    parent[root] = target;
    set_area[target] += set_area[root];
  }
  Grid<std::uint8_t> merged_mask = mask;
  // Relabel: same partition as the union, numbered in raster order, via the generic labeller.
  return label_components(merged_mask, conn, [&](CellIndex a, CellIndex b) {
    return find(in.labels.at(a)) == find(in.labels.at(b));
  });
}

// Labels the furniture cells; with split_height_step_m, neighbours whose tops differ more belong
// to different pieces, and small pieces rejoin a neighbour.
Labels label_objects(const Grid<std::uint8_t>& mask, const Grid<float>& top,
                     const GridGeometry& geo, const ObjectParams& params, bool any_data) {
  std::function<bool(CellIndex, CellIndex)> joins;
  if (params.split_height_step_m > 0 && any_data)
    joins = [&](CellIndex a, CellIndex b) {
      return std::abs(top.at(a) - top.at(b)) <= params.split_height_step_m + 1e-6;
    };
  Labels lab = label_components(mask, params.connectivity, joins);
  if (joins)
    lab = merge_small_pieces(
        lab, mask, params.connectivity,
        static_cast<std::int64_t>(std::ceil(params.min_area_m2 / (geo.cell_m() * geo.cell_m()))));
  return lab;
}

struct Acc {
  std::int64_t cells = 0;
  CellIndex start{-1, -1}, lo{std::numeric_limits<int>::max(), std::numeric_limits<int>::max()},
      hi{-1, -1};
  std::int64_t bottom = std::numeric_limits<std::int64_t>::max(), top = -1;
  bool touches_wall = false;
  std::vector<std::int64_t> tops;  // per cell with data
  std::int64_t solid = 0;   // cells with data holding more than a stray return (FurnitureObject::
                            // surface_cells)
  std::int64_t lintel = 0;  // cells with data under a lintel (lintel_above)
  // Cells with data that hang: the column's run starts at least hanging_min_clearance_m above
  // the floor and the floor under it was seen (hanging_cell), and the lowest of those starts.
  std::int64_t hanging = 0, hanging_bottom = std::numeric_limits<std::int64_t>::max();
};

// A cell of a hanging object (a lamp, a wall cupboard): its occupied run starts at least
// `clearance` layers above the floor, and the floor under it was seen, or a scanner had it in
// sight from above (a lamp over the scanner: the floor under it lies in the blind cone). Under a
// tall shelf's top the floor is hidden by the shelf's body, so its top-only cells do not hang.
bool hanging_cell(const Column& col, const cloud::VoxelGrid& voxels, int c, int r,
                  std::int64_t floor_layer, std::int64_t clearance,
                  const std::vector<Eigen::Vector3d>& scanners_map) {
  if (col.top < 0 || col.bottom - floor_layer < clearance) return false;
  if (floor_seen(voxels, c, r, floor_layer)) return true;
  const Eigen::Vector3d floor(voxels.origin_m.x() + (c + 0.5) * voxels.cell_m,
                              voxels.origin_m.y() + (r + 0.5) * voxels.cell_m,
                              voxels.layer_center_m(floor_layer + 1));
  // Only a run above the scanner's head, over the floor within its height of it (45 degrees
  // down, where a terrestrial scanner's field ends: -40 to -60 degrees). A cabinet's top next to
  // the scanner lies below its head, and its sides in the same blind cone leave the line clear;
  // farther out a clear line through a sparse face is no sign of a floor that was only missed.
  const double run_bottom = voxels.layer_bottom_m(col.bottom);
  return std::any_of(scanners_map.begin(), scanners_map.end(), [&](const Eigen::Vector3d& s) {
    return s.z() < run_bottom && (s - floor).head<2>().norm() <= s.z() - floor.z() &&
           line_of_sight(voxels, s, floor, voxels.cell_m);
  });
}

// Per label: its cells, bounding box, voxel range and whether it touches a wall.
std::vector<Acc> accumulate(const Labels& lab, const ColumnScan& scan, const Grid<Cell>& layout,
                            const cloud::VoxelGrid& voxels, const cloud::LayerAnalysis& layers,
                            const ObjectParams& params,
                            const std::vector<Eigen::Vector3d>& scanners_map) {
  const Grid<Column>& cols = scan.cols;
  const auto gap = static_cast<std::int64_t>(std::ceil(voxels.to_cells(kOpeningMinGap_m) - 1e-9));
  const auto clearance =
      static_cast<std::int64_t>(std::ceil(voxels.to_cells(params.hanging_min_clearance_m) - 1e-9));
  const auto run = static_cast<std::int64_t>(std::ceil(voxels.to_cells(kLintelMin_m) - 1e-9));
  const int w = layout.width, h = layout.height;
  std::vector<Acc> acc(static_cast<std::size_t>(lab.count) + 1);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const int id = lab.labels.at(c, r);
      if (!id) continue;
      Acc& a = acc[id];
      if (a.cells++ == 0) a.start = {c, r};
      a.lo = {std::min(a.lo.col, c), std::min(a.lo.row, r)};
      a.hi = {std::max(a.hi.col, c), std::max(a.hi.row, r)};
      const Column& col = cols.at(c, r);
      if (col.top >= 0) {
        a.bottom = std::min(a.bottom, col.bottom);
        a.top = std::max(a.top, col.top);
        a.tops.push_back(col.top);
        // Where surfaces leave one or two returns to a cell themselves (a sparse scan, a
        // resampled cloud), every seen cell counts.
        a.solid += !scan.surface_test || col.points > scan.stray_max_points;
        a.lintel += lintel_above(voxels, c, r, layers.floor_layer, layers.ceiling_layer, gap, run);
        if (hanging_cell(col, voxels, c, r, layers.floor_layer, clearance, scanners_map)) {
          ++a.hanging;
          a.hanging_bottom = std::min(a.hanging_bottom, col.bottom);
        }
      }
      for (int dr = -1; dr <= 1 && !a.touches_wall; ++dr)
        for (int dc = -1; dc <= 1; ++dc)
          if (layout.contains(c + dc, r + dr) && layout.at(c + dc, r + dr) == Cell::kWall) {
            a.touches_wall = true;
            break;
          }
    }
  return acc;
}

// The wall under a window (its parapet), which the layout calls furniture when the window spans
// the wall band: it touches the wall, and a lintel (lintel_above) stands over at least half its
// length and over at least a fifth of its seen cells. The lintel is the wall's inner face, one or
// two rows of cells, so a parapet (the wall's thickness, 0.2-0.3 m deep) has a fifth or more of
// its cells under it, a desk, cabinet or shelf under a window (0.3 m deep or more, in front of the
// face) less.
bool under_lintel(const Acc& a) {
  const int length_cells = std::max(a.hi.col - a.lo.col, a.hi.row - a.lo.row) + 1;
  return a.touches_wall && 2 * a.lintel >= length_cells &&
         5 * a.lintel >= static_cast<std::int64_t>(a.tops.size());
}

// The labels of at least min_area_m2 become objects, numbered in raster order; res.labels holds
// their ids.
void list_objects(const std::vector<Acc>& acc, const Labels& lab, const GridGeometry& geo,
                  const cloud::VoxelGrid& voxels, const cloud::LayerAnalysis& layers,
                  const ObjectParams& params, ObjectsResult& res) {
  const std::int64_t floor_layer = layers.floor_layer;
  const int w = lab.labels.width, h = lab.labels.height;
  const double cell_area = geo.cell_m() * geo.cell_m();
  std::vector<int> new_id(acc.size(), 0);
  std::vector<std::uint8_t> parapet(acc.size(), 0);
  for (int id = 1; id <= lab.count; ++id) {
    const Acc& a = acc[id];
    if (a.cells * cell_area < params.min_area_m2) continue;
    if (static_cast<double>(a.tops.size()) * cell_area < params.min_seen_area_m2) continue;
    if (under_lintel(a)) {
      parapet[id] = 1;
      continue;
    }
    FurnitureObject o;
    o.id = static_cast<int>(res.objects.size()) + 1;
    new_id[id] = o.id;
    o.cells = a.cells;
    o.seen_cells = static_cast<std::int64_t>(a.tops.size());
    o.surface_cells = a.solid;
    o.start_cell = a.start;
    o.min_cell = a.lo;
    o.max_cell = a.hi;
    o.min_m = geo.origin_m() + Eigen::Vector2d(a.lo.col, a.lo.row) * geo.cell_m();
    o.max_m = geo.origin_m() + Eigen::Vector2d(a.hi.col + 1, a.hi.row + 1) * geo.cell_m();
    o.area_m2 = a.cells * cell_area;
    o.touches_wall = a.touches_wall;
    if (a.top >= 0) {
      o.has_height = true;
      // Most of its cells hang: a lamp low enough for the furniture band, with a few cells of the
      // wall's face it touches (which reach the floor) in its piece.
      const bool mostly_hanging = 2 * a.hanging > static_cast<std::int64_t>(a.tops.size());
      const std::int64_t bottom = mostly_hanging ? a.hanging_bottom : a.bottom;
      o.on_floor = bottom <= floor_layer + 2;
      o.z_min_m = o.on_floor ? voxels.layer_center_m(floor_layer) : voxels.layer_bottom_m(bottom);
      if (o.z_min_m - layers.floor_z_m >= params.hanging_min_clearance_m)
        o.kind = ObjectKind::kHanging;
      // The top is a high percentile of the cells' tops, not their maximum: a strip of cells on
      // the wall face behind an object, or a mixed pixel, must not lift a cabinet to the ceiling.
      std::vector<std::int64_t> tops = a.tops;
      const auto k = static_cast<std::size_t>(params.top_percentile / 100.0 *
                                              static_cast<double>(tops.size() - 1));
      std::nth_element(tops.begin(), tops.begin() + static_cast<std::ptrdiff_t>(k), tops.end());
      o.z_max_m = voxels.layer_center_m(tops[k]);
    }
    res.objects.push_back(std::move(o));
  }
  res.wall_cells = Grid<std::uint8_t>(w, h, 0);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      res.labels.at(c, r) = new_id[lab.labels.at(c, r)];
      res.wall_cells.at(c, r) = parapet[lab.labels.at(c, r)];
    }
}

// Outline, minimum-area box and point count of every object.
void measure_objects(const GridGeometry& geo, const cloud::VoxelGrid& voxels, ObjectsResult& res) {
  for (auto& o : res.objects) {
    o.footprint_m = outline(res.labels, o.id, o.min_cell, o.max_cell, geo);
    o.box = min_area_box(o.footprint_m);
    if (!o.has_height) continue;
    const std::int64_t z0 = voxels.layer_of(o.z_min_m);
    const std::int64_t z1 = voxels.layer_of(o.z_max_m);
    for (int r = o.min_cell.row; r <= o.max_cell.row; ++r)
      for (int c = o.min_cell.col; c <= o.max_cell.col; ++c)
        if (res.labels.at(c, r) == o.id)
          for (std::int64_t z = std::max<std::int64_t>(z0, 0); z <= std::min(z1, voxels.nz - 1);
               ++z)
            o.point_count += voxels.count(c, r, z);
  }
}

// Clears from `wall` (1 on the layout's wall cells) the specks on furniture: pieces of wall cells
// smaller than kMaxSpeckM2 whose ring of neighbouring cells is mostly furniture. The top of a
// shelf that reaches the wall band leaves such specks on the shelf; they are no wall its cells
// could be the face of (second tuning set: two shelves against a wall lost). A wall seen only in
// fragments keeps them: free or unknown space lies beside its pieces.
void drop_specks_on_furniture(const Grid<Cell>& layout, double cell_m, cv::Mat& wall) {
  constexpr double kMaxSpeckM2 = 0.1;  // a pillar of 0.3 x 0.3 m is larger
  cv::Mat pieces, stats, centroids;
  const int n = cv::connectedComponentsWithStats(wall, pieces, stats, centroids, 8, CV_32S);
  const int max_cells = static_cast<int>(std::ceil(kMaxSpeckM2 / (cell_m * cell_m)));
  std::vector<int> ring(static_cast<std::size_t>(n), 0), ring_furniture(ring);
  for (int r = 0; r < layout.height; ++r)
    for (int c = 0; c < layout.width; ++c) {
      if (layout.at(c, r) == Cell::kWall) continue;
      int seen[8], m = 0;  // the pieces this cell borders, each once
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          if (!layout.contains(c + dc, r + dr)) continue;
          const int k = pieces.at<int>(r + dr, c + dc);
          if (k > 0 && std::find(seen, seen + m, k) == seen + m) seen[m++] = k;
        }
      for (int i = 0; i < m; ++i) {
        ++ring[seen[i]];
        ring_furniture[seen[i]] += layout.at(c, r) == Cell::kFurniture;
      }
    }
  for (int r = 0; r < layout.height; ++r)
    for (int c = 0; c < layout.width; ++c)
      if (const int k = pieces.at<int>(r, c); k > 0 &&
                                              stats.at<int>(k, cv::CC_STAT_AREA) < max_cells &&
                                              2 * ring_furniture[k] > ring[k])
        wall.at<std::uint8_t>(r, c) = 0;
}

// A piece lying almost wholly within kWallFaceCells of a wall, and longer along the wall than
// across, is the wall's face seen in the furniture band without its wall-band part (the far face
// of a wall seen at a grazing angle, a doorway's reveal under its lintel, the face of a wall
// whose top ends in a low room), not furniture standing in front of the wall: the thinnest item
// (a shelf, 0.3 m deep) reaches beyond that zone (0.15 m). A compact piece (a bin in a corner)
// stays. Such pieces leave the list and count as left over; those beside a wall are marked in
// wall_cells (the unseen world below is no wall). Specks of wall on furniture are no wall here
// (drop_specks_on_furniture).
void drop_wall_faces(const Grid<Cell>& layout, double cell_m, ObjectsResult& res) {
  constexpr double kMinFaceShare = 0.8, kMinElongation = 1.5, kThinnestItemM = 0.3;
  cv::Mat wall(layout.height, layout.width, CV_8U), unknown(layout.height, layout.width, CV_8U);
  for (int r = 0; r < layout.height; ++r)
    for (int c = 0; c < layout.width; ++c) {
      wall.at<std::uint8_t>(r, c) = layout.at(c, r) == Cell::kWall ? 1 : 0;
      unknown.at<std::uint8_t>(r, c) = layout.at(c, r) == Cell::kUnknown ? 1 : 0;
    }
  drop_specks_on_furniture(layout, cell_m, wall);
  // The unknown that reaches the map's edge is the unseen world beyond the scan: a wall whose
  // wall band was not seen (the far end of a corridor, a face seen through a door under its
  // lintel) borders it. Such a face leaves the list too, but is not marked as wall: the rooms
  // step finds the room's edge at the unknown behind it, as before.
  cv::Mat lab;
  const int n = cv::connectedComponents(unknown, lab, 8, CV_32S);
  std::vector<std::uint8_t> outside(static_cast<std::size_t>(n), 0);
  for (int r = 0; r < layout.height; ++r)
    for (int c = 0; c < layout.width; ++c)
      if (r == 0 || c == 0 || r == layout.height - 1 || c == layout.width - 1)
        outside[lab.at<int>(r, c)] = 1;
  outside[0] = 0;
  cv::Mat edge(layout.height, layout.width, CV_8U);
  for (int r = 0; r < layout.height; ++r)
    for (int c = 0; c < layout.width; ++c)
      edge.at<std::uint8_t>(r, c) = wall.at<std::uint8_t>(r, c) || outside[lab.at<int>(r, c)];
  const cv::Mat square =
      cv::getStructuringElement(cv::MORPH_RECT, {2 * kWallFaceCells + 1, 2 * kWallFaceCells + 1});
  cv::dilate(wall, wall, square);
  cv::dilate(edge, edge, square);
  std::erase_if(res.objects, [&](const FurnitureObject& o) {
    if (o.kind != ObjectKind::kFurniture || !o.own_cells.empty()) return false;
    if (o.box.length_m < kMinElongation * o.box.width_m) return false;
    std::int64_t near_wall = 0, near_edge = 0;
    for (int r = o.min_cell.row; r <= o.max_cell.row; ++r)
      for (int c = o.min_cell.col; c <= o.max_cell.col; ++c)
        if (res.labels.at(c, r) == o.id) {
          near_wall += wall.at<std::uint8_t>(r, c);
          near_edge += edge.at<std::uint8_t>(r, c);
        }
    const double need = kMinFaceShare * static_cast<double>(o.cells);
    const bool a_wall = static_cast<double>(near_wall) >= need;
    // Beside the unseen world, only a strip thinner than the thinnest item: a sparse scan's
    // cabinet is a ring of faces around unseen cells that reach the map's edge through its gaps.
    if (!a_wall && (o.box.width_m >= kThinnestItemM || static_cast<double>(near_edge) < need))
      return false;
    for (int r = o.min_cell.row; r <= o.max_cell.row; ++r)
      for (int c = o.min_cell.col; c <= o.max_cell.col; ++c)
        if (res.labels.at(c, r) == o.id) {
          res.labels.at(c, r) = 0;
          if (a_wall) res.wall_cells.at(c, r) = 1;
        }
    res.left_over_cells += o.cells;
    ++res.left_over_pieces;
    return true;
  });
}

}  // namespace

ObjectsResult extract_objects(const Grid<Cell>& layout, const GridGeometry& geo,
                              const cloud::VoxelGrid& voxels, const cloud::LayerAnalysis& layers,
                              const ObjectParams& params,
                              const std::vector<Eigen::Vector3d>& scanners_map,
                              const ScanTraits& traits) {
  validate(params);
  const int w = layout.width, h = layout.height;
  if (w != geo.width() || h != geo.height() || voxels.nx != w || voxels.ny != h)
    throw Error("extract_objects: layout, geometry and voxel grid differ in size");
  ObjectsResult res;
  res.labels = Grid<std::int32_t>(w, h, 0);
  if (w == 0 || h == 0) return res;

  Grid<std::uint8_t> mask(w, h, 0);
  for (std::size_t i = 0; i < mask.size(); ++i) mask.data[i] = layout.data[i] == Cell::kFurniture;

  // Column extents; cells without data (pockets, closed gaps) take the top of the nearest cell
  // with data so that they join the object they fill.
  const bool dense = traits.dense
                         ? *traits.dense
                         : cloud::floor_fill(voxels, layers.floor_layer) >= kDenseFloorFill;
  ColumnScan scan = scan_columns(layout, voxels, layers, params, mask, dense);
  // Without positions, on a scan whose count tells a stray (ScanTraits::peel_strays): the stray
  // cells leave the mask, and a cell without data takes its top from the nearest surface away
  // from the walls (the cabinet's front), not from the returns off the wall above it nor from a
  // stray nearer it (furniture-extract.md, step 2).
  const bool peel = traits.peel_strays && scan.surface_test;
  scan.surface_first = traits.moving || peel;
  if (peel) {
    for (std::size_t i = 0; i < mask.size(); ++i)
      if (mask.data[i] && scan.cols.data[i].top >= 0 &&
          scan.cols.data[i].points <= scan.stray_max_points)
        mask.data[i] = 0;  // left over
    scan.off_walls = surfaces_off_walls(layout, scan, mask);
  }
  const Grid<float> top = fill_tops(geo, voxels, scan, scanners_map, mask);
  PieceHeights heights{top, Grid<float>(w, h, kNoHeight), layers.floor_z_m, voxels.cell_m};
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (mask.data[i] && scan.cols.data[i].bottom >= 0)
      heights.bottom.data[i] = static_cast<float>(voxels.layer_bottom_m(scan.cols.data[i].bottom));
  Grid<std::uint8_t> solid(w, h, 0);  // cells with more than a stray return
  for (std::size_t i = 0; i < solid.size(); ++i)
    solid.data[i] = scan.cols.data[i].top >= 0 && scan.cols.data[i].points > scan.stray_max_points;
  const Labels lab =
      split_at_necks(join_fragments(label_objects(mask, top, geo, params, scan.any_data), heights,
                                    geo.cell_m(), params),
                     solid, geo.cell_m(), params);
  const std::vector<Acc> acc = accumulate(lab, scan, layout, voxels, layers, params, scanners_map);
  list_objects(acc, lab, geo, voxels, layers, params, res);
  res.left_over_pieces = lab.count - static_cast<std::int64_t>(res.objects.size());
  for (std::size_t i = 0; i < layout.size(); ++i)
    res.left_over_cells += layout.data[i] == Cell::kFurniture && res.labels.data[i] == 0;
  measure_objects(geo, voxels, res);
  drop_wall_faces(layout, geo.cell_m(), res);
  res.left_over_area_m2 = static_cast<double>(res.left_over_cells) * geo.cell_m() * geo.cell_m();
  if (params.pillar_max_extent_m > 0) add_pillars(layout, geo, voxels, layers, params, res);
  if (params.lamp_max_extent_m > 0) add_lamps(layout, geo, voxels, layers, params, res);
  // No object below the minimum area, of any kind (a pillar's or a lamp's area is its fitted
  // footprint's, which may be smaller than its cells').
  std::erase_if(res.objects, [&](const FurnitureObject& o) {
    const bool drop = o.kind != ObjectKind::kFurniture && o.kind != ObjectKind::kHanging &&
                      o.area_m2 < params.min_area_m2;
    if (drop && o.own_cells.empty())
      for (auto& v : res.labels.data) v = v == o.id ? 0 : v;
    return drop;
  });
  for (std::size_t k = 0; k < res.objects.size(); ++k) {
    FurnitureObject& o = res.objects[k];
    const int id = static_cast<int>(k) + 1;
    if (o.id != id && o.own_cells.empty())
      for (int r = o.min_cell.row; r <= o.max_cell.row; ++r)
        for (int c = o.min_cell.col; c <= o.max_cell.col; ++c)
          if (res.labels.at(c, r) == o.id) res.labels.at(c, r) = id;
    o.id = id;
  }
  return res;
}

void drop_stray_pieces(ObjectsResult& res, const GridGeometry& geo, const ObjectParams& params) {
  const double cell_area = geo.cell_m() * geo.cell_m();
  std::erase_if(res.objects, [&](const FurnitureObject& o) {
    if (o.kind != ObjectKind::kFurniture && o.kind != ObjectKind::kHanging) return false;
    if (static_cast<double>(o.surface_cells) * cell_area >= params.min_seen_area_m2 ||
        2 * o.surface_cells >= o.seen_cells)
      return false;
    for (int r = o.min_cell.row; r <= o.max_cell.row; ++r)
      for (int c = o.min_cell.col; c <= o.max_cell.col; ++c)
        if (res.labels.at(c, r) == o.id) res.labels.at(c, r) = 0;
    res.left_over_cells += o.cells;
    res.left_over_area_m2 += static_cast<double>(o.cells) * cell_area;
    ++res.left_over_pieces;
    return true;
  });
}

}  // namespace indoormap::objects
