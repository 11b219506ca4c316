#include "indoormap/sim/seen.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "indoormap/core/errors.hpp"

namespace indoormap::sim {

void validate(const SeenParams& p) {
  if (!(p.min_height_m < p.max_height_m && p.min_height_m >= -1 && p.max_height_m <= 10))
    throw UsageError("seen mask: need -1 <= min_height_m < max_height_m <= 10 (metres)");
}

namespace {

/// Marks the free cells under the part of segment o -> p (scene frame, storey z) whose height
/// lies in [z0, z1].
void walk(const TruthLayout& L, Grid<std::uint8_t>& seen, const Eigen::Vector3d& o,
          const Eigen::Vector3d& p, double z0, double z1) {
  const Eigen::Vector3d d = p - o;
  double t0 = 0.0, t1 = 1.0;
  if (d.z() != 0.0) {
    double a = (z0 - o.z()) / d.z(), b = (z1 - o.z()) / d.z();
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  } else if (o.z() < z0 || o.z() > z1) {
    return;
  }
  if (t0 > t1) return;
  // Cells crossed by the 2D segment from q0 to q1 (continuous cell coordinates): a DDA.
  const Eigen::Vector2d q0 = L.geometry.to_cell_coords((o + t0 * d).head<2>());
  const Eigen::Vector2d q1 = L.geometry.to_cell_coords((o + t1 * d).head<2>());
  const Eigen::Vector2d dq = q1 - q0;
  int x = static_cast<int>(std::floor(q0.x())), y = static_cast<int>(std::floor(q0.y()));
  const int x1 = static_cast<int>(std::floor(q1.x())), y1 = static_cast<int>(std::floor(q1.y()));
  const int sx = dq.x() > 0 ? 1 : -1, sy = dq.y() > 0 ? 1 : -1;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double tdx = dq.x() != 0 ? std::abs(1.0 / dq.x()) : kInf;
  const double tdy = dq.y() != 0 ? std::abs(1.0 / dq.y()) : kInf;
  double tx = dq.x() != 0 ? ((dq.x() > 0 ? x + 1 - q0.x() : q0.x() - x) * tdx) : kInf;
  double ty = dq.y() != 0 ? ((dq.y() > 0 ? y + 1 - q0.y() : q0.y() - y) * tdy) : kInf;
  const int w = L.geometry.width(), h = L.geometry.height();
  for (int guard = std::abs(x1 - x) + std::abs(y1 - y) + 2; guard > 0; --guard) {
    if (x >= 0 && y >= 0 && x < w && y < h && L.cells.at(x, y) == Cell::kFree) seen.at(x, y) = 1;
    if (x == x1 && y == y1) break;
    if (tx < ty) {
      x += sx;
      tx += tdx;
    } else {
      y += sy;
      ty += tdy;
    }
  }
}

}  // namespace

Grid<std::uint8_t> seen_cells(const TruthLayout& layout, const SimResult& sim, const Tilt& tilt,
                              const std::vector<int>& scanner_storey, int storey, double floor_z_m,
                              const SeenParams& params) {
  validate(params);
  Grid<std::uint8_t> seen(layout.geometry.width(), layout.geometry.height(), 0);
  const Eigen::Matrix3d Rt = tilt_rotation(tilt).transpose();  // tilted -> scene
  const Eigen::Vector3d down(0, 0, floor_z_m);
  for (const ScanBlock& b : sim.scans) {
    if (!scanner_storey.empty() && scanner_storey[b.scanner] != storey) continue;
    const Eigen::Vector3d o = Rt * sim.scanner_positions_m[b.scanner] - down;
    for (std::size_t i = b.begin; i < b.end; ++i) {
      const Eigen::Vector3d p = Rt * sim.points[i].cast<double>() - down;
      walk(layout, seen, o, p, params.min_height_m, params.max_height_m);
    }
  }
  return seen;
}

Grid<std::uint8_t> seen_image(const Grid<std::uint8_t>& seen) {
  Grid<std::uint8_t> img(seen.width, seen.height, 0);
  for (std::size_t i = 0; i < seen.data.size(); ++i) img.data[i] = seen.data[i] ? 254 : 0;
  return img;
}

std::int64_t seen_count(const Grid<std::uint8_t>& seen) {
  return std::count_if(seen.data.begin(), seen.data.end(), [](std::uint8_t v) { return v != 0; });
}

}  // namespace indoormap::sim
