#include "indoormap/rooms/rooms.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <string>
#include <utility>

#include "indoormap/areas/rooms.hpp"
#include "indoormap/border/border.hpp"
#include "indoormap/core/cell_rings.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/core/parallel.hpp"

namespace indoormap::rooms {

namespace {

void rooms_require(bool ok, const std::string& key, const std::string& what) {
  if (!ok) throw UsageError("invalid parameter rooms." + key + ": " + what);
}

/// The room's closed polygon: the cells of `id` at half-cell resolution, grown by one half cell
/// (4-neighbours), traced; the largest outer ring, not simplified: a Douglas-Peucker pass cuts
/// corners and door notches by a share of a cell along whole walls (1 % of a 6 m2 room's area),
/// while the staircase of a rotated wall is at most half a cell off its line.
Polygon rooms_outline(const Grid<std::uint16_t>& labels, const GridGeometry& g, int id, int c0,
                      int r0, int c1, int r1) {
  const int w = (c1 - c0 + 3) * 2, h = (r1 - r0 + 3) * 2;  // one cell margin all round
  std::vector<unsigned char> fine(static_cast<std::size_t>(w) * h, 0);
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      if (labels.at(c, r) != id) continue;
      const int fc = (c - c0 + 1) * 2, fr = (r - r0 + 1) * 2;
      for (int dr = -1; dr <= 2; ++dr)
        for (int dc = -1; dc <= 2; ++dc) {
          const bool corner = (dr == -1 || dr == 2) && (dc == -1 || dc == 2);
          if (!corner) fine[static_cast<std::size_t>(fr + dr) * w + fc + dc] = 1;
        }
    }
  const CellRings rings = trace_mask_rings(fine, 0, 0, w, h);
  const CellRing* best = nullptr;
  double best_area = 0.0;
  for (const auto& ring : rings.outer) {
    const double a = std::abs(signed_area(ring));
    if (a > best_area) best_area = a, best = &ring;
  }
  if (!best) return {};
  Polygon poly;
  poly.reserve(best->size());
  for (const auto& v : *best)  // fine cell coords -> grid cell coords -> map frame
    poly.push_back(g.from_cell_coords(v / 2.0 + Eigen::Vector2d(c0 - 1, r0 - 1)));
  return poly;
}

/// Doors: the 4-neighbour pairs of cells of two rooms, per pair of rooms; end points are the
/// extremes along the border's main axis.
std::vector<RoomDoor> rooms_doors(const Grid<std::uint16_t>& labels, const GridGeometry& g) {
  std::map<std::pair<int, int>, std::vector<Eigen::Vector2d>> borders;
  for (int r = 0; r < labels.height; ++r)
    for (int c = 0; c < labels.width; ++c) {
      const int a = labels.at(c, r);
      if (a == 0) continue;
      for (const auto& [dc, dr] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (!labels.contains(c + dc, r + dr)) continue;
        const int b = labels.at(c + dc, r + dr);
        if (b == 0 || b == a) continue;
        const Eigen::Vector2d mid = 0.5 * (g.center_of({c, r}) + g.center_of({c + dc, r + dr}));
        borders[{std::min(a, b), std::max(a, b)}].push_back(mid);
      }
    }
  std::vector<RoomDoor> doors;
  for (const auto& [ab, pts] : borders) {
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const auto& p : pts) mean += p;
    mean /= static_cast<double>(pts.size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (const auto& p : pts) cov += (p - mean) * (p - mean).transpose();
    Eigen::Vector2d axis(1.0, 0.0);
    if (pts.size() > 1) {
      const double angle = 0.5 * std::atan2(2.0 * cov(0, 1), cov(0, 0) - cov(1, 1));
      axis = {std::cos(angle), std::sin(angle)};
    }
    double lo = 0.0, hi = 0.0;
    for (const auto& p : pts) {
      const double t = (p - mean).dot(axis);
      lo = std::min(lo, t), hi = std::max(hi, t);
    }
    RoomDoor d;
    d.a = ab.first, d.b = ab.second;
    d.end0_m = mean + (lo - 0.5 * g.cell_m()) * axis;
    d.end1_m = mean + (hi + 0.5 * g.cell_m()) * axis;
    d.width_m = hi - lo + g.cell_m();
    d.shared_cells = static_cast<int>(pts.size());
    doors.push_back(d);
  }
  return doors;
}

/// Every room's polygon, area and perimeter from the cells of `cells` holding its id.
void rooms_draw_polygons(RoomsResult& out, const Grid<std::uint16_t>& cells) {
  const int n = static_cast<int>(out.rooms.size());
  std::vector<std::array<int, 4>> box(static_cast<std::size_t>(n) + 1, {1 << 30, 1 << 30, -1, -1});
  for (int r = 0; r < cells.height; ++r)
    for (int c = 0; c < cells.width; ++c) {
      const int l = cells.at(c, r);
      if (l <= 0 || l > n) continue;
      auto& b = box[static_cast<std::size_t>(l)];
      b = {std::min(b[0], c), std::min(b[1], r), std::max(b[2], c), std::max(b[3], r)};
    }
  for (auto& room : out.rooms) {
    const auto& b = box[static_cast<std::size_t>(room.id)];
    if (b[2] < 0) continue;
    room.polygon_m = rooms_outline(cells, out.geometry, room.id, b[0], b[1], b[2], b[3]);
    room.area_m2 = std::abs(signed_area(room.polygon_m));
    room.perimeter_m = perimeter(room.polygon_m);
  }
}

// The rooms (ids, cells, polygons), doors and neighbours from labels holding the ids 1..n.
void rooms_rebuild(RoomsResult& out) {
  int n = 0;
  for (const auto l : out.labels.data) n = std::max(n, static_cast<int>(l));
  out.rooms.assign(static_cast<std::size_t>(n), Room{});
  for (int i = 0; i < n; ++i) out.rooms[static_cast<std::size_t>(i)].id = i + 1;
  for (const auto l : out.labels.data)
    if (l != 0) ++out.rooms[static_cast<std::size_t>(l - 1)].cells;
  rooms_draw_polygons(out, out.labels);
  out.doors = rooms_doors(out.labels, out.geometry);
  for (const auto& d : out.doors) {
    out.rooms[static_cast<std::size_t>(d.a - 1)].neighbours.push_back(d.b);
    out.rooms[static_cast<std::size_t>(d.b - 1)].neighbours.push_back(d.a);
  }
  for (auto& r : out.rooms) std::sort(r.neighbours.begin(), r.neighbours.end());
}

/// Door passages: room cells near a door (within its half width plus two cells of its middle)
/// that lie on a chord no longer than the door's width plus four cells between cells outside
/// every room, in some direction (every 7.5 degrees) within 15 degrees of the passage's axis (a
/// veil before the door closes steep chords from a jamb). Inside a room, beside the wall face,
/// every line runs on into the room on one side at least; in the passage through the wall the line
/// from jamb to jamb is closed. The door's own axis (the rooms' shared border) is no guide: the
/// segmentation often splits the passage along a diagonal.
void rooms_cut_passages(const RoomsResult& out, Grid<std::uint16_t>& grown) {
  const GridGeometry& g = out.geometry;
  const Grid<std::uint16_t>& labels = out.labels;
  const double cell = g.cell_m();
  constexpr int kDirections = 24, kAxisWindow = 2;  // every 7.5 degrees, 15 off the axis
  std::array<Eigen::Vector2d, kDirections> dirs;
  for (int k = 0; k < kDirections; ++k)
    dirs[static_cast<std::size_t>(k)] = {std::cos(k * M_PI / kDirections),
                                         std::sin(k * M_PI / kDirections)};
  for (const auto& d : out.doors) {
    const Eigen::Vector2d m = 0.5 * (d.end0_m + d.end1_m);
    const double len = (d.end1_m - d.end0_m).norm();
    if (len <= 0.0) continue;
    const double half = 0.5 * len + 2.0 * cell, max_chord = 2.0 * half;
    // Distance from p along dir to the first cell outside every room, max_chord + 1 if none.
    const auto reach = [&](const Eigen::Vector2d& p, const Eigen::Vector2d& dir) {
      for (double t = 0.0; t <= max_chord; t += 0.5 * cell) {
        const CellIndex q = g.cell_of(p + t * dir);
        if (!labels.contains(q.col, q.row) || labels.at(q) == 0) return t;
      }
      return max_chord + 1.0;
    };
    // The passage's axis: the direction of the shortest closed chord through the door's middle
    // (jamb to jamb), when there is one; chords within 15 degrees of it only.
    int axis = -1;
    double shortest = max_chord;
    for (int k = 0; k < kDirections; ++k) {
      const Eigen::Vector2d& dir = dirs[static_cast<std::size_t>(k)];
      const double chord = reach(m, dir) + reach(m, -dir);
      if (chord <= shortest) shortest = chord, axis = k;
    }
    const CellIndex lo = g.cell_of(m - Eigen::Vector2d::Constant(half));
    const CellIndex hi = g.cell_of(m + Eigen::Vector2d::Constant(half));
    for (int r = std::max(lo.row, 0); r <= std::min(hi.row, labels.height - 1); ++r)
      for (int c = std::max(lo.col, 0); c <= std::min(hi.col, labels.width - 1); ++c) {
        const int id = labels.at(c, r);
        if (id != d.a && id != d.b) continue;
        const Eigen::Vector2d p = g.center_of({c, r});
        if ((p - m).norm() > half) continue;
        for (int k = 0; k < kDirections; ++k) {
          const int off = std::abs(k - axis) % kDirections;
          if (axis >= 0 && std::min(off, kDirections - off) > kAxisWindow) continue;
          const Eigen::Vector2d& dir = dirs[static_cast<std::size_t>(k)];
          if (reach(p, dir) + reach(p, -dir) <= max_chord) {
            grown.at(c, r) = 0;
            break;
          }
        }
      }
  }
}

/// Each room keeps only its largest 4-connected part. With M_r's walls taken out, a door's
/// passage is cut off from the room by the lintel's faces (M_r's wall band holds the lintel); the
/// pieces of the passage the segmentation gave the room would otherwise stay in its outline, and
/// the fit to the faces would follow the jambs into the door.
void keep_main_parts(Grid<std::uint16_t>& grown) {
  const int w = grown.width, h = grown.height;
  Grid<int> part(w, h, 0);
  std::vector<std::int64_t> size(1, 0);
  std::vector<std::uint16_t> room_of(1, 0);
  std::vector<CellIndex> stack;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const std::uint16_t id = grown.at(c, r);
      if (!id || part.at(c, r)) continue;
      const int p = static_cast<int>(size.size());
      size.push_back(0);
      room_of.push_back(id);
      part.at(c, r) = p;
      stack.push_back({c, r});
      while (!stack.empty()) {
        const CellIndex at = stack.back();
        stack.pop_back();
        ++size[static_cast<std::size_t>(p)];
        for (const auto& [dc, dr] :
             {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
          const int nc = at.col + dc, nr = at.row + dr;
          if (!grown.contains(nc, nr) || grown.at(nc, nr) != id || part.at(nc, nr)) continue;
          part.at(nc, nr) = p;
          stack.push_back({nc, nr});
        }
      }
    }
  std::vector<int> best(65536, 0);
  for (std::size_t p = 1; p < size.size(); ++p)
    if (!best[room_of[p]] || size[p] > size[static_cast<std::size_t>(best[room_of[p]])])
      best[room_of[p]] = static_cast<int>(p);
  for (std::size_t i = 0; i < grown.data.size(); ++i)
    if (grown.data[i] && best[grown.data[i]] != part.data[i]) grown.data[i] = 0;
}

}  // namespace

void fill_rooms(RoomsResult& out, const Grid<Cell>& layout, const Grid<std::uint8_t>& blocked,
                double max_fill_m) {
  const Grid<std::uint16_t>& labels = out.labels;
  if (layout.width != labels.width || layout.height != labels.height || out.rooms.empty()) return;
  const bool has_blocked = blocked.width == labels.width && blocked.height == labels.height;
  const auto stops = [&](int c, int r) {
    const Cell l = layout.at(c, r);
    return l == Cell::kWall || l == Cell::kUnknown || (has_blocked && blocked.at(c, r));
  };
  // A door's passage through the wall is free, but M_r has the lintel's wall or strip there:
  // those cells leave the room's polygon (which ends at the wall's face).
  Grid<std::uint16_t> grown = labels;
  Grid<int> steps(labels.width, labels.height, 0);
  std::vector<CellIndex> queue;
  rooms_cut_passages(out, grown);
  out.passages = Grid<std::uint8_t>(labels.width, labels.height, 0);
  for (std::size_t i = 0; i < grown.data.size(); ++i)
    out.passages.data[i] = labels.data[i] != 0 && grown.data[i] == 0;
  for (int r = 0; r < labels.height; ++r)
    for (int c = 0; c < labels.width; ++c) {
      if (!grown.at(c, r)) continue;
      const Cell l = layout.at(c, r);
      if (l == Cell::kWall || (has_blocked && blocked.at(c, r))) grown.at(c, r) = 0;
    }
  keep_main_parts(grown);
  for (int r = 0; r < labels.height; ++r)
    for (int c = 0; c < labels.width; ++c)
      if (grown.at(c, r)) queue.push_back({c, r});
  const int max_steps = static_cast<int>(std::lround(max_fill_m / out.geometry.cell_m()));
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const CellIndex at = queue[head];
    if (steps.at(at) >= max_steps) continue;
    for (const auto& [dc, dr] :
         {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
      const int c = at.col + dc, r = at.row + dr;
      if (!grown.contains(c, r) || grown.at(c, r) != 0 || labels.at(c, r) != 0 || stops(c, r))
        continue;
      grown.at(c, r) = grown.at(at);
      steps.at(c, r) = steps.at(at) + 1;
      queue.push_back({c, r});
    }
  }
  rooms_draw_polygons(out, grown);
}

namespace {

/// A fitted polygon that covers more of other rooms' free cells than this (a line of an unseen
/// corridor end meeting its neighbour far out) or leaves more of the room's own free cells outside
/// (a door's passage through the wall is outside, a few per cent of a corridor's) is not taken.
constexpr double kMaxForeign_m2 = 0.1;
constexpr double kMaxLostShare = 0.05;

struct CellShares {
  double foreign_m2 = 0.0;  ///< other rooms' free cells inside poly
  double lost_share = 0.0;  ///< the room's own free cells outside poly, per cell of the room
};

CellShares cell_shares(const RoomsResult& out, const Room& room, const Polygon& poly) {
  const GridGeometry& g = out.geometry;
  auto [lo, hi] = bounds(poly);
  const CellIndex a = g.cell_of(lo), b = g.cell_of(hi);
  std::int64_t foreign = 0, inside_own = 0;
  for (int r = std::max(a.row, 0); r <= std::min(b.row, out.labels.height - 1); ++r)
    for (int c = std::max(a.col, 0); c <= std::min(b.col, out.labels.width - 1); ++c) {
      const int l = out.labels.at(c, r);
      if (l == 0 || !contains(poly, g.center_of({c, r}))) continue;
      foreign += l != room.id;
      inside_own += l == room.id;
    }
  if (room.cells <= 0) return {0.0, 1.0};
  return {static_cast<double>(foreign) * g.cell_m() * g.cell_m(),
          static_cast<double>(room.cells - inside_own) / room.cells};
}

}  // namespace

int fit_rooms_to_faces(RoomsResult& out, const Grid<Cell>& layout,
                       const border::BorderParams& params, double max_area_change) {
  if (layout.width != out.labels.width || layout.height != out.labels.height) return 0;
  // The rooms' free cells are room space beside the faces, also where M_r's flood did not go
  // (its seeds are the scanner positions; without any it floods one room).
  // A door's passage is no room space: the sides of its jambs are no faces of the rooms.
  Grid<Cell> faces = layout;
  const bool passages = out.passages.data.size() == faces.data.size();
  for (std::size_t i = 0; i < faces.data.size(); ++i)
    if (passages && out.passages.data[i])
      faces.data[i] = Cell::kUnknown;
    else if (out.labels.data[i] != 0 && faces.data[i] == Cell::kUnknown)
      faces.data[i] = Cell::kFree;
  // Each room's fit reads only its own outline and the shared grids: the rooms are split between
  // the cores, and the results applied in room order.
  const auto parts = parallel_parts(out.rooms.size(), 1, [&](std::size_t r0, std::size_t r1) {
    std::vector<std::optional<Polygon>> fits;
    for (std::size_t k = r0; k < r1; ++k) {
      const Room& room = out.rooms[k];
      auto poly = border::fit_to_wall_faces(room.polygon_m, faces, out.geometry, params);
      if (poly) {
        const CellShares sh = cell_shares(out, room, *poly);
        if (std::abs(std::abs(signed_area(*poly)) - room.area_m2) >
                max_area_change * room.area_m2 ||
            sh.foreign_m2 > kMaxForeign_m2 || sh.lost_share > kMaxLostShare)
          poly.reset();
      }
      fits.push_back(std::move(poly));
    }
    return fits;
  });
  int fitted = 0;
  std::size_t k = 0;
  for (const auto& part : parts)
    for (const auto& poly : part) {
      Room& room = out.rooms[k++];
      if (!poly) continue;
      room.polygon_m = *poly;
      room.area_m2 = std::abs(signed_area(*poly));
      room.perimeter_m = perimeter(*poly);
      ++fitted;
    }
  return fitted;
}

void validate(const RoomsParams& p) {
  areas::validate(p.segmentation);
  rooms_require(p.min_room_area_m2 >= 0.0, "min_room_area_m2", "must be >= 0");
  rooms_require(p.inner_wall_max_width_m >= 0.0, "inner_wall_max_width_m", "must be >= 0");
  rooms_require(p.inner_wall_reach_m >= 0.0 && p.inner_wall_reach_m <= 1.0, "inner_wall_reach_m",
                "must be in [0, 1]");
  rooms_require(p.wall_piece_reach_m >= 0.0 && p.wall_piece_reach_m <= 1.0, "wall_piece_reach_m",
                "must be in [0, 1]");
}

RoomsResult find_rooms(const Grid<Cell>& nav, const GridGeometry& g, const RoomsParams& p) {
  validate(p);
  RoomsResult out;
  out.geometry = g;
  out.labels = Grid<std::uint16_t>(nav.width, nav.height, 0);
  Grid<std::uint8_t> free(nav.width, nav.height, 0);
  bool any = false;
  for (std::size_t i = 0; i < nav.data.size(); ++i)
    if (nav.data[i] == Cell::kFree) free.data[i] = 1, any = true;
  if (!any) return out;
  int count = 0;
  const Grid<int> seg = areas::segment_rooms(free, g.cell_m(), p.segmentation, &count);
  // Pieces and their cell counts; small ones are no room; ids renumbered 1.. in order.
  std::vector<int> cells(static_cast<std::size_t>(count) + 1, 0);
  for (const int l : seg.data)
    if (l > 0 && l <= count) ++cells[static_cast<std::size_t>(l)];
  const double cell_area = g.cell_m() * g.cell_m();
  std::vector<int> new_id(cells.size(), 0);
  int n = 0;
  for (std::size_t l = 1; l < cells.size(); ++l)
    if (cells[l] > 0 && cells[l] * cell_area >= p.min_room_area_m2) new_id[l] = ++n;
  for (std::size_t i = 0; i < seg.data.size(); ++i) {
    const int l = seg.data[i];
    if (l > 0 && l <= count) out.labels.data[i] = static_cast<std::uint16_t>(new_id[l]);
  }
  rooms_rebuild(out);
  return out;
}

namespace {
/// [m2] a piece of wall smaller than this stands free in a room (a pillar): no door's jamb.
constexpr double kMaxPillar_m2 = 1.0;
}  // namespace

int join_furniture_necks(RoomsResult& out, const Grid<Cell>& layout, double door_max_m,
                         double reach_m) {
  const GridGeometry& g = out.geometry;
  if (layout.width != out.labels.width || layout.height != out.labels.height) return 0;
  const int reach = static_cast<int>(std::ceil(reach_m / g.cell_m()));
  // The walls' pieces (8-neighbours); one smaller than kMaxPillar_m2 stands free in a room.
  cv::Mat wall(layout.height, layout.width, CV_8U), lab, stats, centroids;
  for (int r = 0; r < layout.height; ++r)
    for (int c = 0; c < layout.width; ++c)
      wall.at<std::uint8_t>(r, c) = layout.at(c, r) == Cell::kWall ? 1 : 0;
  cv::connectedComponentsWithStats(wall, lab, stats, centroids, 8, CV_32S);
  const double pillar_cells = kMaxPillar_m2 / (g.cell_m() * g.cell_m());
  const auto jamb_near = [&](const Eigen::Vector2d& p) {
    const CellIndex at = g.cell_of(p);
    for (int r = at.row - reach; r <= at.row + reach; ++r)
      for (int c = at.col - reach; c <= at.col + reach; ++c)
        if ((c - at.col) * (c - at.col) + (r - at.row) * (r - at.row) <= reach * reach &&
            layout.contains(c, r) && wall.at<std::uint8_t>(r, c) &&
            stats.at<int>(lab.at<int>(r, c), cv::CC_STAT_AREA) >= pillar_cells)
          return true;
    return false;
  };
  std::vector<int> root(out.rooms.size() + 1);
  for (std::size_t i = 0; i < root.size(); ++i) root[i] = static_cast<int>(i);
  const auto find = [&](int a) {
    while (root[static_cast<std::size_t>(a)] != a) a = root[static_cast<std::size_t>(a)];
    return a;
  };
  int joined = 0;
  for (const auto& d : out.doors) {
    if (d.width_m <= door_max_m || jamb_near(d.end0_m) || jamb_near(d.end1_m)) continue;
    const int a = find(d.a), b = find(d.b);
    if (a == b) continue;
    root[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    ++joined;
  }
  if (joined == 0) return 0;
  std::vector<std::uint16_t> new_id(root.size(), 0);
  std::uint16_t n = 0;
  for (std::size_t id = 1; id < root.size(); ++id)
    if (find(static_cast<int>(id)) == static_cast<int>(id)) new_id[id] = ++n;
  for (auto& l : out.labels.data)
    if (l != 0) l = new_id[static_cast<std::size_t>(find(l))];
  rooms_rebuild(out);
  return joined;
}

int room_at(const RoomsResult& rooms, const Eigen::Vector2d& p, double max_m) {
  for (const auto& r : rooms.rooms)
    if (contains(r.polygon_m, p)) return r.id;
  const GridGeometry& g = rooms.geometry;
  const CellIndex at = g.cell_of(p);
  const int reach = static_cast<int>(std::ceil(max_m / g.cell_m()));
  int best = 0;
  double best_d2 = max_m * max_m;
  for (int r = at.row - reach; r <= at.row + reach; ++r)
    for (int c = at.col - reach; c <= at.col + reach; ++c) {
      if (!rooms.labels.contains(c, r) || rooms.labels.at(c, r) == 0) continue;
      const double d2 = (g.center_of({c, r}) - p).squaredNorm();
      if (d2 <= best_d2) best_d2 = d2, best = rooms.labels.at(c, r);
    }
  return best;
}

}  // namespace indoormap::rooms
