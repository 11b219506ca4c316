#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "indoormap/rooms/rooms.hpp"

namespace indoormap::rooms {

namespace {

/// A cell M_r's flood went through (free, or furniture it enclosed) that is no room's free cell.
bool open_unlabelled(const Grid<Cell>& layout, const Grid<std::uint16_t>& labels, int c, int r) {
  const Cell l = layout.at(c, r);
  return labels.at(c, r) == 0 && (l == Cell::kFree || l == Cell::kFurniture);
}

/// The one room whose free cells lie within two cells of (c, r), 0 if none or several.
int facing_room(const Grid<std::uint16_t>& labels, int c, int r) {
  int room = 0;
  for (int dr = -2; dr <= 2; ++dr)
    for (int dc = -2; dc <= 2; ++dc) {
      if (!labels.contains(c + dc, r + dr)) continue;
      const int l = labels.at(c + dc, r + dr);
      if (l == 0) continue;
      if (room != 0 && l != room) return 0;
      room = l;
    }
  return room;
}

struct Normal {
  double x = 0.0, y = 0.0;  ///< unit, grid (column, row) axes, pointing away from the room
  bool ok = false;
};

/// A face's wall cells spread along its line at least this many times more than across it; also
/// near a corner, where the other wall's cells enter the window, but not at a blob or the end of a
/// wall, whose "normal" would run along the room.
constexpr double kMinElongation = 2.5;

/// The face's normal at wall cell (c, r): the minor axis of the wall cells within three cells
/// (which lie along a line, kMinElongation), turned away from the room's cells; the room's cells
/// must lie straight in front of the face.
Normal face_normal(const Grid<Cell>& layout, const Grid<std::uint16_t>& labels, int room, int c,
                   int r) {
  double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0, fx = 0, fy = 0;
  int n = 0;
  for (int dr = -3; dr <= 3; ++dr)
    for (int dc = -3; dc <= 3; ++dc) {
      if (!layout.contains(c + dc, r + dr)) continue;
      if (std::abs(dc) <= 2 && std::abs(dr) <= 2 && labels.at(c + dc, r + dr) == room)
        fx += dc, fy += dr;
      if (layout.at(c + dc, r + dr) != Cell::kWall) continue;
      sx += dc, sy += dr, sxx += dc * dc, syy += dr * dr, sxy += dc * dr, ++n;
    }
  Normal out;
  if (n < 5) return out;
  const double cxx = sxx / n - sx * sx / n / n, cyy = syy / n - sy * sy / n / n,
               cxy = sxy / n - sx * sy / n / n;
  const double mid = (cxx + cyy) / 2, rad = std::hypot((cxx - cyy) / 2, cxy);
  const double major = mid + rad, minor = mid - rad;
  if (major < kMinElongation * std::max(minor, 1e-3)) return out;
  // Minor axis: perpendicular to the major one (cxy, major - cxx) or (major - cyy, cxy).
  double ax = cxy, ay = major - cxx;
  if (std::hypot(ax, ay) < 1e-9) ax = major - cyy, ay = cxy;
  const double len = std::hypot(ax, ay);
  out.x = -ay / len, out.y = ax / len;
  if (out.x * fx + out.y * fy > 0) out.x = -out.x, out.y = -out.y;
  for (const double k : {1.0, 1.5, 2.0}) {
    const int qc = c - static_cast<int>(std::lround(k * out.x)),
              qr = r - static_cast<int>(std::lround(k * out.y));
    if (labels.contains(qc, qr) && labels.at(qc, qr) == room) out.ok = true;
  }
  return out;
}

/// A ray from a face cell along its normal, in steps of half a cell, each cell once.
class Ray {
 public:
  Ray(int c, int r, double nx, double ny) : c_(c), r_(r), nx_(nx), ny_(ny), pc_(c), pr_(r) {}
  /// The next cell and its distance from the face in cells.
  void next(int& c, int& r, double& s) {
    do {
      s_ += 0.5;
      c = c_ + static_cast<int>(std::lround(s_ * nx_));
      r = r_ + static_cast<int>(std::lround(s_ * ny_));
    } while (c == pc_ && r == pr_);
    pc_ = c, pr_ = r, s = s_;
  }

 private:
  int c_, r_;
  double nx_, ny_;
  int pc_, pr_;
  double s_ = 0.0;
};

struct Body {
  std::vector<CellIndex> cells;
  bool gap = false;     ///< a body cell that is no obstacle of the navigation map
  int behind = 0;       ///< the first room's cell on the ray past the body (0: none)
  double behind_s = 0;  ///< its distance from the face, cells
};

/// Walks straight back from the face cell (c, r): its wall cells (kMaxFaceCells at most), then
/// the body up to a room's cell, an unknown cell, a second wall, `reach` cells, or an obstacle of
/// the navigation map after body cells that are none (the near face seen low down, or furniture
/// against the wall: the body's last cell); a body that is an obstacle from the start (the
/// navigation map saw the wall's top) runs on. Then on to the first room's cell within
/// `behind_reach` cells.
Body walk_body(const Grid<Cell>& layout, const Grid<Cell>& nav, const Grid<std::uint16_t>& labels,
               int c, int r, double nx, double ny, double reach, double behind_reach) {
  constexpr int kMaxFaceCells = 2;  // a face in M_r is one or two cells deep; more is the wall
  Body b;
  Ray ray(c, r, nx, ny);
  int face = 1, qc = c, qr = r;
  double s = 0.0;
  bool open = true;
  while (true) {
    ray.next(qc, qr, s);
    if (s > behind_reach || !labels.contains(qc, qr)) return b;
    if (labels.at(qc, qr) != 0) break;
    if (!open || s > reach) continue;
    if (open_unlabelled(layout, labels, qc, qr)) {
      b.cells.push_back({qc, qr});
      if (nav.at(qc, qr) != Cell::kWall)
        b.gap = true;
      else if (b.gap)
        open = false;
    } else if (!b.cells.empty() || layout.at(qc, qr) != Cell::kWall || ++face > kMaxFaceCells) {
      open = false;
    }
  }
  b.behind = labels.at(qc, qr), b.behind_s = s;
  return b;
}

}  // namespace

Grid<Cell> mark_wall_bodies(const Grid<Cell>& layout, const Grid<Cell>& nav,
                            const RoomsResult& rooms, double max_wall_m) {
  Grid<Cell> out = layout;
  const Grid<std::uint16_t>& labels = rooms.labels;
  if (layout.width != labels.width || layout.height != labels.height || nav.width != labels.width ||
      nav.height != labels.height)
    return out;
  const double cell = rooms.geometry.cell_m(), reach = max_wall_m / cell;
  // Another room lies behind a wall's body: past an unseen stretch (the body, a shadow) up to
  // 2 m from the face, or within max_wall_m and two cells of it when the navigation map saw the
  // whole body as an obstacle (the wall's top). An object in a room, whose side M_r may call
  // wall, has the same room behind it, or another one only beyond a wall.
  constexpr double kBehindReach_m = 2.0;
  for (int r = 0; r < layout.height; ++r)
    for (int c = 0; c < layout.width; ++c) {
      if (layout.at(c, r) != Cell::kWall) continue;
      const int room = facing_room(labels, c, r);
      if (room == 0) continue;
      const Normal n = face_normal(layout, labels, room, c, r);
      if (!n.ok) continue;
      const Body b = walk_body(layout, nav, labels, c, r, n.x, n.y, reach, kBehindReach_m / cell);
      if (b.behind == 0 || b.behind == room || (!b.gap && b.behind_s > reach + 2.0)) continue;
      for (const CellIndex& q : b.cells) out.at(q) = Cell::kWall;
    }
  return out;
}

}  // namespace indoormap::rooms
