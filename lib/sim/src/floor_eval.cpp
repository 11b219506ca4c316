#include "indoormap/sim/floor_eval.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

namespace indoormap::sim {

namespace {
bool at_or(const Mask& m, const GridGeometry& g, const Eigen::Vector2d& p, bool outside) {
  const CellIndex c = g.cell_of(p);
  return g.contains(c) ? m.at(c.col, c.row) != 0 : outside;
}
bool near(const Mask& m, const GridGeometry& g, const Eigen::Vector2d& p) {
  const CellIndex c = g.cell_of(p);
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc)
      if (m.contains(c.col + dc, c.row + dr) && m.at(c.col + dc, c.row + dr)) return true;
  return false;
}
std::optional<double> ratio(double a, double b) {
  return b > 0 ? std::optional<double>(a / b) : std::nullopt;
}
}  // namespace

Mask class_mask(const Grid<Cell>& cells, Cell cls) {
  Mask m(cells.width, cells.height, 0);
  for (std::size_t i = 0; i < cells.data.size(); ++i) m.data[i] = cells.data[i] == cls;
  return m;
}

SeenIou evaluate_seen_free(const GridGeometry& tg, const Mask& truth_free, const Mask& seen,
                           const GridGeometry& rg, const Mask& result_free) {
  SeenIou s;
  const double at = tg.cell_m() * tg.cell_m(), ar = rg.cell_m() * rg.cell_m();
  for (int r = 0; r < tg.height(); ++r)
    for (int c = 0; c < tg.width(); ++c) {
      if (!seen.at(c, r)) continue;
      s.seen_m2 += at;
      s.union_m2 += at;
      if (at_or(result_free, rg, tg.center_of({c, r}), false)) s.intersection_m2 += at;
    }
  for (int r = 0; r < rg.height(); ++r)
    for (int c = 0; c < rg.width(); ++c) {
      if (!result_free.at(c, r)) continue;
      const Eigen::Vector2d p = rg.center_of({c, r});
      if (!at_or(truth_free, tg, p, false)) s.union_m2 += ar;  // free where the truth is not
    }
  s.iou = ratio(s.intersection_m2, s.union_m2);
  return s;
}

FarFree evaluate_far_free(const GridGeometry& tg, const Mask& seen, const GridGeometry& rg,
                          const Mask& result_free, double far_m) {
  // Offsets of the truth cells whose centres may lie within far_m of a point in a cell, nearest
  // first, so that a cell beside a seen one stops at once.
  const int k = static_cast<int>(std::ceil(far_m / tg.cell_m())) + 1;
  std::vector<std::pair<int, int>> disc;
  for (int dr = -k; dr <= k; ++dr)
    for (int dc = -k; dc <= k; ++dc) disc.emplace_back(dc, dr);
  std::sort(disc.begin(), disc.end(), [](const auto& a, const auto& b) {
    return a.first * a.first + a.second * a.second < b.first * b.first + b.second * b.second;
  });
  FarFree f;
  const double ar = rg.cell_m() * rg.cell_m(), far2 = far_m * far_m;
  for (int r = 0; r < rg.height(); ++r)
    for (int c = 0; c < rg.width(); ++c) {
      if (!result_free.at(c, r)) continue;
      f.free_m2 += ar;
      const Eigen::Vector2d p = rg.center_of({c, r});
      const CellIndex t = tg.cell_of(p);
      bool near_seen = false;
      for (const auto& [dc, dr] : disc) {
        const int x = t.col + dc, y = t.row + dr;
        if (!seen.contains(x, y) || !seen.at(x, y)) continue;
        if ((tg.center_of({x, y}) - p).squaredNorm() <= far2) {
          near_seen = true;
          break;
        }
      }
      if (!near_seen) f.far_m2 += ar;
    }
  f.share = ratio(f.far_m2, f.free_m2);
  return f;
}

FurnitureFree evaluate_furniture_free(const GridGeometry& tg, const Grid<Cell>& truth,
                                      const GridGeometry& rg, const Mask& result_free) {
  FurnitureFree f;
  const double at = tg.cell_m() * tg.cell_m();
  for (int r = 0; r < tg.height(); ++r)
    for (int c = 0; c < tg.width(); ++c) {
      if (truth.at(c, r) != Cell::kFurniture) continue;
      f.furniture_m2 += at;
      if (at_or(result_free, rg, tg.center_of({c, r}), false)) f.free_m2 += at;
    }
  f.share = ratio(f.free_m2, f.furniture_m2);
  return f;
}

FaceScores evaluate_wall_faces(const GridGeometry& tg, const Grid<Cell>& truth,
                               const GridGeometry& rg, const Mask& result_wall) {
  Mask face(truth.width, truth.height, 0);
  auto is_free = [&](int c, int r) {
    return truth.contains(c, r) && truth.at(c, r) == Cell::kFree;
  };
  FaceScores f;
  int hit = 0;
  for (int r = 0; r < truth.height; ++r)
    for (int c = 0; c < truth.width; ++c) {
      if (truth.at(c, r) != Cell::kWall) continue;
      if (!(is_free(c - 1, r) || is_free(c + 1, r) || is_free(c, r - 1) || is_free(c, r + 1)))
        continue;
      face.at(c, r) = 1;
      ++f.truth_faces;
      hit += near(result_wall, rg, tg.center_of({c, r}));
    }
  int close = 0;
  for (int r = 0; r < rg.height(); ++r)
    for (int c = 0; c < rg.width(); ++c) {
      if (!result_wall.at(c, r)) continue;
      ++f.result_walls;
      close += near(face, tg, rg.center_of({c, r}));
    }
  f.face_recall = ratio(hit, f.truth_faces);
  f.wall_precision = ratio(close, f.result_walls);
  return f;
}

Mask erode_free(const Mask& free, double cell_m, double radius_m) {
  const int k = static_cast<int>(std::floor(radius_m / cell_m + 1e-9));
  std::vector<std::pair<int, int>> disc;
  for (int dy = -k; dy <= k; ++dy)
    for (int dx = -k; dx <= k; ++dx)
      if ((dx * dx + dy * dy) * cell_m * cell_m <= radius_m * radius_m + 1e-12)
        disc.emplace_back(dx, dy);
  Mask out(free.width, free.height, 0);
  for (int r = 0; r < free.height; ++r)
    for (int c = 0; c < free.width; ++c) {
      if (!free.at(c, r)) continue;
      bool ok = true;
      for (const auto& [dx, dy] : disc)
        if (!free.contains(c + dx, r + dy) || !free.at(c + dx, r + dy)) {
          ok = false;
          break;
        }
      out.at(c, r) = ok;
    }
  return out;
}

namespace {
/// 8-connected flood from the seed cells over mask cells accepted by inside(c, r).
template <class In, class Goal>
bool flood_reaches(const Mask& m, std::deque<CellIndex> q, In inside, Goal goal) {
  Mask seen(m.width, m.height, 0);
  for (const auto& c : q) seen.at(c.col, c.row) = 1;
  while (!q.empty()) {
    const CellIndex c = q.front();
    q.pop_front();
    if (goal(c)) return true;
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        const int x = c.col + dc, y = c.row + dr;
        if (!m.contains(x, y) || seen.at(x, y) || !m.at(x, y) || !inside(x, y)) continue;
        seen.at(x, y) = 1;
        q.push_back({x, y});
      }
  }
  return false;
}
}  // namespace

DoorScores evaluate_doors(const std::vector<TruthDoor>& doors, const GridGeometry& g,
                          const Mask& free, double robot_width_m) {
  DoorScores s;
  const Mask robot = erode_free(free, g.cell_m(), robot_width_m / 2);
  for (const TruthDoor& d : doors) {
    const Eigen::Vector2d u = (d.b - d.a).normalized(), n = d.outward.normalized();
    const Eigen::Vector2d mid = (d.a + d.b) / 2;
    const double half = (d.b - d.a).norm() / 2 + 0.3, t = d.wall_thickness_m;
    auto local = [&](int c, int r) {
      const Eigen::Vector2d p = g.center_of({c, r}) - mid;
      return std::abs(p.dot(u)) <= half && p.dot(n) >= -0.6 && p.dot(n) <= t + 0.6;
    };
    auto along = [&](CellIndex c) { return (g.center_of(c) - mid).dot(n); };
    std::deque<CellIndex> seeds;
    Eigen::Vector2d lo = mid, hi = mid;
    for (double su : {-half, half})
      for (double sn : {-0.6, t + 0.6}) {
        lo = lo.cwiseMin(mid + su * u + sn * n);
        hi = hi.cwiseMax(mid + su * u + sn * n);
      }
    const CellIndex a = g.cell_of(lo), b = g.cell_of(hi);
    for (int r = std::max(0, a.row); r <= std::min(g.height() - 1, b.row); ++r)
      for (int c = std::max(0, a.col); c <= std::min(g.width() - 1, b.col); ++c)
        if (robot.at(c, r) && local(c, r) && along({c, r}) <= -0.3) seeds.push_back({c, r});
    DoorResult dr;
    dr.id = d.id;
    dr.open = !seeds.empty() &&
              flood_reaches(robot, seeds, local, [&](CellIndex c) { return along(c) >= t + 0.3; });
    s.open += dr.open;
    s.list.push_back(dr);
  }
  s.doors = static_cast<int>(doors.size());
  s.open_share = ratio(s.open, s.doors);
  return s;
}

ReachScores evaluate_reachability(const std::vector<Eigen::Vector2d>& scanners,
                                  const GridGeometry& g, const Mask& free, double robot_width_m,
                                  double snap_m) {
  ReachScores s;
  s.scanners = static_cast<int>(scanners.size());
  const Mask robot = erode_free(free, g.cell_m(), robot_width_m / 2);
  Grid<int> label(robot.width, robot.height, -1);
  int next = 0;
  const int k = static_cast<int>(std::ceil(snap_m / g.cell_m()));
  std::vector<int> used;
  for (const auto& p : scanners) {
    const CellIndex c0 = g.cell_of(p);
    CellIndex best{-1, -1};
    double best_d = snap_m * snap_m + 1e-12;
    for (int dr = -k; dr <= k; ++dr)
      for (int dc = -k; dc <= k; ++dc) {
        const int x = c0.col + dc, y = c0.row + dr;
        if (!robot.contains(x, y) || !robot.at(x, y)) continue;
        const double d2 = (g.center_of({x, y}) - p).squaredNorm();
        if (d2 < best_d) best_d = d2, best = {x, y};
      }
    if (best.col < 0) {
      s.component.push_back(-1);
      ++s.unplaced;
      continue;
    }
    if (label.at(best.col, best.row) < 0) {  // label this component
      std::deque<CellIndex> q{best};
      label.at(best.col, best.row) = next;
      while (!q.empty()) {
        const CellIndex c = q.front();
        q.pop_front();
        for (int dr = -1; dr <= 1; ++dr)
          for (int dc = -1; dc <= 1; ++dc) {
            const int x = c.col + dc, y = c.row + dr;
            if (!robot.contains(x, y) || !robot.at(x, y) || label.at(x, y) >= 0) continue;
            label.at(x, y) = next;
            q.push_back({x, y});
          }
      }
      ++next;
    }
    const int id = label.at(best.col, best.row);
    s.component.push_back(id);
    if (std::find(used.begin(), used.end(), id) == used.end()) used.push_back(id);
  }
  s.components = static_cast<int>(used.size()) + s.unplaced;
  s.all_reachable = s.scanners > 0 && s.components == 1;
  return s;
}

}  // namespace indoormap::sim
