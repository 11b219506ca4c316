#include "indoormap/laser/occupancy.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "beam_walk.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::laser {

void OccupancyGridParams::validate() const {
  auto positive = [](double v, const char* key) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw UsageError(std::string("occupancy grid: ") + key + " must be positive, got " +
                       std::to_string(v));
  };
  positive(cell_m, "cell_m");
  positive(max_range_m, "max_range_m");
  positive(no_return_clear_m, "no_return_clear_m");
  if (hit_guard_cells < 0 || hit_guard_cells > 1000)
    throw UsageError("occupancy grid: hit_guard_cells must be in [0, 1000]");
  if (!(grow_margin_m >= 0.0) || !std::isfinite(grow_margin_m))
    throw UsageError("occupancy grid: grow_margin_m must be >= 0");
  if (max_cells <= 0) throw UsageError("occupancy grid: max_cells must be positive");
  if (fixed_geometry) {
    if (fixed_geometry->width() <= 0 || fixed_geometry->height() <= 0)
      throw UsageError("occupancy grid: fixed_geometry must have cells");
    if (fixed_geometry->cell_count() > max_cells)
      throw BudgetError("occupancy grid: fixed_geometry has " +
                        std::to_string(fixed_geometry->cell_count()) + " cells, budget " +
                        std::to_string(max_cells));
  }
}

OccupancyMap OccupancyMapper::snapshot() const {
  OccupancyMap m;
  m.geometry = geometry();
  classify(m.cells);
  m.raw = raw();
  return m;
}

namespace {
// Cell-aligned box [lo, hi] (in multiples of cell_m) as a geometry, checked against the budget.
GridGeometry aligned_box(Eigen::Vector2d lo_m, Eigen::Vector2d hi_m, double cell_m,
                         std::int64_t max_cells) {
  const double c0 = std::floor(lo_m.x() / cell_m), r0 = std::floor(lo_m.y() / cell_m);
  const double c1 = std::ceil(hi_m.x() / cell_m), r1 = std::ceil(hi_m.y() / cell_m);
  const double w = std::max(1.0, c1 - c0), h = std::max(1.0, r1 - r0);
  if (!std::isfinite(w) || !std::isfinite(h) || w * h > static_cast<double>(max_cells) ||
      w > std::numeric_limits<int>::max() / 2 || h > std::numeric_limits<int>::max() / 2)
    throw BudgetError("occupancy grid of " + std::to_string(w) + " x " + std::to_string(h) +
                      " cells exceeds the budget of " + std::to_string(max_cells) + " cells");
  return GridGeometry({c0 * cell_m, r0 * cell_m}, cell_m, static_cast<int>(w), static_cast<int>(h));
}
}  // namespace

GridGeometry bound_for_positions(const std::vector<Eigen::Vector2d>& laser_positions_m,
                                 double max_range_m, double cell_m, std::int64_t max_cells) {
  if (laser_positions_m.empty()) throw UsageError("bound_for_positions: no positions");
  Eigen::Vector2d lo = laser_positions_m.front(), hi = lo;
  for (const auto& p : laser_positions_m) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector2d r = Eigen::Vector2d::Constant(max_range_m + cell_m);
  return aligned_box(lo - r, hi + r, cell_m, max_cells);
}

namespace detail {

void compute_beam_ends(const LaserScan& scan, const OccupancyGridParams& p, BeamEnds& out) {
  const Pose2d laser = scan.laser_pose_map();
  out.origin_m = laser.position_m();
  out.end_m.clear();
  out.hit.clear();
  const double clear_m = std::min(p.no_return_clear_m, scan.max_range_m);
  for (std::size_t i = 0; i < scan.size(); ++i) {
    const bool hit = scan.is_hit(i) && scan.ranges_m[i] <= p.max_range_m;
    if (!hit && !p.clear_no_return) continue;
    const double r = hit ? static_cast<double>(scan.ranges_m[i]) : clear_m;
    const double a = laser.theta_rad + scan.beam_angle_rad(i);
    out.end_m.emplace_back(laser.x_m + r * std::cos(a), laser.y_m + r * std::sin(a));
    out.hit.push_back(hit ? 1 : 0);
  }
}

std::optional<GridGeometry> grown_geometry(const GridGeometry& g, bool empty, const BeamEnds& ends,
                                           const OccupancyGridParams& p) {
  Eigen::Vector2d lo = ends.origin_m, hi = lo;
  for (const auto& e : ends.end_m) {
    lo = lo.cwiseMin(e);
    hi = hi.cwiseMax(e);
  }
  if (!empty) {
    const Eigen::Vector2d g_lo = g.origin_m();
    const Eigen::Vector2d g_hi = g.corner_of({g.width(), g.height()});
    if (lo.x() >= g_lo.x() && lo.y() >= g_lo.y() && hi.x() < g_hi.x() && hi.y() < g_hi.y())
      return std::nullopt;
    const Eigen::Vector2d m = Eigen::Vector2d::Constant(p.grow_margin_m);
    // Grow only the sides that need it, and then by the margin; keep the other sides.
    for (int k = 0; k < 2; ++k) {
      lo[k] = lo[k] < g_lo[k] ? lo[k] - m[k] : g_lo[k];
      hi[k] = hi[k] >= g_hi[k] ? hi[k] + m[k] : g_hi[k];
    }
    // Align exactly to g's cells: round the new corner to a whole number of cells from g's.
    const double c = g.cell_m();
    const double dc = std::floor((lo.x() - g_lo.x()) / c + 1e-9),
                 dr = std::floor((lo.y() - g_lo.y()) / c + 1e-9);
    const double wc = std::ceil((hi.x() - g_lo.x()) / c - 1e-9) - dc;
    const double hr = std::ceil((hi.y() - g_lo.y()) / c - 1e-9) - dr;
    if (wc * hr > static_cast<double>(p.max_cells) || wc > (1 << 30) || hr > (1 << 30))
      throw BudgetError("occupancy grid would grow to " + std::to_string(wc) + " x " +
                        std::to_string(hr) + " cells, above the budget of " +
                        std::to_string(p.max_cells) + " cells (max_cells)");
    return GridGeometry(g_lo + Eigen::Vector2d(dc, dr) * c, c, static_cast<int>(wc),
                        static_cast<int>(hr));
  }
  const Eigen::Vector2d m = Eigen::Vector2d::Constant(p.grow_margin_m);
  return aligned_box(lo - m, hi + m, p.cell_m, p.max_cells);
}

}  // namespace detail
}  // namespace indoormap::laser
