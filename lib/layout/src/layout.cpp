#include "indoormap/layout/layout.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <sstream>

#include "indoormap/core/errors.hpp"
#include "inner_walls.hpp"

namespace indoormap::layout {

namespace {

cv::Mat as_mat(Grid<std::uint8_t>& g) {
  return cv::Mat(g.height, g.width, CV_8U, g.data.data());
}

constexpr int kDx4[4] = {1, -1, 0, 0};
constexpr int kDy4[4] = {0, 0, 1, -1};

// Nearest cell with mask != 0 within radius (breadth first, 4-connected), or nullopt.
std::optional<CellIndex> nearest_set(const Grid<std::uint8_t>& mask, CellIndex start, int radius) {
  if (!mask.contains(start.col, start.row)) return std::nullopt;
  if (mask.at(start)) return start;
  Grid<std::uint8_t> seen(mask.width, mask.height, 0);
  std::deque<CellIndex> q{start};
  seen.at(start) = 1;
  while (!q.empty()) {
    const CellIndex c = q.front();
    q.pop_front();
    for (int k = 0; k < 4; ++k) {
      const CellIndex n{c.col + kDx4[k], c.row + kDy4[k]};
      if (!mask.contains(n.col, n.row) || seen.at(n)) continue;
      if (std::abs(n.col - start.col) > radius || std::abs(n.row - start.row) > radius) continue;
      if (mask.at(n)) return n;
      seen.at(n) = 1;
      q.push_back(n);
    }
  }
  return std::nullopt;
}

std::string fmt_len(double m) {
  std::ostringstream s;
  s.precision(2);
  s << std::fixed << m << " m";
  return s.str();
}

std::string fmt_xy(const Eigen::Vector2d& p) {
  std::ostringstream s;
  s.precision(2);
  s << std::fixed << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

Grid<std::uint8_t> obstacles_of(const Grid<std::uint8_t>& walls,
                                const Grid<std::uint8_t>& furniture) {
  Grid<std::uint8_t> o(walls.width, walls.height, 0);
  for (std::size_t i = 0; i < o.size(); ++i) o.data[i] = walls.data[i] | furniture.data[i];
  return o;
}

// The cells of hanging wall-band components, and their descriptions. A candidate must lie inside
// the room: no cell within two cells of it may be outside `inside` (the passage area), so the
// wall above a window (nothing below it either) is not taken for a lamp.
Grid<std::uint8_t> hanging_mask(const Grid<std::uint8_t>& walls, const Grid<std::uint8_t>& support,
                                const Grid<std::uint8_t>& inside, double cell_m,
                                const LayoutParams& params, std::vector<HangingObject>* objects) {
  Grid<std::uint8_t> mask(walls.width, walls.height, 0);
  if (walls.width == 0 || walls.height == 0) return mask;
  // Candidates are the wall cells with no supported cell (see build_layout) within one cell: a
  // lamp that touches a wall in the band is separated from it, because the wall goes on below.
  Grid<std::uint8_t> wcopy(walls.width, walls.height, 0);
  for (int r = 0; r < walls.height; ++r)
    for (int c = 0; c < walls.width; ++c) {
      if (!walls.at(c, r)) continue;
      bool sup = false;
      for (int dr = -1; dr <= 1 && !sup; ++dr)
        for (int dc = -1; dc <= 1 && !sup; ++dc)
          sup = support.contains(c + dc, r + dr) && support.at(c + dc, r + dr);
      wcopy.at(c, r) = !sup;
    }
  cv::Mat labels, stats, centroids;
  const int n =
      cv::connectedComponentsWithStats(as_mat(wcopy), labels, stats, centroids, 8, CV_32S);
  std::vector<std::uint8_t> at_boundary(static_cast<std::size_t>(n), 0);
  for (int r = 0; r < walls.height; ++r)
    for (int c = 0; c < walls.width; ++c) {
      const int lab = labels.at<int>(r, c);
      if (lab == 0) continue;
      for (int dr = -2; dr <= 2 && !at_boundary[lab]; ++dr)
        for (int dc = -2; dc <= 2; ++dc)
          if (!inside.contains(c + dc, r + dr) || !inside.at(c + dc, r + dr)) {
            at_boundary[lab] = 1;
            break;
          }
    }
  const double cell_area = cell_m * cell_m;
  std::vector<std::uint8_t> is_hanging(static_cast<std::size_t>(n), 0);
  for (int lab = 1; lab < n; ++lab) {
    const std::int64_t area = stats.at<int>(lab, cv::CC_STAT_AREA);
    if (area * cell_area > params.hanging_max_area_m2 || at_boundary[lab]) continue;
    const int extent =
        std::max(stats.at<int>(lab, cv::CC_STAT_WIDTH), stats.at<int>(lab, cv::CC_STAT_HEIGHT));
    if (extent * cell_m > params.hanging_max_extent_m) continue;
    is_hanging[lab] = 1;
    HangingObject h;
    h.min_col = stats.at<int>(lab, cv::CC_STAT_LEFT);
    h.min_row = stats.at<int>(lab, cv::CC_STAT_TOP);
    h.max_col = h.min_col + stats.at<int>(lab, cv::CC_STAT_WIDTH) - 1;
    h.max_row = h.min_row + stats.at<int>(lab, cv::CC_STAT_HEIGHT) - 1;
    h.cells = area;
    if (objects) objects->push_back(h);
  }
  for (int r = 0; r < walls.height; ++r)
    for (int c = 0; c < walls.width; ++c) mask.at(c, r) = is_hanging[labels.at<int>(r, c)];
  return mask;
}

}  // namespace

Grid<std::uint8_t> passage_area(const Grid<std::uint8_t>& walls, int min_lines) {
  const int w = walls.width, h = walls.height;
  // Per line direction: an obstacle at or before the cell along the line, and at or after it.
  // Directions (dc, dr) with dr >= 0 and a predecessor (c - dc, r - dr) earlier in raster order.
  const int dirs[4][2] = {{1, 0}, {0, 1}, {1, 1}, {-1, 1}};
  const int n_dirs = min_lines <= 0 ? 2 : 4;
  const int need = min_lines <= 0 ? 2 : std::min(min_lines, 4);
  Grid<std::uint8_t> count(w, h, 0), before(w, h, 0), after(w, h, 0);
  for (int d = 0; d < n_dirs; ++d) {
    const int dc = dirs[d][0], dr = dirs[d][1];
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c)
        before.at(c, r) =
            walls.at(c, r) || (before.contains(c - dc, r - dr) && before.at(c - dc, r - dr));
    for (int r = h - 1; r >= 0; --r)
      for (int c = w - 1; c >= 0; --c)
        after.at(c, r) =
            walls.at(c, r) || (after.contains(c + dc, r + dr) && after.at(c + dc, r + dr));
    for (std::size_t i = 0; i < count.size(); ++i) count.data[i] += before.data[i] && after.data[i];
  }
  for (auto& v : count.data) v = v >= need;
  return count;
}

void validate(const LayoutParams& lo) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw UsageError("invalid parameter " + what);
  };
  require(lo.furniture_closing_iterations >= 0 && lo.furniture_closing_iterations <= 20,
          "layout.furniture_closing_iterations: must be in [0, 20]");
  require(lo.flood_barrier_closing >= 0 && lo.flood_barrier_closing <= 10,
          "layout.flood_barrier_closing: must be in [0, 10]");
  require(lo.enclosed_max_area_m2 >= 0, "layout.enclosed_max_area_m2: must be >= 0");
  require(lo.passage_min_lines >= 0 && lo.passage_min_lines <= 4,
          "layout.passage_min_lines: must be in [0, 4] (0: the paper's row and column passes)");
  require(lo.passage_bridge_m >= 0 && lo.passage_bridge_m <= 2,
          "layout.passage_bridge_m: must be in [0, 2]");
  require(lo.sparse_floor_fill >= 0 && lo.sparse_floor_fill <= 1.01,
          "layout.sparse_floor_fill: must be in [0, 1.01]");
  require(lo.seed_search_radius_m >= 0, "layout.seed_search_radius_m: must be >= 0");
  require(lo.hanging_max_area_m2 >= 0, "layout.hanging_max_area_m2: must be >= 0");
  require(lo.hanging_gap_m > 0, "layout.hanging_gap_m: must be > 0");
  require(lo.wall_max_thickness_m >= 0 && lo.wall_max_thickness_m <= 2,
          "layout.wall_max_thickness_m: must be in [0, 2]");
  require(lo.hidden_body_max_depth_m >= 0 && lo.hidden_body_max_depth_m <= 2,
          "layout.hidden_body_max_depth_m: must be in [0, 2]");
  require(lo.hanging_max_extent_m >= 0, "layout.hanging_max_extent_m: must be >= 0");
}

namespace {

// The obstacles with their gaps up to passage_bridge_m closed (for the passage test only).
Grid<std::uint8_t> bridged(Grid<std::uint8_t> obstacles, double cell_m, const LayoutParams& p) {
  const int k = 2 * static_cast<int>(std::lround(p.passage_bridge_m / cell_m / 2)) + 1;
  if (k < 3 || obstacles.width == 0 || obstacles.height == 0) return obstacles;
  const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, {k, k});
  // Closed on a copy padded with k empty cells: nothing grows into the edge of the grid (which
  // usually runs along the outer wall faces), nothing is eroded from outside.
  cv::Mat padded;
  cv::copyMakeBorder(as_mat(obstacles), padded, k, k, k, k, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::morphologyEx(padded, padded, cv::MORPH_CLOSE, square);
  padded(cv::Rect(k, k, obstacles.width, obstacles.height)).copyTo(as_mat(obstacles));
  return obstacles;
}

// The flood-fill seeds: the scanner positions, moved to the nearest passable cell when they fall on
// an object.
void place_seeds(Grid<std::uint8_t>& passable, const GridGeometry& geo,
                 const std::vector<Eigen::Vector2d>& scanners_map, const LayoutParams& params,
                 LayoutResult& r) {
  const int radius =
      std::max(1, static_cast<int>(std::ceil(params.seed_search_radius_m / geo.cell_m())));
  for (const auto& s : scanners_map) {
    const CellIndex c = geo.cell_of(s);
    if (!geo.contains(c)) {
      r.warnings.push_back("scanner at " + fmt_xy(s) + " lies outside the map; not used as a seed");
      continue;
    }
    if (auto n = nearest_set(passable, c, radius)) {
      r.seeds.push_back(*n);
    } else {
      r.warnings.push_back("no free cell within " + std::to_string(params.seed_search_radius_m) +
                           " m of the scanner at " + fmt_xy(s) + "; not used as a seed");
    }
  }
  if (r.seeds.empty()) {
    // No usable scanner: take the free cell farthest from every obstacle (the middle of the
    // largest open area), which is where a scanner most likely stood.
    cv::Mat dist;
    cv::distanceTransform(as_mat(passable), dist, cv::DIST_L2, cv::DIST_MASK_5);
    double max_v = 0.0;
    cv::Point max_p;
    cv::minMaxLoc(dist, nullptr, &max_v, nullptr, &max_p);
    if (max_v > 0.0) {
      r.seeds.push_back({max_p.x, max_p.y});
      r.seeds_estimated = true;
      r.warnings.push_back(
          "no scanner position known: estimated at " + fmt_xy(geo.center_of(r.seeds.back())) +
          " (the free cell farthest from obstacles); pass --scanner X,Y,Z to set it");
    } else {
      r.warnings.push_back("no free space inside the walls: the layout has no free class");
    }
  }
}

// With no scanner position: a seed in every 4-connected piece of the floodable cells that holds
// at least kSeenSeedMinAreaM2 of cells the scan shows free (observed floor): the rooms of a
// floor scanned by a mobile scanner without its trajectory. One seed alone flooded one room.
constexpr double kSeenSeedMinAreaM2 = 2.0;
void add_seen_seeds(Grid<std::uint8_t>& floodable, const Grid<std::uint8_t>& seen, double cell_m,
                    std::vector<CellIndex>& seeds) {
  cv::Mat lab;
  const int n = cv::connectedComponents(as_mat(floodable), lab, 4, CV_32S);
  std::vector<std::int64_t> count(static_cast<std::size_t>(n), 0);
  std::vector<CellIndex> first(static_cast<std::size_t>(n));
  for (int row = 0; row < floodable.height; ++row)
    for (int col = 0; col < floodable.width; ++col) {
      const int k = lab.at<int>(row, col);
      if (k > 0 && seen.at(col, row) && count[k]++ == 0) first[k] = {col, row};
    }
  const auto min_cells =
      static_cast<std::int64_t>(std::ceil(kSeenSeedMinAreaM2 / (cell_m * cell_m)));
  for (int k = 1; k < n; ++k)
    if (count[k] >= min_cells) seeds.push_back(first[k]);
}

// Flood fill of free space (4-connected, so diagonal gaps in a wall do not leak).
Grid<std::uint8_t> flood_free(const Grid<std::uint8_t>& passable,
                              const std::vector<CellIndex>& seeds) {
  const int w = passable.width, h = passable.height;
  Grid<std::uint8_t> free_mask(w, h, 0);
  std::deque<CellIndex> q;
  for (const auto& s : seeds)
    if (!free_mask.at(s)) {
      free_mask.at(s) = 1;
      q.push_back(s);
    }
  while (!q.empty()) {
    const CellIndex c = q.front();
    q.pop_front();
    for (int k = 0; k < 4; ++k) {
      const int nc = c.col + kDx4[k], nr = c.row + kDy4[k];
      if (!passable.contains(nc, nr) || !passable.at(nc, nr) || free_mask.at(nc, nr)) continue;
      free_mask.at(nc, nr) = 1;
      q.push_back({nc, nr});
    }
  }
  return free_mask;
}

// Furniture stands in the room: an object (8-connected) that touches no free cell lies outside
// it (seen through a window or the door) and stays unknown. Without free space, keep everything.
void keep_furniture_in_room(Grid<std::uint8_t>& furn, const Grid<std::uint8_t>& free_mask) {
  const int w = furn.width, h = furn.height;
  if (std::any_of(free_mask.data.begin(), free_mask.data.end(), [](auto v) { return v != 0; })) {
    cv::Mat obj_labels;
    const int n_obj = cv::connectedComponents(as_mat(furn), obj_labels, 8, CV_32S);
    std::vector<std::uint8_t> keep(static_cast<std::size_t>(n_obj), 0);
    for (int row = 0; row < h; ++row)
      for (int col = 0; col < w; ++col) {
        const int lab = obj_labels.at<int>(row, col);
        if (lab == 0 || keep[lab]) continue;
        for (int k = 0; k < 4; ++k)
          if (free_mask.contains(col + kDx4[k], row + kDy4[k]) &&
              free_mask.at(col + kDx4[k], row + kDy4[k]))
            keep[lab] = 1;
      }
    for (int row = 0; row < h; ++row)
      for (int col = 0; col < w; ++col)
        if (!keep[obj_labels.at<int>(row, col)]) furn.at(col, row) = 0;
  }
}

// The classes of the layout (wall over furniture over free) and their cell counts.
void classify(const Grid<std::uint8_t>& walls, const Grid<std::uint8_t>& furn,
              const Grid<std::uint8_t>& free_mask, LayoutResult& r) {
  for (std::size_t i = 0; i < r.layout.size(); ++i) {
    Cell c = Cell::kUnknown;
    if (walls.data[i])
      c = Cell::kWall;
    else if (furn.data[i])
      c = Cell::kFurniture;
    else if (free_mask.data[i])
      c = Cell::kFree;
    r.layout.data[i] = c;
    switch (c) {
      case Cell::kWall:
        ++r.cells_wall;
        break;
      case Cell::kFurniture:
        ++r.cells_furniture;
        break;
      case Cell::kFree:
        ++r.cells_free;
        break;
      case Cell::kUnknown:
        ++r.cells_unknown;
        break;
    }
  }
}

}  // namespace

LayoutResult build_layout(const Grid<std::uint8_t>& walls_in, const Grid<std::uint8_t>& furniture,
                          const GridGeometry& geo, const std::vector<Eigen::Vector2d>& scanners_map,
                          const LayoutParams& params, const Grid<std::uint8_t>* support,
                          const Grid<std::uint8_t>* evidence, const Grid<std::uint8_t>* seen) {
  if (walls_in.width != furniture.width || walls_in.height != furniture.height ||
      walls_in.width != geo.width() || walls_in.height != geo.height())
    throw Error("build_layout: wall map, furniture map and geometry differ in size");
  validate(params);
  const int w = walls_in.width, h = walls_in.height;
  LayoutResult r;
  r.layout = Grid<Cell>(w, h, Cell::kUnknown);
  if (w == 0 || h == 0) {
    r.warnings.push_back("empty grid: no layout");
    return r;
  }
  Grid<std::uint8_t> walls = walls_in;
  if (support && (support->width != w || support->height != h))
    throw Error("build_layout: support map differs in size");
  const Grid<std::uint8_t> hanging =
      hanging_mask(walls_in, support ? *support : furniture,
                   passage_area(obstacles_of(walls_in, furniture), params.passage_min_lines),
                   geo.cell_m(), params, &r.hanging);
  for (std::size_t i = 0; i < walls.size(); ++i) walls.data[i] &= !hanging.data[i];
  // The passes run over the obstacles of both bands. The paper uses the wall band alone, but one
  // gap in it (a window or a glass transom high up in a wall, as in the Jacobs lab) then opens
  // every row or column through the gap, and the whole strip falls outside the room. The lower
  // part of the same wall closes the gap in the furniture band.
  // A scanner stands inside its room: when none lies in the passage area, the walls are too
  // sparse to bracket it (dotted walls of a sparse scan) and the test runs on bridged obstacles.
  // Only then: bridging a dense scan's obstacles also brackets the corridor seen through a door.
  const Grid<std::uint8_t> obstacles = obstacles_of(walls, furniture);
  r.passage = passage_area(obstacles, params.passage_min_lines);
  bool in_map = false, inside = false;
  for (const auto& s : scanners_map) {
    const CellIndex c = geo.cell_of(s);
    in_map = in_map || geo.contains(c);
    inside = inside || (geo.contains(c) && r.passage.at(c) != 0);
  }
  if (in_map && !inside && params.passage_bridge_m >= 1.5 * geo.cell_m()) {  // >= 3 cells
    r.passage = passage_area(bridged(obstacles, geo.cell_m(), params), params.passage_min_lines);
    r.passage_bridged = true;
    r.warnings.push_back(
        "no scanner inside the walls found: the walls are sparse (a coarse scan?); gaps up to " +
        fmt_len(params.passage_bridge_m) + " bridged to close the room");
  }

  // The flood is stopped by the furniture map closed with a 3x3 square: a scanner sees the front
  // of a cabinet as a speckled face, and a 4-connected flood would leak through its gaps into the
  // space behind it. Closing (not dilating) keeps the free space as large as it is.
  Grid<std::uint8_t> barrier = furniture;
  if (params.flood_barrier_closing > 0) {
    const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
    cv::morphologyEx(as_mat(barrier), as_mat(barrier), cv::MORPH_CLOSE, square, {-1, -1},
                     params.flood_barrier_closing);
  }
  Grid<std::uint8_t> passable(w, h, 0);
  for (std::size_t i = 0; i < passable.size(); ++i)
    passable.data[i] = r.passage.data[i] && !walls.data[i] && !barrier.data[i];
  if (evidence && (evidence->width != w || evidence->height != h))
    throw Error("build_layout: evidence map differs in size");
  Grid<std::uint8_t> floodable = passable;
  if (evidence && params.free_needs_evidence) {
    Grid<std::uint8_t> seen = *evidence;
    const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
    cv::morphologyEx(as_mat(seen), as_mat(seen), cv::MORPH_CLOSE, square);
    for (std::size_t i = 0; i < floodable.size(); ++i) floodable.data[i] &= seen.data[i] != 0;
  }

  if (seen && (seen->width != w || seen->height != h))
    throw Error("build_layout: seen map differs in size");
  place_seeds(floodable, geo, scanners_map, params, r);
  if (r.seeds_estimated && seen) add_seen_seeds(floodable, *seen, geo.cell_m(), r.seeds);
  const Grid<std::uint8_t> free_mask = flood_free(floodable, r.seeds);
  if (params.wall_max_thickness_m > 0)
    detail::add_inner_walls(furniture, seen, r.passage, free_mask, geo.cell_m(),
                            params.wall_max_thickness_m, walls);

  // Furniture: furniture-band obstacles inside the passage area, plus small unreachable pockets
  // that touch them (behind and between objects).
  Grid<std::uint8_t> furn(w, h, 0);
  for (std::size_t i = 0; i < furn.size(); ++i)
    furn.data[i] = r.passage.data[i] && barrier.data[i] && !walls.data[i];
  Grid<std::uint8_t> pockets(w, h, 0);
  for (std::size_t i = 0; i < pockets.size(); ++i)
    pockets.data[i] = passable.data[i] && !free_mask.data[i];
  cv::Mat labels, stats, centroids;
  const int n =
      cv::connectedComponentsWithStats(as_mat(pockets), labels, stats, centroids, 4, CV_32S);
  if (n > 1) {
    const double cell_area = geo.cell_m() * geo.cell_m();
    std::vector<std::uint8_t> touches(static_cast<std::size_t>(n), 0);
    for (int row = 0; row < h; ++row)
      for (int col = 0; col < w; ++col) {
        const int lab = labels.at<int>(row, col);
        if (lab == 0 || touches[lab]) continue;
        for (int dr = -1; dr <= 1 && !touches[lab]; ++dr)
          for (int dc = -1; dc <= 1; ++dc)
            if (furn.contains(col + dc, row + dr) && furn.at(col + dc, row + dr)) {
              touches[lab] = 1;
              break;
            }
      }
    for (int row = 0; row < h; ++row)
      for (int col = 0; col < w; ++col) {
        const int lab = labels.at<int>(row, col);
        if (lab > 0 && touches[lab] &&
            stats.at<int>(lab, cv::CC_STAT_AREA) * cell_area <= params.enclosed_max_area_m2)
          furn.at(col, row) = 1;
      }
  }
  if (params.furniture_closing_iterations > 0) {
    const cv::Mat cross = cv::getStructuringElement(cv::MORPH_CROSS, {3, 3});
    cv::Mat closed;
    cv::morphologyEx(as_mat(furn), closed, cv::MORPH_CLOSE, cross, {-1, -1},
                     params.furniture_closing_iterations);
    for (int row = 0; row < h; ++row)
      for (int col = 0; col < w; ++col)
        if (closed.at<std::uint8_t>(row, col) && r.passage.at(col, row) && !walls.at(col, row))
          furn.at(col, row) = 1;
  }

  keep_furniture_in_room(furn, free_mask);
  classify(walls, furn, free_mask, r);
  return r;
}

}  // namespace indoormap::layout
