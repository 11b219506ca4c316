#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <opencv2/imgproc.hpp>
#include <queue>

#include "objects_internal.hpp"

namespace indoormap::objects::detail {

namespace {

// A top surface this close below the scanner is seen at so grazing an angle that its samples
// leave gaps: no data there is no evidence of an empty cell.
constexpr double kMinDropBelowScanner_m = 0.1;

}  // namespace

// The occupied run of a voxel column starting above the floor: the first occupied layer at
// least two layers above the floor layer (the floor smears into the next one), then upward
// while empty gaps stay within max_gap layers.
Column column_extent(const cloud::VoxelGrid& g, int col, int row, std::int64_t floor_layer,
                     std::int64_t top_layer, std::int64_t max_gap) {
  Column c;
  for (std::int64_t z = std::max<std::int64_t>(0, floor_layer + 2);
       z <= std::min(top_layer, g.nz - 1); ++z) {
    if (!g.count(col, row, z)) {
      if (c.bottom >= 0 && z - c.top > max_gap) break;
      continue;
    }
    if (c.bottom < 0) c.bottom = z;
    c.top = z;
    c.points += g.count(col, row, z);
  }
  return c;
}

// True when layer z (one layer either way) is occupied over a free cell of the layout within
// kOverFreeReachM of (col, row).
bool level_over_free(const Grid<Cell>& layout, const cloud::VoxelGrid& g, int col, int row,
                     std::int64_t z) {
  constexpr double kOverFreeReachM = 0.5;
  const int reach = static_cast<int>(std::ceil(kOverFreeReachM / g.cell_m));
  for (int r = row - reach; r <= row + reach; ++r)
    for (int c = col - reach; c <= col + reach; ++c) {
      if (!layout.contains(c, r) || layout.at(c, r) != Cell::kFree) continue;
      for (std::int64_t k = std::max<std::int64_t>(z - 1, 0); k <= std::min(z + 1, g.nz - 1); ++k)
        if (g.count(c, r, k)) return true;
    }
  return false;
}

bool floor_seen(const cloud::VoxelGrid& g, int col, int row, std::int64_t floor_layer) {
  for (std::int64_t z = std::max<std::int64_t>(0, floor_layer - 1);
       z <= std::min(floor_layer + 1, g.nz - 1); ++z)
    if (g.count(col, row, z)) return true;
  return false;
}

// True when the straight line from the scanner to `target` (map frame) crosses no occupied voxel,
// leaving out the last `skip_end_m` (horizontally) before the target: the target's own column and
// its neighbours hold the surface the line ends on.
bool line_of_sight(const cloud::VoxelGrid& g, const Eigen::Vector3d& scanner,
                   const Eigen::Vector3d& target, double skip_end_m) {
  const Eigen::Vector3d d = target - scanner;
  const double horiz = d.head<2>().norm();
  if (horiz <= skip_end_m) return true;
  const double step = 0.5 * g.cell_m;
  const auto n = static_cast<std::int64_t>(std::ceil((horiz - skip_end_m) / (step)));
  for (std::int64_t i = 0; i <= n; ++i) {
    const double t = std::min(1.0, i * step / horiz);
    const Eigen::Vector3d p = scanner + t * d;
    const VoxelIndex v = g.voxel_of(p);
    if (!g.contains(v)) continue;
    if (g.count(v.ix, v.iy, v.iz)) return false;
  }
  return true;
}

bool return_beyond(const cloud::VoxelGrid& g, const Eigen::Vector3d& scanner,
                   const Eigen::Vector3d& target, double max_m) {
  const Eigen::Vector3d d = (target - scanner).normalized();
  const double step = 0.5 * g.cell_m;
  for (double t = step; t <= max_m; t += step) {
    const VoxelIndex v = g.voxel_of(target + t * d);
    if (!g.contains(v)) return false;
    if (g.count(v.ix, v.iy, v.iz)) return true;
  }
  return false;
}

bool lintel_above(const cloud::VoxelGrid& g, int col, int row, std::int64_t floor_layer,
                  std::int64_t ceiling_layer, std::int64_t min_gap, std::int64_t min_run) {
  std::int64_t last = floor_layer, run_start = -1;  // last occupied layer below the run
  for (std::int64_t z = std::max<std::int64_t>(0, floor_layer + 2); z < g.nz; ++z) {
    if (!g.count(col, row, z)) {
      if (run_start >= 0) {
        if (z - run_start >= min_run && z - 1 >= ceiling_layer - 2) return true;
        last = z - 1;
        run_start = -1;
      }
      continue;
    }
    if (run_start < 0) {
      if (z - last - 1 < min_gap) {  // no opening below: part of the run below
        last = z;
        continue;
      }
      run_start = z;
    }
  }
  return run_start >= 0 && g.nz - run_start >= min_run;  // up to the grid's top
}

bool surfaces_leave_several(const cloud::VoxelGrid& g, std::int64_t floor_layer) {
  if (floor_layer < 0 || floor_layer >= g.nz) return false;
  std::vector<std::uint16_t> counts;
  for (std::int64_t r = 0; r < g.ny; ++r)
    for (std::int64_t c = 0; c < g.nx; ++c)
      if (const std::uint16_t n = g.count(c, r, floor_layer)) counts.push_back(n);
  if (counts.empty()) return false;
  const auto mid = counts.begin() + static_cast<std::ptrdiff_t>(counts.size() / 2);
  std::nth_element(counts.begin(), mid, counts.end());
  return *mid >= kSurfaceMinFloorPoints;
}

ColumnScan scan_columns(const Grid<Cell>& layout, const cloud::VoxelGrid& voxels,
                        const cloud::LayerAnalysis& layers, const ObjectParams& params,
                        Grid<std::uint8_t>& mask, bool dense) {
  const std::int64_t floor_layer = layers.floor_layer, ceiling_layer = layers.ceiling_layer;
  const int w = layout.width, h = layout.height;
  const auto max_gap =
      static_cast<std::int64_t>(std::ceil(voxels.to_cells(params.max_vertical_gap_m)));
  ColumnScan s;
  s.cols = Grid<Column>(w, h);
  s.pocket = Grid<std::uint8_t>(w, h, 0);
  s.no_data = cv::Mat(h, w, CV_8U, cv::Scalar(1));
  if (dense) s.stray_max_points = kStrayMaxPointsDense;
  s.surface_test = dense && surfaces_leave_several(voxels, layers.floor_layer);
  Grid<Column>& cols = s.cols;
  Grid<std::uint8_t>& pocket = s.pocket;
  cv::Mat& no_data = s.no_data;
  bool& any_data = s.any_data;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (mask.at(c, r)) {
        // Below the ceiling (and the ceiling's own smear): a cell with only ceiling returns above
        // it has no height.
        cols.at(c, r) = column_extent(voxels, c, r, floor_layer, ceiling_layer - 2, max_gap);
        // A run that starts above the furniture band at a level that also lies over free floor
        // nearby is the ceiling of a room lower than the storey's (over a shelf's unseen body)
        // or a lamp: no height of the cell's own. A tall shelf's top lies over the shelf only.
        if (layers.furniture_band.hi_layer >= layers.furniture_band.lo_layer &&
            cols.at(c, r).bottom > layers.furniture_band.hi_layer &&
            level_over_free(layout, voxels, c, r, cols.at(c, r).bottom))
          cols.at(c, r) = Column{};
        bool wall_face = false;
        if (cols.at(c, r).top >= layers.wall_band.lo_layer)
          for (int dr = -kWallFaceCells; dr <= kWallFaceCells && !wall_face; ++dr)
            for (int dc = -kWallFaceCells; dc <= kWallFaceCells; ++dc)
              if (layout.contains(c + dc, r + dr) && layout.at(c + dc, r + dr) == Cell::kWall)
                wall_face = true;
        if (wall_face) cols.at(c, r) = Column{};
        if (!wall_face && cols.at(c, r).top < 0) {
          // The floor seen: nothing stands here (an enclosed pocket the scanner saw into).
          if (floor_seen(voxels, c, r, floor_layer)) {
            mask.at(c, r) = 0;
            continue;
          }
          pocket.at(c, r) = 1;
        }
        if (cols.at(c, r).top >= 0) {
          no_data.at<std::uint8_t>(r, c) = 0;
          any_data = true;
        }
      }
  return s;
}

namespace {

// For every cell, the nearest cell (L2) where no_data is 0; there must be one.
Grid<CellIndex> nearest_data(const cv::Mat& no_data) {
  cv::Mat dist, label;
  cv::distanceTransform(no_data, dist, label, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
  std::vector<CellIndex> seed_of(1, CellIndex{});  // label -> data cell
  for (int r = 0; r < no_data.rows; ++r)
    for (int c = 0; c < no_data.cols; ++c)
      if (!no_data.at<std::uint8_t>(r, c)) {
        const int lab = label.at<int>(r, c);
        if (static_cast<std::size_t>(lab) >= seed_of.size()) seed_of.resize(lab + 1);
        seed_of[lab] = {c, r};
      }
  Grid<CellIndex> out(no_data.cols, no_data.rows);
  for (int r = 0; r < no_data.rows; ++r)
    for (int c = 0; c < no_data.cols; ++c) out.at(c, r) = seed_of[label.at<int>(r, c)];
  return out;
}

// For every cell of the mask, the nearest data cell (no_data 0) reached through mask cells
// (8-neighbour steps of 1 and sqrt 2 cells); elsewhere, and where the mask's piece holds no data,
// the nearest in a straight line (nearest_data). A shelf's unseen body along a wall takes the
// top of its own seen face, not that of the cabinet behind the wall in the next room (a moving
// scanner about 1 m up sees a tall shelf as its front face only).
Grid<CellIndex> nearest_data_within(const cv::Mat& no_data, const Grid<std::uint8_t>& mask) {
  Grid<CellIndex> out = nearest_data(no_data);
  const int w = no_data.cols, h = no_data.rows;
  Grid<float> dist(w, h, std::numeric_limits<float>::infinity());
  using Item = std::pair<float, int>;  // distance, cell index
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (mask.at(c, r) && !no_data.at<std::uint8_t>(r, c)) {
        dist.at(c, r) = 0.0F;
        queue.push({0.0F, r * w + c});
      }
  while (!queue.empty()) {
    const auto [d, i] = queue.top();
    queue.pop();
    const int c = i % w, r = i / w;
    if (d > dist.at(c, r)) continue;
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        const int nc = c + dc, nr = r + dr;
        if ((!dc && !dr) || !mask.contains(nc, nr) || !mask.at(nc, nr)) continue;
        const float nd = d + ((dc && dr) ? static_cast<float>(M_SQRT2) : 1.0F);
        if (nd >= dist.at(nc, nr)) continue;
        dist.at(nc, nr) = nd;
        out.at(nc, nr) = out.at(c, r);
        queue.push({nd, nr * w + nc});
      }
  }
  return out;
}

// The target of a line-of-sight test over cell (c, r): just above the top layer `top`.
Eigen::Vector3d top_target(const GridGeometry& geo, const cloud::VoxelGrid& voxels, int c, int r,
                           std::int64_t top) {
  return {geo.origin_m().x() + (c + 0.5) * geo.cell_m(),
          geo.origin_m().y() + (r + 0.5) * geo.cell_m(),
          voxels.layer_bottom_m(top + 1) + 0.25 * voxels.cell_m};
}

// Some scanner's line to the target is clear and, continued, ends on a recorded return: had
// something stood at the target, that beam would have met it.
bool seen_by_a_scanner(const GridGeometry& geo, const cloud::VoxelGrid& voxels,
                       const std::vector<Eigen::Vector3d>& scanners_map,
                       const Eigen::Vector3d& target) {
  for (const auto& sc : scanners_map)
    if (target.z() < sc.z() - kMinDropBelowScanner_m &&
        line_of_sight(voxels, sc, target, 1.5 * geo.cell_m()) &&
        return_beyond(voxels, sc, target, kMaxBeyond_m))
      return true;
  return false;
}

// Stray returns (columns of at most stray_max_points points: ColumnScan) at least
// kStrayBelowTopLayers below the top of the nearest surface cell, where a scanner could have seen
// that top carried over: the ray that left them passed under the top's level, so the object does
// not reach them (a mixed pixel in the shadow behind a bin would otherwise join the shadow to the
// bin). They leave the mask and become cells without data.
constexpr std::int64_t kSampleBandLayers = 3;  // 0.15 m on 5 cm layers: one top, sampled
constexpr int kStrayReachCells = 4;            // 0.2 m on 5 cm cells: a bin's shadow up to the wall

void drop_stray_below_tops(const GridGeometry& geo, const cloud::VoxelGrid& voxels,
                           const Grid<Column>& cols, std::int64_t stray_max_points,
                           const std::vector<Eigen::Vector3d>& scanners_map, cv::Mat& no_data,
                           Grid<std::uint8_t>& mask) {
  const int w = mask.width, h = mask.height;
  cv::Mat no_surface = no_data.clone();
  bool any_stray = false, any_surface = false;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (mask.at(c, r) && cols.at(c, r).top >= 0) {
        const bool stray = cols.at(c, r).points <= stray_max_points;
        no_surface.at<std::uint8_t>(r, c) = stray ? 1 : 0;
        any_stray = any_stray || stray;
        any_surface = any_surface || !stray;
      }
  if (!any_stray || !any_surface || scanners_map.empty()) return;
  const Grid<CellIndex> surface = nearest_data(no_surface);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const Column& own = cols.at(c, r);
      if (!mask.at(c, r) || own.top < 0 || own.points > stray_max_points) continue;
      // The nearest surface's top, and the lowest surface top within kStrayReachCells: a stray
      // between a bin and the cabinet behind it is nearer to the cabinet, while its ray passed
      // over the bin.
      const std::int64_t nearest_top = cols.at(surface.at(c, r)).top;
      std::int64_t lowest_top = nearest_top;
      for (int dr = -kStrayReachCells; dr <= kStrayReachCells; ++dr)
        for (int dc = -kStrayReachCells; dc <= kStrayReachCells; ++dc)
          if (mask.contains(c + dc, r + dr) && mask.at(c + dc, r + dr) &&
              !no_surface.at<std::uint8_t>(r + dr, c + dc))
            lowest_top = std::min(lowest_top, cols.at(c + dc, r + dr).top);
      bool below_a_seen_top = false;
      for (const std::int64_t carried : {nearest_top, lowest_top})
        below_a_seen_top =
            below_a_seen_top ||
            (own.top <= carried - kStrayBelowTopLayers &&
             seen_by_a_scanner(geo, voxels, scanners_map, top_target(geo, voxels, c, r, carried)));
      if (!below_a_seen_top) continue;
      mask.at(c, r) = 0;
      no_data.at<std::uint8_t>(r, c) = 1;
    }
}

// Pocket cells in a gap of a few cells between data cells of about one height (tops in the
// nearest data cell's band of kSampleBandLayers layers or a neighbouring one): missed samples of
// one top (seen at a grazing angle), not evidence of an empty cell. A gap between a bin's top
// and a cabinet behind it is no such gap: the pocket rule decides there.
cv::Mat between_samples(const Grid<Column>& cols, const cv::Mat& no_data,
                        const Grid<CellIndex>& nearest, const Grid<std::uint8_t>& pocket,
                        const Grid<std::uint8_t>& mask) {
  const int w = no_data.cols, h = no_data.rows;
  auto band = [](std::int64_t top) { return top / kSampleBandLayers; };
  // Only the pocket cells of the mask are asked about: per band of their nearest data cell, the
  // box around them, wide enough (5 cells) for the closing there to be the whole grid's.
  std::map<std::int64_t, cv::Rect> bands;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (mask.at(c, r) && pocket.at(c, r))
        bands[band(cols.at(nearest.at(c, r)).top)] |= cv::Rect(c, r, 1, 1);
  cv::Mat out(h, w, CV_8U, cv::Scalar(0));
  const cv::Rect all(0, 0, w, h);
  for (const auto& [k, box] : bands) {
    const cv::Rect roi = cv::Rect(box.x - 5, box.y - 5, box.width + 10, box.height + 10) & all;
    cv::Mat data_k(roi.size(), CV_8U, cv::Scalar(0)), closed;
    for (int r = roi.y; r < roi.y + roi.height; ++r)
      for (int c = roi.x; c < roi.x + roi.width; ++c)
        if (!no_data.at<std::uint8_t>(r, c) && std::abs(band(cols.at(c, r).top) - k) <= 1)
          data_k.at<std::uint8_t>(r - roi.y, c - roi.x) = 1;
    cv::morphologyEx(data_k, closed, cv::MORPH_CLOSE,
                     cv::getStructuringElement(cv::MORPH_RECT, {3, 3}), {-1, -1}, 2);
    for (int r = box.y; r < box.y + box.height; ++r)
      for (int c = box.x; c < box.x + box.width; ++c)
        if (closed.at<std::uint8_t>(r - roi.y, c - roi.x) &&
            band(cols.at(nearest.at(c, r)).top) == k)
          out.at<std::uint8_t>(r, c) = 1;
  }
  return out;
}

// A moving scanner's cell without data takes the top of the nearest surface (a column of more
// points than a stray's) within this many cells before a stray return nearer it: its beams
// graze the wall above a cabinet in single returns (1.7-2 m), and the cabinet's unseen body
// along the wall took that height and the height split cut it off. 0.8 m: the deepest simulated
// cabinet is 0.6 m.
constexpr double kSurfaceReachCells = 16.0;

// The nearest surface cell of every cell, through the mask (nearest_data_within; col -1
// everywhere when there is none).
// `off_walls_only`: only the surface cells of ColumnScan::off_walls.
Grid<CellIndex> nearest_surface(const Grid<Column>& cols, const cv::Mat& no_data,
                                const ColumnScan& scan, const Grid<std::uint8_t>& mask,
                                bool off_walls_only) {
  cv::Mat no_surface = no_data.clone();
  bool any = false;
  for (int r = 0; r < no_data.rows; ++r)
    for (int c = 0; c < no_data.cols; ++c)
      if (!no_data.at<std::uint8_t>(r, c)) {
        const bool surface = cols.at(c, r).points > scan.stray_max_points &&
                             (!off_walls_only || scan.off_walls.at(c, r));
        no_surface.at<std::uint8_t>(r, c) = surface ? 0 : 1;
        any = any || surface;
      }
  if (!any) return Grid<CellIndex>(no_data.cols, no_data.rows, CellIndex{-1, -1});
  return nearest_data_within(no_surface, mask);
}

// The top a face carries over the cells it hides: that of surface cell s, or the median of the
// surface tops in its 3 x 3 neighbourhood when higher. A cell that a rotated face crosses at a
// corner holds fewer of its samples, and its top is lower: the body behind a shelf's front took
// 1.3 m from one such cell and 1.8 m from the next, and the height split cut it into strips that
// the wall-face rule then dropped. The median keeps a lone higher cell (a pillar's beside the
// shelf) from lifting it.
std::int64_t face_top(const Grid<Column>& cols, const cv::Mat& no_data, const ColumnScan& scan,
                      const Grid<std::uint8_t>& mask, CellIndex s) {
  std::array<std::int64_t, 9> tops{};
  std::size_t n = 0;
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc) {
      const int c = s.col + dc, r = s.row + dr;
      if (!mask.contains(c, r) || !mask.at(c, r) || no_data.at<std::uint8_t>(r, c)) continue;
      if (cols.at(c, r).points > scan.stray_max_points) tops[n++] = cols.at(c, r).top;
    }
  if (n == 0) return cols.at(s).top;
  std::nth_element(tops.begin(), tops.begin() + static_cast<std::ptrdiff_t>(n / 2),
                   tops.begin() + static_cast<std::ptrdiff_t>(n));
  return std::max(cols.at(s).top, tops[n / 2]);
}

}  // namespace

Grid<std::uint8_t> surfaces_off_walls(const Grid<Cell>& layout, const ColumnScan& scan,
                                      const Grid<std::uint8_t>& mask) {
  const int w = mask.width, h = mask.height;
  cv::Mat wall(h, w, CV_8U, cv::Scalar(0)), near_wall;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) wall.at<std::uint8_t>(r, c) = layout.at(c, r) == Cell::kWall;
  cv::dilate(
      wall, near_wall,
      cv::getStructuringElement(cv::MORPH_RECT, {2 * kWallFaceCells + 1, 2 * kWallFaceCells + 1}));
  Grid<std::uint8_t> out(w, h, 0);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      out.at(c, r) = mask.at(c, r) && scan.cols.at(c, r).points > scan.stray_max_points &&
                     !near_wall.at<std::uint8_t>(r, c);
  return out;
}

Grid<float> fill_tops(const GridGeometry& geo, const cloud::VoxelGrid& voxels,
                      const ColumnScan& scan, const std::vector<Eigen::Vector3d>& scanners_map,
                      Grid<std::uint8_t>& mask) {
  const int w = mask.width, h = mask.height;
  const Grid<Column>& cols = scan.cols;
  const Grid<std::uint8_t>& pocket = scan.pocket;
  cv::Mat no_data = scan.no_data.clone();
  drop_stray_below_tops(geo, voxels, cols, scan.stray_max_points, scanners_map, no_data, mask);
  const bool any_data = scan.any_data && cv::countNonZero(no_data == 0) > 0;
  Grid<float> top(w, h, kNoHeight);
  if (any_data) {
    // Along a path only: from fixed positions the straight-line nearest serves the objects
    // better (on the buildings' 3DTK rows the search through furniture joined the shelves on
    // both sides of a wall through a gap in it, and the rooms step dropped them as a wall).
    const Grid<CellIndex> nearest =
        scan.surface_first ? nearest_data_within(no_data, mask) : nearest_data(no_data);
    const cv::Mat near_data = between_samples(cols, no_data, nearest, pocket, mask);
    const Grid<CellIndex> surface =
        scan.surface_first ? nearest_surface(cols, no_data, scan, mask, false) : Grid<CellIndex>{};
    const Grid<CellIndex> off_walls = scan.surface_first && !scan.off_walls.data.empty()
                                          ? nearest_surface(cols, no_data, scan, mask, true)
                                          : Grid<CellIndex>{};
    auto within_reach = [](CellIndex q, int c, int r) {
      return q.col >= 0 && std::hypot(q.col - c, q.row - r) <= kSurfaceReachCells;
    };
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c)
        if (mask.at(c, r)) {
          CellIndex s = nearest.at(c, r);
          std::int64_t t = cols.at(s).top;
          if (!surface.data.empty() && no_data.at<std::uint8_t>(r, c)) {
            if (!off_walls.data.empty() && within_reach(off_walls.at(c, r), c, r))
              s = off_walls.at(c, r);
            else if (within_reach(surface.at(c, r), c, r))
              s = surface.at(c, r);
            t = face_top(cols, no_data, scan, mask, s);
          }
          top.at(c, r) = static_cast<float>(voxels.layer_center_m(t));
          // A pocket cell (no data, floor unseen) is the hidden part of the object next to it
          // only if that object's top surface, carried over the cell, would be hidden too. A
          // scanner that could see it there and saw nothing proves the object ends before it:
          // the shadow behind a bin, fenced in by other obstacles, is not part of the bin (where
          // a beam passed: seen_by_a_scanner).
          if (!pocket.at(c, r) || near_data.at<std::uint8_t>(r, c)) continue;
          if (seen_by_a_scanner(geo, voxels, scanners_map, top_target(geo, voxels, c, r, t))) {
            mask.at(c, r) = 0;
            top.at(c, r) = kNoHeight;
          }
        }
  }
  return top;
}

}  // namespace indoormap::objects::detail
