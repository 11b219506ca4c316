#include "indoormap/laser/log_odds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "beam_walk.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::laser {

namespace {
float logit(double p) {
  return static_cast<float>(std::log(p / (1.0 - p)));
}
constexpr float kUnobserved = std::numeric_limits<float>::quiet_NaN();
}  // namespace

void LogOddsParams::validate() const {
  auto prob = [](double v, const char* key) {
    if (!(v > 0.0 && v < 1.0))
      throw UsageError(std::string("log-odds: ") + key + " must be in (0, 1), got " +
                       std::to_string(v));
  };
  prob(p_hit, "p_hit");
  prob(p_miss, "p_miss");
  prob(p_min, "p_min");
  prob(p_max, "p_max");
  prob(occupied_above_p, "occupied_above_p");
  prob(free_below_p, "free_below_p");
  if (!(p_hit > 0.5)) throw UsageError("log-odds: p_hit must be above 0.5");
  if (!(p_miss < 0.5)) throw UsageError("log-odds: p_miss must be below 0.5");
  if (!(p_min < p_max)) throw UsageError("log-odds: p_min must be below p_max");
  if (!(free_below_p <= occupied_above_p))
    throw UsageError("log-odds: free_below_p must not exceed occupied_above_p");
}

LogOddsMapper::LogOddsMapper(OccupancyGridParams grid, LogOddsParams params)
    : grid_params_(std::move(grid)), p_(params) {
  grid_params_.validate();
  p_.validate();
  l_hit_ = logit(p_.p_hit);
  l_miss_ = logit(p_.p_miss);
  l_min_ = logit(p_.p_min);
  l_max_ = logit(p_.p_max);
  l_occ_ = logit(p_.occupied_above_p);
  l_free_ = logit(p_.free_below_p);
  if (grid_params_.fixed_geometry) {
    geometry_ = *grid_params_.fixed_geometry;
    log_odds_ = Grid<float>(geometry_.width(), geometry_.height(), kUnobserved);
  }
}

void LogOddsMapper::grow_to(const GridGeometry& g) {
  if (log_odds_.size() == 0)
    log_odds_ = Grid<float>(g.width(), g.height(), kUnobserved);
  else
    detail::regrid(log_odds_, geometry_, g, kUnobserved);
  geometry_ = g;
}

void LogOddsMapper::integrate(const LaserScan& scan) {
  validate(scan);
  thread_local detail::BeamEnds ends;
  detail::compute_beam_ends(scan, grid_params_, ends);
  if (!grid_params_.fixed_geometry)
    if (auto g = detail::grown_geometry(geometry_, log_odds_.size() == 0, ends, grid_params_))
      grow_to(*g);
  float* d = log_odds_.data.data();
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const float lo = p_.clamp ? l_min_ : -kInf, hi = p_.clamp ? l_max_ : kInf;
  const float miss = l_miss_, hit = l_hit_;
  detail::walk_beams(
      ends, geometry_, grid_params_.hit_guard_cells,
      [&](std::size_t i) {
        const float v = std::isnan(d[i]) ? 0.0f : d[i];
        d[i] = std::clamp(v + miss, lo, hi);
      },
      [&](std::size_t i) {
        const float v = std::isnan(d[i]) ? 0.0f : d[i];
        d[i] = std::clamp(v + hit, lo, hi);
      });
  ++scans_;
}

float LogOddsMapper::log_odds(CellIndex c) const {
  if (!geometry_.contains(c) || log_odds_.size() == 0) return kUnobserved;
  return log_odds_.at(c);
}

Cell LogOddsMapper::classify_value(float l) const {
  if (std::isnan(l)) return Cell::kUnknown;
  if (l > l_occ_) return Cell::kWall;
  if (l < l_free_) return Cell::kFree;
  return Cell::kUnknown;
}

Cell LogOddsMapper::cell_at(CellIndex c) const {
  return classify_value(log_odds(c));
}

void LogOddsMapper::classify(Grid<Cell>& out) const {
  out = Grid<Cell>(log_odds_.width, log_odds_.height, Cell::kUnknown);
  for (std::size_t i = 0; i < log_odds_.data.size(); ++i)
    out.data[i] = classify_value(log_odds_.data[i]);
}

}  // namespace indoormap::laser
