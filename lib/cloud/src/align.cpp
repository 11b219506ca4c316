#include "indoormap/cloud/align.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "indoormap/core/errors.hpp"

namespace indoormap::cloud {

namespace {

constexpr double kAlignPi = 3.14159265358979323846;
constexpr double kAlignSlice_m = 0.2;          // height slices of the wall test
constexpr int kAlignMaxSlices = 64;            // one bit each
constexpr double kAlignMaxCells = 4e6;         // plan grid of the wall test
constexpr double kAlignMargin_m = 2.0;         // round the 0.5-99.5 % extent of the sample
constexpr std::size_t kAlignMaxWall = 60000;   // wall points scored (evenly strided)
constexpr double kAlignCoarseStep_deg = 0.25;  // coarse scan over [0, 90)
constexpr double kAlignCoarseBin_m = 0.05;     // its histogram bins
constexpr double kAlignFineStep_deg = 0.01;    // fine scan over +-2 coarse steps
constexpr double kAlignFineBin_m = 0.01;       // its histogram bins

double align_percentile(std::vector<double> v, double share) {
  const auto k = static_cast<std::size_t>(std::clamp(share, 0.0, 1.0) * (v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// Points of the levelled sample standing in wall cells (see the header), centred on their mean.
std::vector<Eigen::Vector2d> wall_points(const std::vector<Eigen::Vector3d>& s,
                                         const WallAlignParams& p) {
  std::vector<double> xs, ys, zs;
  for (const auto& q : s) {
    xs.push_back(q.x());
    ys.push_back(q.y());
    zs.push_back(q.z());
  }
  const double x0 = align_percentile(xs, 0.005) - kAlignMargin_m;
  const double x1 = align_percentile(xs, 0.995) + kAlignMargin_m;
  const double y0 = align_percentile(ys, 0.005) - kAlignMargin_m;
  const double y1 = align_percentile(ys, 0.995) + kAlignMargin_m;
  const double z0 = align_percentile(zs, 0.005), z1 = align_percentile(zs, 0.995);
  const double cell = std::max(p.cell_m, std::sqrt((x1 - x0) * (y1 - y0) / kAlignMaxCells));
  const double slice = std::max(kAlignSlice_m, (z1 - z0) / kAlignMaxSlices);
  const auto w = static_cast<std::int64_t>((x1 - x0) / cell) + 1;
  const auto h = static_cast<std::int64_t>((y1 - y0) / cell) + 1;
  std::vector<std::uint64_t> slices(static_cast<std::size_t>(w * h), 0);
  auto cell_of = [&](const Eigen::Vector3d& q) -> std::int64_t {
    if (q.x() < x0 || q.x() > x1 || q.y() < y0 || q.y() > y1) return -1;
    const auto c = std::min(w - 1, static_cast<std::int64_t>((q.x() - x0) / cell));
    const auto r = std::min(h - 1, static_cast<std::int64_t>((q.y() - y0) / cell));
    return r * w + c;
  };
  for (const auto& q : s) {
    const auto i = cell_of(q);
    if (i < 0 || q.z() < z0 || q.z() > z1) continue;
    const int k = std::min(kAlignMaxSlices - 1, static_cast<int>((q.z() - z0) / slice));
    slices[static_cast<std::size_t>(i)] |= std::uint64_t{1} << k;
  }
  const int min_slices = std::max(2, static_cast<int>(std::ceil(p.min_wall_height_m / slice)));
  std::vector<Eigen::Vector2d> out;
  for (const auto& q : s) {
    const auto i = cell_of(q);
    if (i >= 0 && std::popcount(slices[static_cast<std::size_t>(i)]) >= min_slices)
      out.emplace_back(q.x(), q.y());
  }
  if (out.size() > kAlignMaxWall) {  // evenly strided, deterministic
    std::vector<Eigen::Vector2d> kept;
    const double step = static_cast<double>(out.size()) / kAlignMaxWall;
    for (double i = 0; i < static_cast<double>(out.size()); i += step)
      kept.push_back(out[static_cast<std::size_t>(i)]);
    out.swap(kept);
  }
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& q : out) mean += q;
  if (!out.empty()) mean /= static_cast<double>(out.size());
  for (auto& q : out) q -= mean;
  return out;
}

// Sharpness of the projections of pts onto the axes turned by deg: the sum of the squared
// (linearly splatted) histogram counts of both, over the squared point count.
class Sharpness {
 public:
  Sharpness(const std::vector<Eigen::Vector2d>& pts, double bin_m) : pts_(pts), bin_m_(bin_m) {
    for (const auto& q : pts) radius_m_ = std::max(radius_m_, q.norm());
    hist_.resize(static_cast<std::size_t>(2.0 * radius_m_ / bin_m) + 3);
  }
  double operator()(double deg) {
    const double a = deg * kAlignPi / 180.0, c = std::cos(a), s = std::sin(a);
    double sum = 0.0;
    for (int axis = 0; axis < 2; ++axis) {
      std::fill(hist_.begin(), hist_.end(), 0.0);
      for (const auto& q : pts_) {
        const double u = axis == 0 ? c * q.x() + s * q.y() : -s * q.x() + c * q.y();
        const double t = (u + radius_m_) / bin_m_;
        const auto i = static_cast<std::size_t>(t);
        const double f = t - static_cast<double>(i);
        hist_[i] += 1.0 - f;
        hist_[i + 1] += f;
      }
      for (double v : hist_) sum += v * v;
    }
    const double n = static_cast<double>(pts_.size());
    return sum / (n * n);
  }

 private:
  const std::vector<Eigen::Vector2d>& pts_;
  double bin_m_;
  double radius_m_ = 0.0;
  std::vector<double> hist_;
};

// The angle in (-45, 45] equal to deg modulo 90.
double wrap_quarter(double deg) {
  double a = std::fmod(deg, 90.0);
  if (a <= -45.0) a += 90.0;
  if (a > 45.0) a -= 90.0;
  return a;
}

}  // namespace

void validate(const WallAlignParams& p) {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw UsageError(std::string("invalid parameter ") + what);
  };
  require(p.cell_m > 0 && p.cell_m <= 1.0, "align_walls.cell_m: must be in (0, 1]");
  require(p.min_wall_height_m > 0 && p.min_wall_height_m <= 10.0,
          "align_walls.min_wall_height_m: must be in (0, 10]");
  require(p.sample_points >= 100 && p.sample_points <= 100'000'000,
          "align_walls.sample_points: must be in [100, 1e8]");
  require(p.min_wall_points >= 10, "align_walls.min_wall_points: must be >= 10");
  require(p.min_confidence >= 0 && p.min_confidence < 1,
          "align_walls.min_confidence: must be in [0, 1)");
}

Eigen::Matrix3d yaw_rotation(double yaw_deg) {
  const double a = yaw_deg * kAlignPi / 180.0;
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  r(0, 0) = std::cos(a);
  r(0, 1) = -std::sin(a);
  r(1, 0) = std::sin(a);
  r(1, 1) = std::cos(a);
  return r;
}

double yaw_of(const Eigen::Matrix3d& r) {
  return std::atan2(r(1, 0), r(0, 0)) * 180.0 / kAlignPi;
}

WallAlignResult estimate_wall_alignment(const std::vector<Eigen::Vector3f>& points,
                                        const WallAlignParams& params,
                                        const Eigen::Matrix3d& levelled_from_input) {
  validate(params);
  WallAlignResult r;
  if (!params.enabled) {
    r.note = "wall alignment disabled";
    return r;
  }
  std::vector<Eigen::Vector3d> sample;
  const double step =
      std::max(1.0, static_cast<double>(points.size()) / static_cast<double>(params.sample_points));
  for (double i = 0; i < static_cast<double>(points.size()); i += step) {
    const auto& q = points[static_cast<std::size_t>(i)];
    if (q.allFinite()) sample.push_back(levelled_from_input * q.cast<double>());
  }
  const auto walls =
      sample.size() < 3 ? std::vector<Eigen::Vector2d>{} : wall_points(sample, params);
  r.wall_points = walls.size();
  if (walls.size() < params.min_wall_points) {
    r.note = "too few wall points (" + std::to_string(walls.size()) +
             ", align_walls.min_wall_points " + std::to_string(params.min_wall_points) +
             "); map left in the scan's frame";
    return r;
  }
  Sharpness coarse(walls, kAlignCoarseBin_m);
  const int n = static_cast<int>(std::lround(90.0 / kAlignCoarseStep_deg));
  std::vector<double> scores(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k)
    scores[static_cast<std::size_t>(k)] = coarse(k * kAlignCoarseStep_deg);
  const auto best = std::max_element(scores.begin(), scores.end());
  std::vector<double> sorted = scores;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  r.confidence = *best > 0 ? (*best - sorted[static_cast<std::size_t>(n / 2)]) / *best : 0.0;
  const double coarse_deg = static_cast<double>(best - scores.begin()) * kAlignCoarseStep_deg;

  Sharpness fine(walls, kAlignFineBin_m);
  const int m = static_cast<int>(std::lround(2.0 * kAlignCoarseStep_deg / kAlignFineStep_deg));
  std::vector<double> fs;
  for (int k = -m; k <= m; ++k) fs.push_back(fine(coarse_deg + k * kAlignFineStep_deg));
  const auto fb = static_cast<int>(std::max_element(fs.begin(), fs.end()) - fs.begin());
  double offset = 0.0;  // parabola through the best and its neighbours
  if (fb > 0 && fb + 1 < static_cast<int>(fs.size())) {
    const double a = fs[static_cast<std::size_t>(fb - 1)], b = fs[static_cast<std::size_t>(fb)],
                 c = fs[static_cast<std::size_t>(fb + 1)];
    const double den = a - 2.0 * b + c;
    if (den < 0) offset = std::clamp(0.5 * (a - c) / den, -0.5, 0.5);
  }
  r.direction_deg = wrap_quarter(coarse_deg + (fb - m + offset) * kAlignFineStep_deg);
  char text[160];
  if (r.confidence < params.min_confidence) {
    std::snprintf(text, sizeof text,
                  "no dominant wall direction (confidence %.2f < align_walls.min_confidence "
                  "%.2f); map left in the scan's frame",
                  r.confidence, params.min_confidence);
    r.note = text;
    return r;
  }
  r.applied = true;
  r.yaw_deg = -r.direction_deg;
  r.rotation = yaw_rotation(r.yaw_deg);
  std::snprintf(text, sizeof text, "walls at %.3f deg (confidence %.2f, %zu wall points)",
                r.direction_deg, r.confidence, r.wall_points);
  r.note = text;
  return r;
}

}  // namespace indoormap::cloud
