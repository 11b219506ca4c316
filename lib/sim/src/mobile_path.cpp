// plan_mobile_path: a tour over the truth free space (docs/scene-sim.md, "Mobile scanner").
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>

#include "indoormap/core/errors.hpp"
#include "indoormap/sim/mobile.hpp"

namespace indoormap::sim {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

/// Distance (metres, 3-4 chamfer) from every cell to the nearest cell that is not free.
std::vector<double> clearance_map(const TruthLayout& L) {
  const int w = L.geometry.width(), h = L.geometry.height();
  const double c = L.geometry.cell_m();
  std::vector<double> d(static_cast<std::size_t>(w) * h);
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = L.cells.data[i] == Cell::kFree ? kInf : 0.0;
  const double a = c, b = c * std::numbers::sqrt2;
  auto at = [&](int x, int y) -> double& { return d[static_cast<std::size_t>(y) * w + x]; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double& v = at(x, y);
      if (x == 0 || y == 0 || x == w - 1 || y == h - 1) v = std::min(v, 0.0);
      if (x > 0) v = std::min(v, at(x - 1, y) + a);
      if (y > 0) v = std::min(v, at(x, y - 1) + a);
      if (x > 0 && y > 0) v = std::min(v, at(x - 1, y - 1) + b);
      if (x < w - 1 && y > 0) v = std::min(v, at(x + 1, y - 1) + b);
    }
  for (int y = h - 1; y >= 0; --y)
    for (int x = w - 1; x >= 0; --x) {
      double& v = at(x, y);
      if (x < w - 1) v = std::min(v, at(x + 1, y) + a);
      if (y < h - 1) v = std::min(v, at(x, y + 1) + a);
      if (x < w - 1 && y < h - 1) v = std::min(v, at(x + 1, y + 1) + b);
      if (x > 0 && y < h - 1) v = std::min(v, at(x - 1, y + 1) + b);
    }
  return d;
}

/// Dijkstra over cells with clearance >= min_clear from start; returns parents (-1: none).
struct Search {
  std::vector<double> dist;
  std::vector<int> parent;
};
Search dijkstra(int w, int h, const std::vector<double>& clear, double min_clear, int start,
                double cell_m) {
  Search s;
  s.dist.assign(clear.size(), kInf);
  s.parent.assign(clear.size(), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> q;
  s.dist[start] = 0;
  q.push({0.0, start});
  while (!q.empty()) {
    const auto [d, i] = q.top();
    q.pop();
    if (d > s.dist[i]) continue;
    const int x = i % w, y = i / w;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || x + dx < 0 || y + dy < 0 || x + dx >= w || y + dy >= h)
          continue;
        const int j = (y + dy) * w + x + dx;
        if (clear[j] < min_clear) continue;
        const double nd = d + cell_m * ((dx != 0 && dy != 0) ? std::numbers::sqrt2 : 1.0);
        if (nd < s.dist[j]) {
          s.dist[j] = nd;
          s.parent[j] = i;
          q.push({nd, j});
        }
      }
  }
  return s;
}

/// The free cell of the polygon with the largest clearance (first in raster order); -1 if none.
int best_cell(const TruthLayout& L, const std::vector<double>& clear, const Polygon& poly,
              const Eigen::Vector2d& prefer_dir) {
  const auto [lo, hi] = bounds(poly);
  const CellIndex a = L.geometry.cell_of(lo), b = L.geometry.cell_of(hi);
  int best = -1;
  double best_c = 0, best_key = kInf;
  for (int r = std::max(0, a.row); r <= std::min(L.geometry.height() - 1, b.row); ++r)
    for (int c = std::max(0, a.col); c <= std::min(L.geometry.width() - 1, b.col); ++c) {
      const int i = r * L.geometry.width() + c;
      const Eigen::Vector2d p = L.geometry.center_of({c, r});
      if (clear[i] <= 0 || !contains(poly, p)) continue;
      // Clearance first (to 1 cm); among equals the smallest projection on prefer_dir.
      const double cl = std::floor(clear[i] * 100) / 100, key = prefer_dir.dot(p);
      if (cl > best_c || (cl == best_c && key < best_key)) {
        best = i;
        best_c = cl;
        best_key = key;
      }
    }
  return best;
}
}  // namespace

MobilePath plan_mobile_path(const Scene& scene, const TruthLayout& L, const MobileParams& p) {
  validate(p);
  const int w = L.geometry.width(), h = L.geometry.height();
  const std::vector<double> clear = clearance_map(L);
  // Start: the west end of the corridor's centre line (the corridor's first edge points east);
  // without a corridor, the best cell of the first room.
  int start = -1;
  std::vector<int> targets;
  for (const Room& room : scene.rooms) {
    const Eigen::Vector2d dir = room.polygon.size() >= 2
                                    ? (room.polygon[1] - room.polygon[0]).normalized()
                                    : Eigen::Vector2d::UnitX();
    const int cell = best_cell(L, clear, room.polygon, dir);
    if (room.kind == RoomKind::kCorridor && start < 0)
      start = cell;
    else if (cell >= 0)
      targets.push_back(cell);
  }
  MobilePath out;
  if (start < 0 && !targets.empty()) {
    start = targets.front();
    targets.erase(targets.begin());
  }
  if (start < 0) return out;
  std::vector<int> cells{start};
  std::vector<bool> done(targets.size(), false);
  const double clearances[] = {p.clearance_m, 0.3, 0.2, 0.1};
  int current = start;
  for (;;) {
    int pick = -1;
    Search s;
    const bool all_done = std::all_of(done.begin(), done.end(), [](bool b) { return b; });
    for (double c : clearances) {
      if (c > p.clearance_m) continue;
      s = dijkstra(w, h, clear, std::min(c, clear[current]), current, L.geometry.cell_m());
      if (all_done) {
        pick = s.dist[start] < kInf ? -2 : -1;
      } else {
        double best = kInf;
        for (std::size_t k = 0; k < targets.size(); ++k)
          if (!done[k] && s.dist[targets[k]] < best)
            best = s.dist[targets[k]], pick = static_cast<int>(k);
      }
      if (pick != -1) break;
    }
    if (pick == -1) break;
    const int goal = pick == -2 ? start : targets[pick];
    std::vector<int> leg;
    for (int i = goal; i != current && i >= 0; i = s.parent[i]) leg.push_back(i);
    cells.insert(cells.end(), leg.rbegin(), leg.rend());
    current = goal;
    if (pick == -2) break;
    done[pick] = true;
    ++out.rooms_visited;
  }
  out.unreached = static_cast<int>(std::count(done.begin(), done.end(), false));
  // Resample the cell polyline every step_m.
  std::vector<Eigen::Vector2d> pts;
  for (int i : cells) pts.push_back(L.geometry.center_of({i % w, i / w}));
  std::vector<Eigen::Vector2d> samples{pts.front()};
  double carry = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const double seg = (pts[i] - pts[i - 1]).norm();
    out.length_m += seg;
    double t = p.step_m - carry;
    while (t <= seg + 1e-12) {
      samples.push_back(pts[i - 1] + (pts[i] - pts[i - 1]) * (t / seg));
      t += p.step_m;
    }
    carry = seg - (t - p.step_m);
  }
  for (std::size_t i = 0; i < samples.size(); ++i) {
    Eigen::Vector2d d = Eigen::Vector2d::UnitX();
    if (i + 1 < samples.size())
      d = samples[i + 1] - samples[i];
    else if (i > 0)
      d = samples[i] - samples[i - 1];
    if (room_at(scene, samples[i]) < 0) continue;  // inside a door opening
    ScannerPose sp;
    sp.position_m = Eigen::Vector3d(samples[i].x(), samples[i].y(), p.sensor_height_m);
    sp.heading_deg = std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
    out.poses.push_back(sp);
  }
  return out;
}

}  // namespace indoormap::sim
