// What a levelling rests on (issue 17): the area of floor its plane holds, how far round the
// scanner that floor reaches, how much of the horizon the scan covers. A tilt fitted to one side
// of the room tilts with that side's unevenness and the scanner's own errors; it is refused.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "indoormap/cloud/level.hpp"
#include "level_internal.hpp"

namespace indoormap::cloud {

namespace {

constexpr int kLevelSupportBins = 36;         // 10 degree sectors round a scanner
constexpr double kLevelSupportCell_m = 0.25;  // area grid of the floor support
constexpr double kLevelSupportMinRange_m = 0.3;
constexpr double kBeyondCell_m = 0.1;  // columns of beyond_share
constexpr double kBeyondGap_m = 0.3;   // beyond the inlier band and the range noise

// Share of the kLevelSupportBins sectors round `centre` (xy) that hold at least one point of
// `pts` beyond kLevelSupportMinRange_m.
double level_sector_share(const std::vector<Eigen::Vector3d>& pts, const Eigen::Vector3d& centre) {
  std::vector<std::uint8_t> bins(kLevelSupportBins, 0);
  constexpr double kTwoPi = 6.283185307179586;
  for (const auto& p : pts) {
    const Eigen::Vector2d d = (p - centre).head<2>();
    if (d.norm() < kLevelSupportMinRange_m) continue;
    const double a = std::atan2(d.y(), d.x()) + kTwoPi / 2;  // [0, 2 pi]
    bins[std::min(kLevelSupportBins - 1, static_cast<int>(a / kTwoPi * kLevelSupportBins))] = 1;
  }
  int n = 0;
  for (auto b : bins) n += b;
  return static_cast<double>(n) / kLevelSupportBins;
}

// Area of the kLevelSupportCell_m cells holding points; with dense_only, only the cells holding
// at least 1/20 of the median occupied cell's count (the room, not the sparse returns seen
// through a window tens of metres away).
double level_cell_area_m2(const std::vector<Eigen::Vector3d>& pts, bool dense_only) {
  std::vector<std::pair<long, long>> cells;
  cells.reserve(pts.size());
  for (const auto& p : pts)
    cells.emplace_back(static_cast<long>(std::floor(p.x() / kLevelSupportCell_m)),
                       static_cast<long>(std::floor(p.y() / kLevelSupportCell_m)));
  std::sort(cells.begin(), cells.end());
  std::vector<std::size_t> counts;
  for (std::size_t i = 0; i < cells.size();) {
    std::size_t j = i;
    while (j < cells.size() && cells[j] == cells[i]) ++j;
    counts.push_back(j - i);
    i = j;
  }
  std::size_t n = counts.size();
  if (dense_only && !counts.empty()) {
    std::vector<std::size_t> sorted = counts;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(n / 2),
                     sorted.end());
    const double min_count = static_cast<double>(sorted[n / 2]) / 20.0;
    n = static_cast<std::size_t>(std::count_if(counts.begin(), counts.end(), [&](std::size_t c) {
      return static_cast<double>(c) >= min_count;
    }));
  }
  return static_cast<double>(n) * kLevelSupportCell_m * kLevelSupportCell_m;
}

}  // namespace

double detail::beyond_share(const std::vector<Eigen::Vector3d>& sample, const PlaneFit& plane,
                            double inlier_m, double side) {
  if (!plane.found) return 0.0;
  // Per kBeyondCell_m column, the farthest signed distance beyond the plane on `side`.
  std::unordered_map<std::int64_t, double> farthest;
  auto key = [](const Eigen::Vector3d& q) {
    const auto cx = static_cast<std::int64_t>(std::floor(q.x() / kBeyondCell_m));
    const auto cy = static_cast<std::int64_t>(std::floor(q.y() / kBeyondCell_m));
    return cx * 4'000'037 + cy;
  };
  for (const auto& q : sample) {
    const double d = side * (plane.normal.dot(q) - plane.offset_m);
    auto [it, fresh] = farthest.try_emplace(key(q), d);
    if (!fresh) it->second = std::max(it->second, d);
  }
  std::size_t inliers = 0, beyond = 0;
  for (const auto& q : sample) {
    if (std::abs(plane.normal.dot(q) - plane.offset_m) > inlier_m) continue;
    ++inliers;
    beyond += farthest[key(q)] > kBeyondGap_m;
  }
  return inliers ? static_cast<double>(beyond) / static_cast<double>(inliers) : 0.0;
}

LevelSupport level_support(const std::vector<Eigen::Vector3d>& sample, const PlaneFit& plane,
                           double inlier_m, const std::vector<Eigen::Vector3d>& scanners) {
  LevelSupport s;
  std::vector<Eigen::Vector3d> inliers;
  if (plane.found)
    for (const auto& q : sample)
      if (std::abs(plane.normal.dot(q) - plane.offset_m) <= inlier_m) inliers.push_back(q);
  s.plane_area_m2 = level_cell_area_m2(inliers, false);
  s.cloud_area_m2 = level_cell_area_m2(sample, true);
  // With several scanners the best surrounded one counts: the others' floor fills its sectors.
  for (const auto& sc : scanners) {
    s.plane_surround_share = std::max(s.plane_surround_share, level_sector_share(inliers, sc));
    s.horizon_share = std::max(s.horizon_share, level_sector_share(sample, sc));
  }
  if (scanners.empty()) s.plane_surround_share = s.horizon_share = 1.0;  // cannot judge
  return s;
}

namespace detail {

std::string level_percent(double share) {
  return std::to_string(static_cast<int>(std::lround(100.0 * share))) + " %";
}

bool level_supported(const std::vector<Eigen::Vector3d>& sample, const LevelParams& p,
                     const std::vector<Eigen::Vector3d>& scanners, LevelResult& r) {
  const PlaneFit& plane = r.floor.found ? r.floor : r.ceiling;
  r.support = level_support(sample, plane, p.inlier_m, scanners);
  const LevelSupport& s = r.support;
  if (s.horizon_share < p.warn_horizon_share)
    r.warnings.push_back("the scan covers only " + level_percent(s.horizon_share) +
                         " of the horizon round its scanner: the map ends where it looks away");
  const double floor_share =
      r.floor.found && s.cloud_area_m2 > 0 ? s.plane_area_m2 / s.cloud_area_m2 : 0.0;
  if (floor_share < p.warn_floor_share)
    r.warnings.push_back("the floor is nearly all unseen: floor points cover " +
                         level_percent(floor_share) +
                         " of the cloud's area; the floor height found may be wrong (give "
                         "layers.floor_z_m if known)");
  if (!plane.found) return false;
  const std::string tilt = std::to_string(r.tilt_deg).substr(0, 4) + " deg";
  if (r.tilt_deg > p.max_tilt_deg) {
    r.note = "a tilt of " + tilt + " is above level.max_tilt_deg; cloud left as it is";
    return false;
  }
  const char* which = r.floor.found ? "floor" : "ceiling";
  if (s.plane_area_m2 < p.min_support_area_m2) {
    r.note = "a tilt of " + tilt + " would rest on " +
             std::to_string(s.plane_area_m2).substr(0, 4) + " m2 of " + which +
             " (level.min_support_area_m2); cloud left as it is";
    return false;
  }
  if (s.plane_surround_share < p.min_support_surround) {
    r.note = "a tilt of " + tilt + " would rest on " + which + " seen in " +
             level_percent(s.plane_surround_share) +
             " of the directions round the scanner (level.min_support_surround); cloud left as "
             "it is";
    return false;
  }
  return true;
}

}  // namespace detail

}  // namespace indoormap::cloud
