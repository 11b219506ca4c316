#include "indoormap/objects/objects.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "indoormap/core/errors.hpp"

namespace indoormap::objects {

namespace {

constexpr float kNoHeight = std::numeric_limits<float>::quiet_NaN();
// Cells this close to a wall cell whose column reaches the wall band hold the wall's face (the
// wall class comes from the wall band and may sit a cell or two off the lower face).
constexpr int kWallFaceCells = 3;
// A top surface this close below the scanner is seen at so grazing an angle that its samples
// leave gaps: no data there is no evidence of an empty cell.
constexpr double kMinDropBelowScanner_m = 0.1;
// A wall component with more unknown cells than this share of the cells around it is a piece of
// the room's outer wall, not a pillar standing in the room.
constexpr double kPillarMaxUnknownShare = 0.25;
// A pillar's seen face is round when the circle fitted to its cell centres stays this close to
// them (in cells). The corner of a square pillar leaves as little (0.49 cells for two faces of 8
// cells), so flat faces are recognised first (kPillarFlatShare).
constexpr double kPillarCircleMaxRmsCells = 0.5;
// A pillar's seen face is flat (one or two faces of a square pillar) when this share of its cells
// lies within a cell of its minimum-area rectangle's border; half a ring has about half there.
constexpr double kPillarFlatShare = 0.85;
// A lamp hangs: at least this much empty space below its lowest point in every one of its columns.
constexpr double kLampMinClearance_m = 0.2;
// Wall components smaller than this (cells) are a lamp's cords, not walls.
constexpr int kLampCordMaxCells = 5;

struct Column {
  std::int64_t bottom = -1, top = -1;  // layers; -1: nothing above the floor
};

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
  }
  return c;
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

OrientedBox min_area_box(const std::vector<Eigen::Vector2d>& pts) {
  OrientedBox b;
  if (pts.empty()) return b;
  std::vector<cv::Point2f> cv_pts;
  for (const auto& p : pts)
    cv_pts.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
  const cv::RotatedRect rr = cv::minAreaRect(cv_pts);
  cv::Point2f corner[4];
  rr.points(corner);
  const Eigen::Vector2d e1(corner[1].x - corner[0].x, corner[1].y - corner[0].y);
  const Eigen::Vector2d e2(corner[2].x - corner[1].x, corner[2].y - corner[1].y);
  const Eigen::Vector2d& along = e1.norm() >= e2.norm() ? e1 : e2;
  b.center_m = {rr.center.x, rr.center.y};
  b.length_m = std::max(e1.norm(), e2.norm());
  b.width_m = std::min(e1.norm(), e2.norm());
  double a = std::atan2(along.y(), along.x()) * 180.0 / M_PI;
  while (a < 0) a += 180.0;
  while (a >= 180.0) a -= 180.0;
  b.angle_deg = a;
  return b;
}

// The four corners of a cell (map metres), for minimum-area rectangles of cell sets.
void add_cell_corners(const GridGeometry& geo, CellIndex c, std::vector<Eigen::Vector2d>& out) {
  for (const auto& d : {Eigen::Vector2d(-0.5, -0.5), Eigen::Vector2d(0.5, -0.5),
                        Eigen::Vector2d(0.5, 0.5), Eigen::Vector2d(-0.5, 0.5)})
    out.push_back(geo.center_of(c) + d * geo.cell_m());
}

// The box's axes: along its length, and across.
std::pair<Eigen::Vector2d, Eigen::Vector2d> box_axes(const OrientedBox& b) {
  const Eigen::Vector2d u(std::cos(b.angle_deg * M_PI / 180), std::sin(b.angle_deg * M_PI / 180));
  return {u, Eigen::Vector2d(-u.y(), u.x())};
}

// The box as a counter-clockwise polygon.
std::vector<Eigen::Vector2d> box_polygon(const OrientedBox& b) {
  const auto [u, v] = box_axes(b);
  std::vector<Eigen::Vector2d> poly;
  for (const auto& [su, sv] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
    poly.push_back(b.center_m + su * 0.5 * b.length_m * u + sv * 0.5 * b.width_m * v);
  return poly;
}

// Twice the signed area (counter-clockwise positive).
double signed_area2(const std::vector<Eigen::Vector2d>& poly) {
  double a2 = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    a2 += a.x() * b.y() - b.x() * a.y();
  }
  return a2;
}

// Outline of the cells of one label, traced on a 4x upsampled mask eroded by one pixel: it runs
// 1/8 cell outside the centres of the boundary cells. A boundary cell holds the object's surface
// somewhere inside it, so its centre is the unbiased estimate; the cell edges would make every
// object half a cell too large on each side (a 0.36 m bin 30 % too large in area). A label that
// the erosion splits (cells joined only at a corner) is traced along its cell edges instead.
std::vector<Eigen::Vector2d> outline(const Grid<std::int32_t>& labels, int id, CellIndex lo,
                                     CellIndex hi, const GridGeometry& geo) {
  constexpr int kUp = 4;
  const int bw = hi.col - lo.col + 3, bh = hi.row - lo.row + 3;  // one empty cell around
  cv::Mat m(bh, bw, CV_8U, cv::Scalar(0));
  for (int r = lo.row; r <= hi.row; ++r)
    for (int c = lo.col; c <= hi.col; ++c)
      if (labels.at(c, r) == id) m.at<std::uint8_t>(r - lo.row + 1, c - lo.col + 1) = 255;
  cv::Mat up, inner;
  cv::resize(m, up, {}, kUp, kUp, cv::INTER_NEAREST);
  cv::erode(up, inner, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(inner, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  if (contours.size() != 1) {
    contours.clear();
    cv::findContours(up, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  }
  if (contours.empty()) return {};
  const auto& best = *std::max_element(
      contours.begin(), contours.end(),
      [](const auto& a, const auto& b) { return cv::contourArea(a) < cv::contourArea(b); });
  std::vector<Eigen::Vector2d> poly;
  for (const auto& p : best) {
    const double col = lo.col - 1 + (p.x + 0.5) / kUp, row = lo.row - 1 + (p.y + 0.5) / kUp;
    poly.emplace_back(geo.origin_m().x() + col * geo.cell_m(),
                      geo.origin_m().y() + row * geo.cell_m());
  }
  if (signed_area2(poly) < 0) std::reverse(poly.begin(), poly.end());
  return poly;
}

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

struct Circle {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double radius = 0.0, rms = 0.0;
};

// Algebraic (Kasa) circle fit: x^2 + y^2 + D x + E y + F = 0 in least squares.
std::optional<Circle> fit_circle(const std::vector<Eigen::Vector2d>& pts) {
  if (pts.size() < 5) return std::nullopt;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  for (const auto& q : pts) {
    const Eigen::Vector2d p = q - mean;  // centred for conditioning
    const Eigen::Vector3d row(p.x(), p.y(), 1.0);
    ata += row * row.transpose();
    atb -= row * p.squaredNorm();
  }
  const Eigen::Vector3d x = ata.ldlt().solve(atb);
  if (!x.allFinite()) return std::nullopt;
  Circle c;
  c.center = mean + Eigen::Vector2d(-x[0] / 2, -x[1] / 2);
  const double r2 = x[0] * x[0] / 4 + x[1] * x[1] / 4 - x[2];
  if (!(r2 > 0)) return std::nullopt;
  c.radius = std::sqrt(r2);
  double ss = 0.0;
  for (const auto& p : pts) ss += std::pow((p - c.center).norm() - c.radius, 2);
  c.rms = std::sqrt(ss / static_cast<double>(pts.size()));
  return c;
}

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
    // A pillar goes up to the ceiling: most of its columns hold points at the top of the wall
    // band. The front of a tall shelf that reaches into the band in a low room ends below it.
    std::size_t reach_top = 0;
    const std::int64_t top_hi = std::min(layers.wall_band.hi_layer, voxels.nz - 1);
    for (const auto& c : cells)
      for (std::int64_t z = std::max<std::int64_t>(0, top_hi - 2); z <= top_hi; ++z)
        if (voxels.count(c.col, c.row, z)) {
          ++reach_top;
          break;
        }
    if (2 * reach_top < cells.size()) continue;

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
    std::size_t on_border = 0;
    for (const auto& p : centres) {
      const Eigen::Vector2d q = p - rect.center_m;
      const double to_border = std::min(0.5 * rect.length_m - std::abs(q.dot(ru)),
                                        0.5 * rect.width_m - std::abs(q.dot(rv)));
      on_border += to_border <= cell;
    }
    const bool flat =
        static_cast<double>(on_border) >= kPillarFlatShare * static_cast<double>(centres.size());
    const auto circle = flat ? std::nullopt : fit_circle(centres);
    const double extent = std::max(bw, bh) * cell;
    if (circle && circle->rms <= kPillarCircleMaxRmsCells * cell && circle->radius >= cell &&
        circle->radius <= extent) {
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

// Lamps and other ceiling fixtures: points hanging above the furniture band and below the
// ceiling, over the room (known cells more than kWallFaceCells from a wall), with empty space
// between them and what stands below. The wall band's projection leaves them out (thin slabs, not
// walls) and the furniture band ends below them, so no other class holds them. Their cells may lie
// over a table's: they are listed with their own cell list, not in `labels`.
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
  // Walls, without the specks a lamp's cords make: a cord runs up through the wall band and is a
  // wall cell or two in the layout, inside the lamp.
  cv::Mat wall(h, w, CV_8U, cv::Scalar(0));
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) wall.at<std::uint8_t>(r, c) = layout.at(c, r) == Cell::kWall;
  {
    cv::Mat wl, ws, wc;
    const int nw = cv::connectedComponentsWithStats(wall, wl, ws, wc, 8, CV_32S);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c)
        if (const int lab = wl.at<int>(r, c);
            lab && lab < nw && ws.at<int>(lab, cv::CC_STAT_AREA) < kLampCordMaxCells)
          wall.at<std::uint8_t>(r, c) = 0;
  }
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
  // A lamp's underside is flat: its columns start at about one height. Columns that start
  // higher beside it hold the mixed pixels between its edge and the ceiling; they go.
  {
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

}  // namespace

ObjectsResult extract_objects(const Grid<Cell>& layout, const GridGeometry& geo,
                              const cloud::VoxelGrid& voxels, const cloud::LayerAnalysis& layers,
                              const ObjectParams& params,
                              const std::vector<Eigen::Vector3d>& scanners_map) {
  validate(params);
  const std::int64_t floor_layer = layers.floor_layer, ceiling_layer = layers.ceiling_layer;
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
  const auto max_gap =
      static_cast<std::int64_t>(std::ceil(voxels.to_cells(params.max_vertical_gap_m)));
  Grid<Column> cols(w, h);
  Grid<std::uint8_t> pocket(w, h, 0);  // furniture cells without data, floor unseen
  cv::Mat no_data(h, w, CV_8U, cv::Scalar(1));
  bool any_data = false;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (mask.at(c, r)) {
        // Below the ceiling (and the ceiling's own smear): a cell with only ceiling returns above
        // it has no height.
        cols.at(c, r) = column_extent(voxels, c, r, floor_layer, ceiling_layer - 2, max_gap);
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
  Grid<float> top(w, h, kNoHeight);
  if (any_data) {
    cv::Mat dist, nearest;
    cv::distanceTransform(no_data, dist, nearest, cv::DIST_L2, cv::DIST_MASK_5,
                          cv::DIST_LABEL_PIXEL);
    std::vector<CellIndex> seed_of(1, CellIndex{});  // label -> data cell
    // Gaps of a few cells between data cells are missed samples (a top seen at a grazing angle),
    // not evidence of an empty cell.
    cv::Mat near_data;
    cv::morphologyEx(no_data == 0, near_data, cv::MORPH_CLOSE,
                     cv::getStructuringElement(cv::MORPH_RECT, {3, 3}), {-1, -1}, 2);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c)
        if (!no_data.at<std::uint8_t>(r, c)) {
          const int lab = nearest.at<int>(r, c);
          if (static_cast<std::size_t>(lab) >= seed_of.size()) seed_of.resize(lab + 1);
          seed_of[lab] = {c, r};
        }
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c)
        if (mask.at(c, r)) {
          const CellIndex s = seed_of[nearest.at<int>(r, c)];
          top.at(c, r) = static_cast<float>(voxels.layer_center_m(cols.at(s).top));
          // A pocket cell (no data, floor unseen) is the hidden part of the object next to it
          // only if that object's top surface, carried over the cell, would be hidden too. A
          // scanner that could see it there and saw nothing proves the object ends before it:
          // the shadow behind a bin, fenced in by other obstacles, is not part of the bin.
          if (!pocket.at(c, r) || near_data.at<std::uint8_t>(r, c)) continue;
          const Eigen::Vector3d target(
              geo.origin_m().x() + (c + 0.5) * geo.cell_m(),
              geo.origin_m().y() + (r + 0.5) * geo.cell_m(),
              voxels.layer_bottom_m(cols.at(s).top + 1) + 0.25 * voxels.cell_m);
          for (const auto& sc : scanners_map)
            if (target.z() < sc.z() - kMinDropBelowScanner_m &&
                line_of_sight(voxels, sc, target, 1.5 * geo.cell_m())) {
              mask.at(c, r) = 0;
              top.at(c, r) = kNoHeight;
              break;
            }
        }
  }

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

  struct Acc {
    std::int64_t cells = 0;
    CellIndex start{-1, -1}, lo{std::numeric_limits<int>::max(), std::numeric_limits<int>::max()},
        hi{-1, -1};
    std::int64_t bottom = std::numeric_limits<std::int64_t>::max(), top = -1;
    bool touches_wall = false;
    std::vector<std::int64_t> tops;  // per cell with data
  };
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
      }
      for (int dr = -1; dr <= 1 && !a.touches_wall; ++dr)
        for (int dc = -1; dc <= 1; ++dc)
          if (layout.contains(c + dc, r + dr) && layout.at(c + dc, r + dr) == Cell::kWall) {
            a.touches_wall = true;
            break;
          }
    }

  const double cell_area = geo.cell_m() * geo.cell_m();
  std::vector<int> new_id(acc.size(), 0);
  for (int id = 1; id <= lab.count; ++id) {
    const Acc& a = acc[id];
    if (a.cells * cell_area < params.min_area_m2) continue;
    FurnitureObject o;
    o.id = static_cast<int>(res.objects.size()) + 1;
    new_id[id] = o.id;
    o.cells = a.cells;
    o.start_cell = a.start;
    o.min_cell = a.lo;
    o.max_cell = a.hi;
    o.min_m = geo.origin_m() + Eigen::Vector2d(a.lo.col, a.lo.row) * geo.cell_m();
    o.max_m = geo.origin_m() + Eigen::Vector2d(a.hi.col + 1, a.hi.row + 1) * geo.cell_m();
    o.area_m2 = a.cells * cell_area;
    o.touches_wall = a.touches_wall;
    if (a.top >= 0) {
      o.has_height = true;
      o.on_floor = a.bottom <= floor_layer + 2;
      o.z_min_m = o.on_floor ? voxels.layer_center_m(floor_layer) : voxels.layer_bottom_m(a.bottom);
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
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) res.labels.at(c, r) = new_id[lab.labels.at(c, r)];

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
  if (params.pillar_max_extent_m > 0) add_pillars(layout, geo, voxels, layers, params, res);
  if (params.lamp_max_extent_m > 0) add_lamps(layout, geo, voxels, layers, params, res);
  return res;
}

std::vector<std::vector<std::size_t>> crop_indices(const ObjectsResult& result,
                                                   const GridGeometry& geo,
                                                   const std::vector<Eigen::Vector3f>& points_map,
                                                   double crop_margin_m) {
  const int w = geo.width(), h = geo.height();
  const std::size_t n_obj = result.objects.size();
  std::vector<std::vector<std::size_t>> out(n_obj);
  if (n_obj == 0 || w == 0 || h == 0) return out;
  const int dil = std::max(0, static_cast<int>(std::ceil(crop_margin_m / geo.cell_m() - 1e-9)));

  // Cell -> objects whose dilated footprint covers it, as a compressed list (CSR).
  std::vector<std::pair<std::int64_t, int>> covered;  // (cell index, object index)
  Grid<std::int32_t> last(w, h, -1);
  for (std::size_t k = 0; k < n_obj; ++k) {
    const auto& o = result.objects[k];
    std::vector<CellIndex> cells = o.own_cells;
    if (cells.empty())
      for (int r = o.min_cell.row; r <= o.max_cell.row; ++r)
        for (int c = o.min_cell.col; c <= o.max_cell.col; ++c)
          if (result.labels.at(c, r) == o.id) cells.push_back({c, r});
    for (const auto& [c, r] : cells)
      for (int rr = std::max(0, r - dil); rr <= std::min(h - 1, r + dil); ++rr)
        for (int cc = std::max(0, c - dil); cc <= std::min(w - 1, c + dil); ++cc)
          if (last.at(cc, rr) != static_cast<std::int32_t>(k)) {
            last.at(cc, rr) = static_cast<std::int32_t>(k);
            covered.emplace_back(static_cast<std::int64_t>(rr) * w + cc, static_cast<int>(k));
          }
  }
  std::sort(covered.begin(), covered.end());
  std::vector<std::uint32_t> first(static_cast<std::size_t>(w) * h + 1, 0);
  for (const auto& [cell, k] : covered) ++first[static_cast<std::size_t>(cell) + 1];
  for (std::size_t i = 1; i < first.size(); ++i) first[i] += first[i - 1];

  std::vector<float> zlo(n_obj), zhi(n_obj);
  for (std::size_t k = 0; k < n_obj; ++k) {
    const auto& o = result.objects[k];
    zlo[k] = o.has_height ? static_cast<float>(o.z_min_m - crop_margin_m)
                          : -std::numeric_limits<float>::infinity();
    zhi[k] = o.has_height ? static_cast<float>(o.z_max_m + crop_margin_m)
                          : std::numeric_limits<float>::infinity();
  }
  for (std::size_t i = 0; i < points_map.size(); ++i) {
    const auto& p = points_map[i];
    if (!p.allFinite()) continue;
    const CellIndex c = geo.cell_of({p.x(), p.y()});
    if (!geo.contains(c)) continue;
    const auto cell = static_cast<std::size_t>(c.row) * w + c.col;
    for (std::uint32_t j = first[cell]; j < first[cell + 1]; ++j) {
      const int k = covered[j].second;
      if (p.z() >= zlo[k] && p.z() <= zhi[k]) out[k].push_back(i);
    }
  }
  return out;
}

}  // namespace indoormap::objects
