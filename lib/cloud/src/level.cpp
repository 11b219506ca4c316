#include "indoormap/cloud/level.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <tuple>

#include "indoormap/core/errors.hpp"
#include "indoormap/core/parallel.hpp"
#include "level_internal.hpp"

namespace indoormap::cloud {

namespace {

constexpr double kPi = 3.14159265358979323846;
// A floor (ceiling) plane with more than this share of its points over others below (above)
// it is refused: a real one has none there but for noise and what is seen through openings
// (0.0 on the simulated scenes and the office), the planes that cut walls 0.18-0.72.
constexpr double kMaxBeyondShare = 0.1;

double deg2rad(double d) {
  return d * kPi / 180.0;
}
double rad2deg(double r) {
  return r * 180.0 / kPi;
}

std::vector<Eigen::Vector3d> stride_sample(const std::vector<Eigen::Vector3f>& points,
                                           std::size_t max_count) {
  std::vector<Eigen::Vector3d> out;
  if (points.empty() || max_count == 0) return out;
  const double step = std::max(1.0, static_cast<double>(points.size()) / max_count);
  out.reserve(std::min(points.size(), max_count));
  for (double i = 0; i < points.size(); i += step) {
    const auto& p = points[static_cast<std::size_t>(i)];
    if (p.allFinite()) out.push_back(p.cast<double>());
  }
  return out;
}

double percentile(std::vector<double> v, double pct) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(std::clamp(pct / 100.0, 0.0, 1.0) * (v.size() - 1));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}

// Share of the inliers' extent (0.25 m cells, between their 2nd and 98th x / y percentiles, so a
// few far points seen through a window do not inflate it) that holds inliers.
double fill_ratio(const std::vector<Eigen::Vector3d>& cand, const PlaneFit& f, double inlier_m) {
  constexpr double kCell = 0.25;
  std::vector<double> xs, ys;
  for (const auto& q : cand)
    if (std::abs(f.normal.dot(q) - f.offset_m) <= inlier_m) {
      xs.push_back(q.x());
      ys.push_back(q.y());
    }
  if (xs.size() < 3) return 0.0;
  const double x0 = percentile(xs, 2.0), x1 = percentile(xs, 98.0);
  const double y0 = percentile(ys, 2.0), y1 = percentile(ys, 98.0);
  const auto w = static_cast<std::size_t>((x1 - x0) / kCell) + 1;
  const auto h = static_cast<std::size_t>((y1 - y0) / kCell) + 1;
  if (w * h > 4'000'000) return 1.0;  // far beyond any room: do not judge
  std::vector<std::uint8_t> occ(w * h, 0);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    if (xs[i] < x0 || xs[i] > x1 || ys[i] < y0 || ys[i] > y1) continue;
    occ[static_cast<std::size_t>((ys[i] - y0) / kCell) * w +
        static_cast<std::size_t>((xs[i] - x0) / kCell)] = 1;
  }
  std::size_t n = 0;
  for (auto v : occ) n += v;
  return static_cast<double>(n) / static_cast<double>(w * h);
}

// RANSAC over planes within max_tilt of horizontal, then two rounds of least-squares refinement
// on the inliers. Candidates are the points of one height band.
PlaneFit fit_horizontal_plane(const std::vector<Eigen::Vector3d>& cand, const LevelParams& p,
                              std::mt19937_64& rng) {
  PlaneFit best;
  if (cand.size() < 3) return best;
  const double cos_max = std::cos(deg2rad(p.max_tilt_deg));
  std::uniform_int_distribution<std::size_t> pick(0, cand.size() - 1);
  // Hypotheses are scored on an evenly strided subset; the winner is refined on all candidates.
  std::vector<Eigen::Vector3d> score_set;
  const std::size_t stride = std::max<std::size_t>(1, cand.size() / 20000);
  for (std::size_t i = 0; i < cand.size(); i += stride) score_set.push_back(cand[i]);
  std::size_t best_count = 0;
  Eigen::Vector3d best_n = Eigen::Vector3d::UnitZ();
  double best_d = 0.0;
  for (int it = 0; it < p.iterations; ++it) {
    const auto& a = cand[pick(rng)];
    const auto& b = cand[pick(rng)];
    const auto& c = cand[pick(rng)];
    Eigen::Vector3d n = (b - a).cross(c - a);
    const double len = n.norm();
    if (len < 1e-9) continue;
    n /= len;
    if (n.z() < 0) n = -n;
    if (n.z() < cos_max) continue;
    const double d = n.dot(a);
    std::size_t count = 0;
    for (const auto& q : score_set) count += std::abs(n.dot(q) - d) <= p.inlier_m;
    if (count > best_count) {
      best_count = count;
      best_n = n;
      best_d = d;
    }
  }
  best_count *= stride;
  if (best_count < std::max<std::size_t>(3, p.min_inliers)) return best;

  Eigen::Vector3d n = best_n;
  double d = best_d;
  for (int round = 0; round < 2; ++round) {
    std::vector<Eigen::Vector3d> inl;
    inl.reserve(best_count);
    for (const auto& q : cand)
      if (std::abs(n.dot(q) - d) <= p.inlier_m) inl.push_back(q);
    PlaneFit f = fit_plane_least_squares(inl);
    if (!f.found || f.normal.z() < cos_max) break;
    n = f.normal;
    d = f.offset_m;
    best = f;
  }
  if (!best.found) {
    best.found = true;
    best.normal = n;
    best.offset_m = d;
    best.inliers = best_count;
  }
  if (fill_ratio(cand, best, p.inlier_m) < p.min_fill) return PlaneFit{};
  return best;
}

}  // namespace

PlaneFit fit_plane_least_squares(const std::vector<Eigen::Vector3d>& points) {
  PlaneFit f;
  if (points.size() < 3) return f;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& q : points) mean += q;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& q : points) {
    const Eigen::Vector3d d = q - mean;
    cov += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
  Eigen::Vector3d n = es.eigenvectors().col(0);  // smallest eigenvalue
  if (n.z() < 0) n = -n;
  f.found = true;
  f.normal = n.normalized();
  f.offset_m = f.normal.dot(mean);
  f.inliers = points.size();
  double ss = 0.0;
  for (const auto& q : points) ss += std::pow(f.normal.dot(q) - f.offset_m, 2);
  f.rms_m = std::sqrt(ss / static_cast<double>(points.size()));
  std::vector<double> xs, ys;
  xs.reserve(points.size());
  ys.reserve(points.size());
  for (const auto& q : points) xs.push_back(q.x()), ys.push_back(q.y());
  f.extent_m = std::hypot(percentile(xs, 98.0) - percentile(xs, 2.0),
                          percentile(ys, 98.0) - percentile(ys, 2.0));
  return f;
}

void validate(const LevelParams& lv) {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw UsageError(std::string("invalid parameter ") + what);
  };
  require(lv.max_tilt_deg > 0 && lv.max_tilt_deg < 90, "level.max_tilt_deg: must be in (0, 90)");
  require(lv.band_m > 0, "level.band_m: must be > 0");
  require(lv.peak_fraction > 0 && lv.peak_fraction <= 1, "level.peak_fraction: must be in (0, 1]");
  require(lv.inlier_m > 0, "level.inlier_m: must be > 0");
  require(lv.iterations > 0 && lv.iterations <= 100000, "level.iterations: must be in [1, 100000]");
  require(lv.sample_points >= 3 && lv.sample_points <= 100'000'000,
          "level.sample_points: must be in [3, 1e8]");
  require(lv.min_fill >= 0 && lv.min_fill <= 1, "level.min_fill: must be in [0, 1]");
  require(lv.min_support_area_m2 >= 0, "level.min_support_area_m2: must be >= 0");
  require(lv.min_support_surround >= 0 && lv.min_support_surround <= 1,
          "level.min_support_surround: must be in [0, 1]");
  require(lv.warn_horizon_share >= 0 && lv.warn_horizon_share <= 1,
          "level.warn_horizon_share: must be in [0, 1]");
  require(lv.warn_floor_share >= 0 && lv.warn_floor_share <= 1,
          "level.warn_floor_share: must be in [0, 1]");
}

LevelResult estimate_level(const std::vector<Eigen::Vector3f>& points, const LevelParams& params,
                           const std::vector<Eigen::Vector3d>& scanners) {
  validate(params);
  LevelResult r;
  if (!params.enabled) {
    r.note = "levelling disabled";
    return r;
  }
  const auto sample = stride_sample(points, params.sample_points);
  if (sample.size() < 3) {
    r.note = "too few points to level";
    return r;
  }
  // Floor and ceiling heights from a 0.1 m height histogram: the lowest and the highest bins
  // holding peak_fraction of the fullest bin. Percentiles would not do: points seen through
  // windows can lie metres above the ceiling and be more than 1 % of the cloud.
  std::vector<double> zs;
  zs.reserve(sample.size());
  for (const auto& q : sample) zs.push_back(q.z());
  const double h_lo = percentile(zs, 0.1), h_hi = percentile(zs, 99.9);
  const std::size_t bins = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::ceil((h_hi - h_lo) / 0.1)) + 1, 1, 10000);
  const double bin_m = std::max(0.1, (h_hi - h_lo) / static_cast<double>(bins));
  std::vector<std::size_t> hist(bins, 0);
  for (double z : zs)
    if (z >= h_lo && z <= h_hi)
      ++hist[std::min(bins - 1, static_cast<std::size_t>((z - h_lo) / bin_m))];
  const std::size_t peak = *std::max_element(hist.begin(), hist.end());
  std::size_t first = 0, last = bins - 1;
  while (first < bins - 1 && hist[first] < params.peak_fraction * peak) ++first;
  while (last > first && hist[last] < params.peak_fraction * peak) --last;
  const double z_floor = h_lo + (first + 0.5) * bin_m, z_ceiling = h_lo + (last + 0.5) * bin_m;

  std::vector<Eigen::Vector3d> low, high;
  for (const auto& q : sample) {
    if (q.z() >= z_floor - 0.5 * params.band_m && q.z() <= z_floor + params.band_m)
      low.push_back(q);
    if (q.z() <= z_ceiling + 0.5 * params.band_m && q.z() >= z_ceiling - params.band_m)
      high.push_back(q);
  }
  std::mt19937_64 rng(params.seed);
  r.floor = fit_horizontal_plane(low, params, rng);
  // A ceiling must lie well above the floor; with a flat cloud both bands are the same points.
  if (z_ceiling - z_floor > 2.0 * params.band_m)
    r.ceiling = fit_horizontal_plane(high, params, rng);

  // A plane with points beyond it cuts through walls: no floor or ceiling (a 16-beam lidar in a
  // small room, whose lowest row, 15 degrees down, meets the floor only 4-6 m away: its rows
  // cross the walls along curves that planes fit within the inlier band).
  for (auto [plane, name, side] :
       {std::tuple{&r.floor, "floor", -1.0}, std::tuple{&r.ceiling, "ceiling", 1.0}}) {
    if (!plane->found) continue;
    const double share = detail::beyond_share(sample, *plane, params.inlier_m, side);
    if (share <= kMaxBeyondShare) continue;
    plane->found = false;
    r.warnings.push_back(std::string("the ") + name + " plane found has " +
                         detail::level_percent(share) + " of its points over other points " +
                         (side < 0 ? "below" : "above") +
                         " it: it cuts through walls, not used for levelling");
  }

  Eigen::Vector3d up;
  if (r.floor.found && r.ceiling.found) {
    const double angle =
        rad2deg(std::acos(std::clamp(r.floor.normal.dot(r.ceiling.normal), -1.0, 1.0)));
    // Where the two disagree by more than the tilt that moves the floor's far ends by
    // inlier_m (0.06 degrees across a 30 m building), a ceiling that fits its points worse than
    // the floor does (larger RMS) is no single flat surface: the rooms of a building at several
    // heights, which tilted the 12-room building 0.33-0.63 degrees off its floor and put the
    // floor's far end 7 cm high. Then the floor alone decides.
    const double level_deg = rad2deg(std::atan2(params.inlier_m, r.floor.extent_m));
    if (angle > level_deg && angle <= params.max_normal_disagreement_deg &&
        r.ceiling.rms_m > r.floor.rms_m) {
      up = r.floor.normal;
      r.note = "floor plane only (the ceiling plane, " + std::to_string(angle) +
               " deg off the floor, fits its points worse: RMS " + std::to_string(r.ceiling.rms_m) +
               " m against " + std::to_string(r.floor.rms_m) + " m)";
    } else if (angle <= params.max_normal_disagreement_deg) {
      up = (r.floor.normal * static_cast<double>(r.floor.inliers) +
            r.ceiling.normal * static_cast<double>(r.ceiling.inliers))
               .normalized();
      r.note = "floor and ceiling planes";
    } else {
      up = r.floor.normal;
      r.note =
          "floor plane only (ceiling not parallel to floor: " + std::to_string(angle) + " deg)";
    }
  } else if (r.floor.found) {
    up = r.floor.normal;
    r.note = "floor plane only (no ceiling plane found)";
  } else if (r.ceiling.found) {
    up = r.ceiling.normal;
    r.note = "ceiling plane only (no floor plane found)";
  } else {
    r.note = "no near-horizontal floor or ceiling plane found; cloud left as it is";
    detail::level_supported(sample, params, scanners, r);  // for the warnings
    return r;
  }
  r.tilt_deg = rad2deg(std::acos(std::clamp(up.z(), -1.0, 1.0)));
  if (!detail::level_supported(sample, params, scanners, r)) {
    r.tilt_deg = 0.0;  // refused: the rotation is the identity (the note names the tilt)
    return r;
  }
  r.levelled = true;
  r.up_input = up;
  r.map_from_input =
      Eigen::Quaterniond::FromTwoVectors(up, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return r;
}

void rotate(PointCloud& cloud, const Eigen::Matrix3d& rotation) {
  const Eigen::Matrix3f rf = rotation.cast<float>();
  parallel_parts(cloud.points.size(), 1 << 20, [&](std::size_t i0, std::size_t i1) {
    for (std::size_t i = i0; i < i1; ++i) cloud.points[i] = rf * cloud.points[i];
    return 0;
  });
  for (auto& s : cloud.scanners) s = rotation * s;
}

}  // namespace indoormap::cloud
