#include "indoormap/laser/raycast.hpp"

#include <string>

#include "indoormap/core/errors.hpp"

namespace indoormap::laser {

double cast_ray(const Grid<Cell>& cells, const GridGeometry& g, const Eigen::Vector2d& origin_m,
                double angle_rad, double max_range_m) {
  return cast_ray(g, origin_m, angle_rad, max_range_m,
                  [&](CellIndex c) { return is_obstacle(cells.at(c)); });
}

void ConsistencyParams::validate() const {
  auto positive = [](double v, const char* key) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw UsageError(std::string("consistency: ") + key + " must be positive");
  };
  positive(within_cells, "within_cells");
  positive(max_range_m, "max_range_m");
  positive(histogram_bin_m, "histogram_bin_m");
  positive(histogram_max_m, "histogram_max_m");
  if (histogram_max_m / histogram_bin_m > 1e8)
    throw UsageError("consistency: histogram_max_m / histogram_bin_m above 1e8 bins");
}

ConsistencyCheck::ConsistencyCheck(Grid<Cell> cells, GridGeometry geometry,
                                   ConsistencyParams params)
    : cells_(std::move(cells)), geometry_(std::move(geometry)), p_(params) {
  p_.validate();
  if (cells_.width != geometry_.width() || cells_.height != geometry_.height())
    throw UsageError("consistency: the cell grid does not match its geometry");
  histogram_.assign(static_cast<std::size_t>(p_.histogram_max_m / p_.histogram_bin_m) + 1, 0);
}

void ConsistencyCheck::add(const LaserScan& scan) {
  validate(scan);
  const Pose2d laser = scan.laser_pose_map();
  const double tol = p_.within_cells * geometry_.cell_m();
  const double reach = std::min(p_.max_range_m, scan.max_range_m);
  for (std::size_t i = 0; i < scan.size(); ++i) {
    if (!scan.is_hit(i) || scan.ranges_m[i] > reach) continue;
    const double measured = scan.ranges_m[i];
    // Cast a little beyond the measurement, so that a missing wall counts as a large error.
    const RayHit cast =
        cast_ray_cell(geometry_, laser.position_m(), laser.theta_rad + scan.beam_angle_rad(i),
                      reach + tol, [&](CellIndex c) { return is_obstacle(cells_.at(c)); });
    const double err = measured < cast.entry_m  ? cast.entry_m - measured
                       : measured > cast.exit_m ? measured - cast.exit_m
                                                : 0.0;
    ++checked_;
    if (err <= tol) ++within_;
    sum_abs_m_ += err;
    const auto bin =
        std::min(histogram_.size() - 1, static_cast<std::size_t>(err / p_.histogram_bin_m));
    ++histogram_[bin];
  }
}

ConsistencyResult ConsistencyCheck::result() const {
  ConsistencyResult r;
  r.beams_checked = checked_;
  r.beams_within = within_;
  r.within_m = p_.within_cells * geometry_.cell_m();
  if (checked_ == 0) return r;
  r.within_share = static_cast<double>(within_) / static_cast<double>(checked_);
  r.mean_abs_error_m = sum_abs_m_ / static_cast<double>(checked_);
  const std::size_t half = (checked_ + 1) / 2;  // the lower median
  std::size_t seen = 0;
  for (std::size_t b = 0; b < histogram_.size(); ++b) {
    seen += histogram_[b];
    if (seen >= half) {
      r.median_abs_error_m = (static_cast<double>(b) + 0.5) * p_.histogram_bin_m;
      break;
    }
  }
  return r;
}

}  // namespace indoormap::laser
