#include "indoormap/sim/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "indoormap/core/angles.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/sim/world.hpp"
#include "simulate_detail.hpp"

namespace indoormap::sim {

namespace {

std::uint64_t splitmix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
std::uint64_t rotl(std::uint64_t x, int k) {
  return (x << k) | (x >> (64 - k));
}

int azimuth_count(const ScannerParams& s) {
  return std::max(1, static_cast<int>(std::floor(360.0 / s.azimuth_step_deg + 1e-9)));
}
int elevation_count(const ScannerParams& s) {
  return static_cast<int>(std::floor(
             (s.elevation_max_deg - s.elevation_min_deg) / s.elevation_step_deg + 1e-9)) +
         1;
}
}  // namespace

Rng::Rng(std::uint64_t seed) {
  for (auto& s : s_) s = splitmix64(seed);
}

std::uint64_t Rng::next() {
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

double Rng::uniform() {
  return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

int Rng::uniform_int(int lo, int hi) {
  const std::uint64_t span = static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - lo) + 1;
  return lo + static_cast<int>(next() % span);
}

double Rng::normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  double u, v, s;
  do {
    u = 2.0 * uniform() - 1.0;
    v = 2.0 * uniform() - 1.0;
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double f = std::sqrt(-2.0 * std::log(s) / s);
  spare_ = v * f;
  has_spare_ = true;
  return u * f;
}

std::uint64_t ray_count(const Scene& scene) {
  return static_cast<std::uint64_t>(azimuth_count(scene.scanner)) *
         static_cast<std::uint64_t>(elevation_count(scene.scanner)) * scene.scanners.size();
}

namespace detail {

SimResult simulate_pattern(const Scene& scene, const SimOptions& options, std::uint64_t rays,
                           const PatternFn& pattern) {
  const ScannerParams& sp = scene.scanner;
  if (rays > options.max_rays)
    throw BudgetError("scene: " + std::to_string(rays) + " rays exceed the budget of " +
                      std::to_string(options.max_rays) +
                      " (coarser scanner.azimuth_step_deg / elevation_step_deg?)");

  const SceneGeometry geometry = build_geometry(scene);
  RayCaster caster(geometry);
  const Eigen::Matrix3d R = tilt_rotation(scene.tilt);  // scene -> tilted
  const Eigen::Matrix3d Rt = R.transpose();
  const double sector =
      options.sector_deg > 0 && options.sector_deg < 360 ? options.sector_deg : 360.0;
  const int n_sectors = static_cast<int>(std::ceil(360.0 / sector - 1e-9));

  SimResult out;
  out.rays = rays;
  out.points.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(rays, 50'000'000)));
  Rng rng(scene.seed);
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> prev_col, cur_col, cos_el, sin_el;
  ProgressTicker ticker(options.progress, static_cast<std::int64_t>(rays), 100'000);

  for (std::size_t s = 0; s < scene.scanners.size(); ++s) {
    const RayPattern pat = pattern(s);
    const int n_az = pat.azimuths, n_el = static_cast<int>(pat.elevation_deg.size());
    cos_el.resize(n_el);
    sin_el.resize(n_el);
    for (int j = 0; j < n_el; ++j) {
      const double el = pat.elevation_deg[j] * kDeg;
      cos_el[j] = std::cos(el);
      sin_el[j] = std::sin(el);
    }
    prev_col.assign(n_el, kNone);
    cur_col.assign(n_el, kNone);
    // A mixed pixel is one beam's footprint straddling a depth edge: only a neighbour ray within
    // the footprint's scale (twice the terrestrial step) tells of one. The mobile pattern's rows
    // lie degrees apart: two floor returns of neighbouring rows differ by more than the jump
    // without any edge between them (a phantom point 0.1-0.3 m above the floor).
    const double adjacent_deg = 2.0 * std::max(sp.azimuth_step_deg, sp.elevation_step_deg);
    std::vector<std::uint8_t> row_adjacent(static_cast<std::size_t>(n_el), 0);
    for (int j = 1; j < n_el; ++j)
      row_adjacent[static_cast<std::size_t>(j)] =
          std::abs(pat.elevation_deg[j] - pat.elevation_deg[j - 1]) <= adjacent_deg;
    const bool columns_adjacent = pat.azimuth_step_deg <= adjacent_deg;
    const Eigen::Vector3d origin = scene.scanners[s].position_m;
    const Eigen::Vector3d origin_tilted = R * origin;
    out.scanner_positions_m.push_back(origin_tilted);
    int sector_index = -1;
    for (int i = 0; i < n_az; ++i) {
      const double az_rel = i * pat.azimuth_step_deg;
      const int sec = std::min(n_sectors - 1, static_cast<int>(az_rel / sector));
      if (sec != sector_index) {
        if (!out.scans.empty()) out.scans.back().end = out.points.size();
        ScanBlock b;
        b.scanner = static_cast<int>(s);
        b.sector = sec;
        b.azimuth_begin_deg = scene.scanners[s].heading_deg + sec * sector;
        b.azimuth_end_deg = scene.scanners[s].heading_deg + std::min(360.0, (sec + 1) * sector);
        b.begin = out.points.size();
        out.scans.push_back(b);
        sector_index = sec;
      }
      const double az = (scene.scanners[s].heading_deg + pat.azimuth_offset_deg + az_rel) * kDeg;
      const double ca = std::cos(az), sa = std::sin(az);
      double above = kNone;  // true range of the previous ray in this column
      for (int j = 0; j < n_el; ++j) {
        const Eigen::Vector3d d_tilted(cos_el[j] * ca, cos_el[j] * sa, sin_el[j]);
        const Eigen::Vector3d d_scene = Rt * d_tilted;
        const auto hit = caster.cast(origin, d_scene, sp.range_max_m);
        const double t = hit ? hit->t_m : kNone;
        cur_col[j] = t;
        const double left = columns_adjacent ? prev_col[j] : kNone;
        const double below = row_adjacent[static_cast<std::size_t>(j)] ? above : kNone;
        above = t;
        if (!hit || t < sp.range_min_m) continue;
        double range = t;
        bool mixed = false;
        if (sp.mixed_pixel_probability > 0) {
          // A depth edge towards the neighbour measured just before (same column or previous
          // column): the footprint straddles both surfaces and the echo lands in between.
          double other = kNone;
          if (!std::isnan(below) && std::abs(below - t) > sp.mixed_pixel_min_jump_m)
            other = below;
          else if (!std::isnan(left) && std::abs(left - t) > sp.mixed_pixel_min_jump_m)
            other = left;
          if (!std::isnan(other) && rng.uniform() < sp.mixed_pixel_probability) {
            range = t + rng.uniform() * (other - t);
            mixed = true;
          }
        }
        if (sp.range_sigma_m > 0) range += sp.range_sigma_m * rng.normal();
        if (range < sp.range_min_m || range > sp.range_max_m) continue;
        Eigen::Vector3d p = origin_tilted + range * d_tilted;
        if (sp.coordinate_step_m > 0)
          p = ((p / sp.coordinate_step_m).array().round() * sp.coordinate_step_m).matrix();
        out.points.emplace_back(p.cast<float>());
        out.mixed_pixels += mixed;
      }
      std::swap(prev_col, cur_col);
      ticker.tick(n_el);
    }
    if (!out.scans.empty()) out.scans.back().end = out.points.size();
  }
  out.returns = out.points.size();
  ticker.finish();
  return out;
}

}  // namespace detail

SimResult simulate(const Scene& input, const SimOptions& options) {
  require_valid(input);
  const Scene scene = normalised(input);
  const ScannerParams& sp = scene.scanner;
  detail::RayPattern pat;
  pat.azimuths = azimuth_count(sp);
  pat.azimuth_step_deg = sp.azimuth_step_deg;
  const int n_el = elevation_count(sp);
  for (int j = 0; j < n_el; ++j)
    pat.elevation_deg.push_back(sp.elevation_min_deg + j * sp.elevation_step_deg);
  return detail::simulate_pattern(scene, options, ray_count(scene),
                                  [&](std::size_t) { return pat; });
}

}  // namespace indoormap::sim
