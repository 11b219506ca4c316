#include "indoormap/sim/mobile.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "indoormap/core/errors.hpp"
#include "simulate_detail.hpp"

namespace indoormap::sim {

namespace {
constexpr double kGolden = 0.6180339887498949;

int columns(const Scene& scene, const MobileParams& p) {
  const ScannerParams& s = scene.scanner;
  const double n_az = std::max(1.0, std::floor(360.0 / s.azimuth_step_deg + 1e-9));
  const double n_el =
      std::floor((s.elevation_max_deg - s.elevation_min_deg) / s.elevation_step_deg + 1e-9) + 1;
  return std::max(1, static_cast<int>(std::lround(p.ray_share * n_az * n_el / p.beams)));
}
}  // namespace

void validate(const MobileParams& p) {
  if (!(p.step_m >= 0.05 && p.step_m <= 10))
    throw UsageError("mobile step must be in [0.05, 10] m");
  if (!(p.ray_share > 0 && p.ray_share <= 1))
    throw UsageError("mobile ray share must be in (0, 1]");
  if (p.beams < 1 || p.beams > 128) throw UsageError("mobile beams must be in [1, 128]");
  if (!(p.elevation_min_deg >= -90 && p.elevation_min_deg < p.elevation_max_deg &&
        p.elevation_max_deg <= 90))
    throw UsageError("mobile fan: need -90 <= elevation_min_deg < elevation_max_deg <= 90");
  if (!(p.sensor_height_m >= 0.1 && p.sensor_height_m <= 3))
    throw UsageError("mobile sensor height must be in [0.1, 3] m");
  if (!(p.clearance_m >= 0 && p.clearance_m <= 2))
    throw UsageError("mobile clearance must be in [0, 2] m");
  if (!(p.speed_m_s > 0 && p.speed_m_s <= 100))
    throw UsageError("mobile speed must be in (0, 100] m/s");
}

std::uint64_t mobile_ray_count(const Scene& scene, const MobileParams& p) {
  return static_cast<std::uint64_t>(columns(scene, p)) * static_cast<std::uint64_t>(p.beams) *
         scene.scanners.size();
}

SimResult simulate_mobile(const Scene& input, const MobileParams& p, const SimOptions& options) {
  validate(p);
  require_valid(input);
  const Scene scene = normalised(input);
  const int n_col = columns(scene, p);
  const double spacing = (p.elevation_max_deg - p.elevation_min_deg) / p.beams;
  SimOptions opt = options;
  opt.sector_deg = 0;  // one scan per position
  return detail::simulate_pattern(scene, opt, mobile_ray_count(scene, p), [&](std::size_t k) {
    detail::RayPattern pat;
    const double phase = std::fmod(static_cast<double>(k) * kGolden, 1.0);
    for (int j = 0; j < p.beams; ++j)
      pat.elevation_deg.push_back(p.elevation_min_deg + (j + phase) * spacing);
    pat.azimuths = n_col;
    pat.azimuth_step_deg = 360.0 / n_col;
    pat.azimuth_offset_deg =
        std::fmod(static_cast<double>(k) * (1 - kGolden), 1.0) * pat.azimuth_step_deg;
    return pat;
  });
}

std::vector<TrajectoryPose> trajectory(const std::vector<ScannerPose>& scanners, const Tilt& tilt,
                                       double speed_m_s, double t0_s) {
  const Eigen::Matrix3d R = tilt_rotation(tilt);
  std::vector<TrajectoryPose> out;
  double t = t0_s;
  for (std::size_t i = 0; i < scanners.size(); ++i) {
    if (i > 0) t += (scanners[i].position_m - scanners[i - 1].position_m).norm() / speed_m_s;
    TrajectoryPose tp;
    tp.t_s = t;
    tp.position_m = R * scanners[i].position_m;
    const Eigen::Quaterniond yaw(Eigen::AngleAxisd(
        scanners[i].heading_deg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ()));
    tp.orientation = yaw;  // the ray pattern is regular in the tilted frame (simulate.hpp)
    out.push_back(tp);
  }
  return out;
}

}  // namespace indoormap::sim
