#include <algorithm>
#include <cmath>
#include <map>
#include <opencv2/imgproc.hpp>

#include "objects_internal.hpp"

namespace indoormap::objects::detail {

namespace {

// A wall component with more unknown cells than this share of the cells around it is a piece of
// the room's outer wall, not a pillar standing in the room.
constexpr double kPillarMaxUnknownShare = 0.25;
// A pillar's seen face is round when the circle fitted to its cell centres stays this close to
// them (in cells) and closer than the sides of its minimum-area rectangle do. The corner of a
// square pillar leaves 0.49 cells from a circle (two faces of 8 cells) and none from its
// rectangle; a third of a round pillar's ring, seen from one position, is thin: most of its cells
// touch its rectangle's border too, but its middle lies a cell or two inside the long side.
constexpr double kPillarCircleMaxRmsCells = 0.5;
// A lamp hangs: at least this much empty space below its lowest point in every one of its columns.
constexpr double kLampMinClearance_m = 0.2;
// Wall components smaller than this (cells) are a lamp's cords, not walls.
constexpr int kLampCordMaxCells = 5;

// Walls, without the specks a lamp's cords make: a cord runs up through the wall band and is a
// wall cell or two in the layout, inside the lamp.
cv::Mat walls_without_cords(const Grid<Cell>& layout) {
  const int w = layout.width, h = layout.height;
  cv::Mat wall(h, w, CV_8U, cv::Scalar(0));
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) wall.at<std::uint8_t>(r, c) = layout.at(c, r) == Cell::kWall;
  cv::Mat wl, ws, wc;
  const int nw = cv::connectedComponentsWithStats(wall, wl, ws, wc, 8, CV_32S);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (const int lab = wl.at<int>(r, c);
          lab && lab < nw && ws.at<int>(lab, cv::CC_STAT_AREA) < kLampCordMaxCells)
        wall.at<std::uint8_t>(r, c) = 0;
  return wall;
}

// A lamp's underside is flat: its columns start at about one height. Columns that start
// higher beside it hold the mixed pixels between its edge and the ceiling; they go.
void drop_raised_columns(const Grid<std::int32_t>& bottom, cv::Mat& mask) {
  const int w = bottom.width, h = bottom.height;
  cv::Mat labels;
  const int n = cv::connectedComponents(mask, labels, 8, CV_32S);
  std::vector<std::map<std::int32_t, int>> bottoms(static_cast<std::size_t>(n));
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (const int lab = labels.at<int>(r, c)) ++bottoms[lab][bottom.at(c, r)];
  std::vector<std::int32_t> mode(static_cast<std::size_t>(n), 0);
  for (int lab = 1; lab < n; ++lab)
    mode[lab] = std::max_element(bottoms[lab].begin(), bottoms[lab].end(),
                                 [](const auto& a, const auto& b) { return a.second < b.second; })
                    ->first;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (const int lab = labels.at<int>(r, c); lab && std::abs(bottom.at(c, r) - mode[lab]) > 1)
        mask.at<std::uint8_t>(r, c) = 0;
}

// A pillar goes up to the ceiling: most of its columns hold points at the top of the wall band
// (the front of a tall shelf that reaches into the band in a low room ends below it). And it
// stands on the floor: most of its columns hold points in the furniture band too (above a desk
// in front of it, at least); a lamp hanging in the wall band, under the ceiling's smear, has
// nothing there.
bool floor_to_ceiling(const std::vector<CellIndex>& cells, const cloud::VoxelGrid& voxels,
                      const cloud::LayerAnalysis& layers) {
  auto columns_with_points = [&](std::int64_t z0, std::int64_t z1) {
    std::size_t n = 0;
    for (const auto& c : cells)
      for (std::int64_t z = std::max<std::int64_t>(0, z0); z <= std::min(z1, voxels.nz - 1); ++z)
        if (voxels.count(c.col, c.row, z)) {
          ++n;
          break;
        }
    return n;
  };
  const std::int64_t top_hi = std::min(layers.wall_band.hi_layer, voxels.nz - 1);
  if (2 * columns_with_points(top_hi - 2, top_hi) < cells.size()) return false;
  const std::int64_t band_lo = std::max<std::int64_t>(layers.furniture_band.lo_layer, 0),
                     band_hi = std::min(layers.furniture_band.hi_layer, voxels.nz - 1);
  return band_hi < band_lo || 2 * columns_with_points(band_lo, band_hi) >= cells.size();
}

}  // namespace

// Pillars and columns: wall-class components that stand free in the room (few unknown cells
// around them) and are small. They reach the wall band, so the paper's layout makes them wall, and
// a scanner sees only their front: the footprint is the circle fitted to the seen face when it
// fits (a round pillar), else the minimum-area rectangle of the seen cells.
void add_pillars(const Grid<Cell>& layout, const GridGeometry& geo, const cloud::VoxelGrid& voxels,
                 const cloud::LayerAnalysis& layers, const ObjectParams& params,
                 ObjectsResult& res) {
  const int w = layout.width, h = layout.height;
  cv::Mat wall(h, w, CV_8U, cv::Scalar(0));
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (layout.at(c, r) == Cell::kWall) wall.at<std::uint8_t>(r, c) = 1;
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(wall, labels, stats, centroids, 8, CV_32S);
  const double cell = geo.cell_m();
  for (int lab = 1; lab < n; ++lab) {
    const int x0 = stats.at<int>(lab, cv::CC_STAT_LEFT), y0 = stats.at<int>(lab, cv::CC_STAT_TOP);
    const int bw = stats.at<int>(lab, cv::CC_STAT_WIDTH),
              bh = stats.at<int>(lab, cv::CC_STAT_HEIGHT);
    if (std::max(bw, bh) * cell > params.pillar_max_extent_m) continue;
    if (x0 == 0 || y0 == 0 || x0 + bw == w || y0 + bh == h) continue;
    // The ring of cells around the component: a piece of the outer wall (between a door and a
    // corner) has the unknown outside along one side; a pillar has the room all around.
    std::int64_t ring = 0, unknown = 0;
    std::vector<CellIndex> cells;
    for (int r = y0 - 1; r <= y0 + bh; ++r)
      for (int c = x0 - 1; c <= x0 + bw; ++c) {
        if (labels.at<int>(r, c) == lab) {
          cells.push_back({c, r});
          continue;
        }
        bool next_to = false;
        for (int dr = -1; dr <= 1 && !next_to; ++dr)
          for (int dc = -1; dc <= 1 && !next_to; ++dc)
            next_to = layout.contains(c + dc, r + dr) && labels.at<int>(r + dr, c + dc) == lab;
        if (!next_to) continue;
        ++ring;
        unknown += layout.at(c, r) == Cell::kUnknown;
      }
    if (ring == 0 || unknown > kPillarMaxUnknownShare * static_cast<double>(ring)) continue;
    if (static_cast<double>(cells.size()) * cell * cell < params.min_area_m2) continue;
    if (!floor_to_ceiling(cells, voxels, layers)) continue;

    FurnitureObject o;
    o.id = static_cast<int>(res.objects.size()) + 1;
    o.kind = ObjectKind::kPillar;
    o.cells = static_cast<std::int64_t>(cells.size());
    o.start_cell = cells.front();
    o.min_cell = {x0, y0};
    o.max_cell = {x0 + bw - 1, y0 + bh - 1};
    std::vector<Eigen::Vector2d> centres, corners;
    for (const auto& c : cells) {
      centres.push_back(geo.center_of(c));
      add_cell_corners(geo, c, corners);
    }
    const OrientedBox rect = min_area_box(corners);
    const auto [ru, rv] = box_axes(rect);
    // RMS distance of the cell centres to the nearest side of the rectangle (centres lie half a
    // cell inside it).
    double ss_rect = 0.0;
    for (const auto& p : centres) {
      const Eigen::Vector2d q = p - rect.center_m;
      const double to_border = std::min(0.5 * rect.length_m - std::abs(q.dot(ru)),
                                        0.5 * rect.width_m - std::abs(q.dot(rv)));
      ss_rect += std::pow(std::max(0.0, to_border - 0.5 * cell), 2);
    }
    const double rect_rms = std::sqrt(ss_rect / static_cast<double>(centres.size()));
    const auto circle = fit_circle(centres);
    const double extent = std::max(bw, bh) * cell;
    if (circle && circle->rms <= kPillarCircleMaxRmsCells * cell && circle->rms < rect_rms &&
        circle->radius >= cell && circle->radius <= extent) {
      // The fit runs through the centres of the face cells: the surface lies inside them.
      const double radius = circle->radius;
      constexpr int kVertices = 32;
      for (int k = 0; k < kVertices; ++k) {
        const double a = 2.0 * M_PI * k / kVertices;
        o.footprint_m.push_back(circle->center +
                                radius * Eigen::Vector2d(std::cos(a), std::sin(a)));
      }
    } else {
      o.footprint_m = box_polygon(rect);
    }
    o.box = min_area_box(o.footprint_m);
    o.area_m2 = std::abs(signed_area2(o.footprint_m)) / 2;
    o.min_m = o.footprint_m.front();
    o.max_m = o.footprint_m.front();
    for (const auto& p : o.footprint_m) {
      o.min_m = o.min_m.cwiseMin(p);
      o.max_m = o.max_m.cwiseMax(p);
    }
    o.touches_wall = false;  // it is the wall class itself, standing free
    std::int64_t top = -1;
    for (const auto& c : cells) {
      res.labels.at(c) = o.id;
      for (std::int64_t z = std::max<std::int64_t>(0, layers.floor_layer + 1); z < voxels.nz; ++z)
        if (voxels.count(c.col, c.row, z)) {
          top = std::max(top, z);
          o.point_count += voxels.count(c.col, c.row, z);
        }
    }
    if (top >= 0) {
      o.has_height = true;
      o.on_floor = true;
      o.z_min_m = voxels.layer_center_m(layers.floor_layer);
      o.z_max_m = std::min(voxels.layer_center_m(top), layers.ceiling_z_m);
    }
    res.objects.push_back(std::move(o));
  }
}

void add_lamps(const Grid<Cell>& layout, const GridGeometry& geo, const cloud::VoxelGrid& voxels,
               const cloud::LayerAnalysis& layers, const ObjectParams& params, ObjectsResult& res) {
  const int w = layout.width, h = layout.height;
  if (layers.furniture_band.hi_layer < layers.furniture_band.lo_layer) return;  // no bands
  const std::int64_t z_lo = std::max<std::int64_t>(layers.furniture_band.hi_layer + 1, 0);
  // Below the ceiling and its smear. Under a sloped ceiling this is its lowest part: lamps
  // higher up are not found.
  const std::int64_t z_hi = std::min<std::int64_t>(layers.ceiling_layer - 2, voxels.nz - 1);
  if (z_hi < z_lo) return;
  const auto gap = static_cast<std::int64_t>(std::ceil(voxels.to_cells(kLampMinClearance_m)));
  cv::Mat wall = walls_without_cords(layout);
  Grid<std::int32_t> bottom(w, h, -1), top(w, h, -1);
  cv::Mat mask(h, w, CV_8U, cv::Scalar(0));
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      if (layout.at(c, r) == Cell::kUnknown || wall.at<std::uint8_t>(r, c)) continue;
      bool near_wall = false;
      for (int dr = -kWallFaceCells; dr <= kWallFaceCells && !near_wall; ++dr)
        for (int dc = -kWallFaceCells; dc <= kWallFaceCells && !near_wall; ++dc)
          near_wall = layout.contains(c + dc, r + dr) && wall.at<std::uint8_t>(r + dr, c + dc);
      if (near_wall) continue;
      std::int64_t lo = -1, hi = -1;
      for (std::int64_t z = z_lo; z <= z_hi; ++z)
        if (voxels.count(c, r, z)) {
          if (lo < 0) lo = z;
          hi = z;
        }
      if (lo < 0) continue;
      // Hanging: nothing in the `gap` layers below its lowest point (a tall wardrobe's top
      // continues from below).
      bool clear = true;
      for (std::int64_t zz = std::max<std::int64_t>(0, lo - gap); zz < lo && clear; ++zz)
        clear = voxels.count(c, r, zz) == 0;
      if (!clear) continue;
      mask.at<std::uint8_t>(r, c) = 1;
      bottom.at(c, r) = static_cast<std::int32_t>(lo);
      top.at(c, r) = static_cast<std::int32_t>(hi);
    }
  drop_raised_columns(bottom, mask);
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  const double cell = geo.cell_m();
  for (int lab = 1; lab < n; ++lab) {
    const int x0 = stats.at<int>(lab, cv::CC_STAT_LEFT), y0 = stats.at<int>(lab, cv::CC_STAT_TOP);
    const int bw = stats.at<int>(lab, cv::CC_STAT_WIDTH),
              bh = stats.at<int>(lab, cv::CC_STAT_HEIGHT);
    const int area = stats.at<int>(lab, cv::CC_STAT_AREA);
    if (area * cell * cell < params.min_area_m2) continue;
    if (std::max(bw, bh) * cell > params.lamp_max_extent_m) continue;
    FurnitureObject o;
    o.id = static_cast<int>(res.objects.size()) + 1;
    o.kind = ObjectKind::kLamp;
    o.cells = area;
    o.min_cell = {x0, y0};
    o.max_cell = {x0 + bw - 1, y0 + bh - 1};
    std::vector<Eigen::Vector2d> corners;
    std::int64_t lo = std::numeric_limits<std::int64_t>::max();
    std::map<std::int64_t, std::uint64_t> per_layer;  // points
    for (int r = y0; r < y0 + bh; ++r)
      for (int c = x0; c < x0 + bw; ++c) {
        if (labels.at<int>(r, c) != lab) continue;
        if (o.own_cells.empty()) o.start_cell = {c, r};
        o.own_cells.push_back({c, r});
        lo = std::min<std::int64_t>(lo, bottom.at(c, r));
        for (std::int64_t z = bottom.at(c, r); z <= top.at(c, r); ++z) {
          o.point_count += voxels.count(c, r, z);
          per_layer[z] += voxels.count(c, r, z);
        }
        add_cell_corners(geo, {c, r}, corners);
      }
    // The cells are where the lamp's underside was seen: its outline is their minimum-area
    // rectangle, drawn through the boundary cells' centres as for the furniture (a lamp 1.2 m
    // long covers 24 cells of 5 cm, not 25).
    OrientedBox b = min_area_box(corners);
    b.length_m = std::max(cell, b.length_m - cell);
    b.width_m = std::max(cell, b.width_m - cell);
    o.footprint_m = box_polygon(b);
    o.box = b;
    o.area_m2 = b.length_m * b.width_m;
    o.min_m = geo.origin_m() + Eigen::Vector2d(x0, y0) * cell;
    o.max_m = geo.origin_m() + Eigen::Vector2d(x0 + bw, y0 + bh) * cell;
    o.has_height = true;
    o.on_floor = false;
    // The top: where 95 % of its points lie below (the cords it hangs from hold few points).
    std::int64_t hi = lo;
    std::uint64_t below = 0;
    for (const auto& [z, k] : per_layer) {
      hi = z;
      below += k;
      if (static_cast<double>(below) >= 0.95 * static_cast<double>(o.point_count)) break;
    }
    o.z_min_m = voxels.layer_bottom_m(lo);
    o.z_max_m = voxels.layer_bottom_m(hi + 1);
    res.objects.push_back(std::move(o));
  }
}

}  // namespace indoormap::objects::detail
