#include "indoormap/laser/himm.hpp"

#include <algorithm>
#include <string>

#include "beam_walk.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::laser {

namespace {
constexpr std::uint8_t kValueMask = 0x0F;
constexpr std::uint8_t kObserved = 0x10;
}  // namespace

void HimmParams::validate() const {
  auto in = [](int v, int lo, int hi, const char* key) {
    if (v < lo || v > hi)
      throw UsageError(std::string("himm: ") + key + " must be in [" + std::to_string(lo) + ", " +
                       std::to_string(hi) + "], got " + std::to_string(v));
  };
  in(max_value, 1, 15, "max_value");
  in(initial_value, 0, max_value, "initial_value");
  in(hit_increment, 0, max_value, "hit_increment");
  in(miss_decrement, 0, max_value, "miss_decrement");
  in(occupied_above, 0, max_value, "occupied_above");
  in(free_below, 0, occupied_above + 1, "free_below");
}

HimmMapper::HimmMapper(OccupancyGridParams grid, HimmParams himm)
    : grid_params_(std::move(grid)), p_(himm) {
  grid_params_.validate();
  p_.validate();
  if (grid_params_.fixed_geometry) {
    geometry_ = *grid_params_.fixed_geometry;
    cells_ = Grid<std::uint8_t>(geometry_.width(), geometry_.height(),
                                static_cast<std::uint8_t>(p_.initial_value));
  }
}

void HimmMapper::grow_to(const GridGeometry& g) {
  const auto fill = static_cast<std::uint8_t>(p_.initial_value);
  if (cells_.size() == 0)
    cells_ = Grid<std::uint8_t>(g.width(), g.height(), fill);
  else
    detail::regrid(cells_, geometry_, g, fill);
  geometry_ = g;
}

void HimmMapper::integrate(const LaserScan& scan) {
  validate(scan);
  thread_local detail::BeamEnds ends;
  detail::compute_beam_ends(scan, grid_params_, ends);
  if (!grid_params_.fixed_geometry)
    if (auto g = detail::grown_geometry(geometry_, cells_.size() == 0, ends, grid_params_))
      grow_to(*g);
  std::uint8_t* d = cells_.data.data();
  const int maxv = p_.max_value, dec = p_.miss_decrement, inc = p_.hit_increment;
  const bool freeze = p_.freeze_at_max;
  hits_.clear();
  const int w = geometry_.width();
  detail::walk_beams(
      ends, geometry_, grid_params_.hit_guard_cells,
      [&](std::size_t i) {
        const int v = d[i] & kValueMask;
        const int nv = (freeze && v == maxv) ? v : std::max(0, v - dec);
        d[i] = static_cast<std::uint8_t>(nv | kObserved);
      },
      [&](std::size_t i) {
        const int v = std::min(maxv, (d[i] & kValueMask) + inc);
        d[i] = static_cast<std::uint8_t>(v | kObserved);
        if (p_.mask) hits_.push_back({static_cast<int>(i % w), static_cast<int>(i / w)});
      });
  for (const CellIndex& h : hits_) apply_mask(h);
  ++scans_;
}

// The paper's mask: a cell surrounded by obstacles (its four neighbours occupied) becomes an
// obstacle at full certainty. Only cells next to this scan's hits can newly qualify.
void HimmMapper::apply_mask(CellIndex h) {
  const int w = cells_.width, hgt = cells_.height;
  auto occupied = [&](int c, int r) {
    if (c < 0 || r < 0 || c >= w || r >= hgt) return false;
    const std::uint8_t v = cells_.at(c, r);
    return (v & kObserved) && (v & kValueMask) > p_.occupied_above;
  };
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc) {
      const int c = h.col + dc, r = h.row + dr;
      if (c < 0 || r < 0 || c >= w || r >= hgt) continue;
      std::uint8_t& v = cells_.at(c, r);
      if ((v & kValueMask) == p_.max_value) continue;
      if (occupied(c - 1, r) && occupied(c + 1, r) && occupied(c, r - 1) && occupied(c, r + 1))
        v = static_cast<std::uint8_t>(p_.max_value | kObserved);
    }
}

int HimmMapper::value(CellIndex c) const {
  if (!geometry_.contains(c) || cells_.size() == 0) return p_.initial_value;
  return cells_.at(c) & kValueMask;
}

bool HimmMapper::observed(CellIndex c) const {
  return geometry_.contains(c) && cells_.size() != 0 && (cells_.at(c) & kObserved);
}

Cell HimmMapper::cell_at(CellIndex c) const {
  if (!observed(c)) return Cell::kUnknown;
  const int v = cells_.at(c) & kValueMask;
  if (v > p_.occupied_above) return Cell::kWall;
  if (v < p_.free_below) return Cell::kFree;
  return Cell::kUnknown;
}

void HimmMapper::classify(Grid<Cell>& out) const {
  out = Grid<Cell>(cells_.width, cells_.height, Cell::kUnknown);
  for (std::size_t i = 0; i < cells_.data.size(); ++i) {
    const std::uint8_t b = cells_.data[i];
    if (!(b & kObserved)) continue;
    const int v = b & kValueMask;
    out.data[i] = v > p_.occupied_above ? Cell::kWall
                  : v < p_.free_below   ? Cell::kFree
                                        : Cell::kUnknown;
  }
}

Grid<float> HimmMapper::raw() const {
  Grid<float> out(cells_.width, cells_.height);
  for (std::size_t i = 0; i < cells_.data.size(); ++i)
    out.data[i] = static_cast<float>(cells_.data[i] & kValueMask);
  return out;
}

}  // namespace indoormap::laser
