#include "laser_run.hpp"

#include <algorithm>
#include <chrono>
#include <functional>

#include "indoormap/core/errors.hpp"
#include "indoormap/formats/carmen_laser.hpp"
#include "indoormap/laser/mappers.hpp"
#include "indoormap/laser/pose_refine.hpp"
#include "progress.hpp"

namespace indoormap::app {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

/// One pass over the log: on_scan(k, scan) for the k-th usable FLASER message; a scan that
/// laser::validate rejects (a non-finite pose) is counted in skipped. Progress (scans of
/// total_scans, 0: unknown) reported every `every` scans (0: none). Throws InputError on the first
/// bad line.
formats::CarmenStats log_pass(const std::string& path, const LaserMapConfig& cfg, int every,
                              const char* what, std::int64_t total_scans, std::size_t& skipped,
                              const std::function<void(std::size_t, laser::LaserScan&)>& on_scan) {
  const ProgressReporter bar(std::string("laser-to-map: ") + what, "scans", every <= 0);
  formats::CarmenReader reader(path, cfg.log);
  formats::CarmenScan c;
  laser::LaserScan s;
  skipped = 0;
  std::size_t k = 0;
  while (reader.next(c)) {
    s = formats::to_laser_scan(c);
    try {
      laser::validate(s);
    } catch (const UsageError&) {
      ++skipped;
      continue;
    }
    on_scan(k++, s);
    const std::size_t n = reader.stats().scans;
    if (every > 0 && n % static_cast<std::size_t>(every) == 0)
      bar.update(static_cast<std::int64_t>(n), total_scans);
  }
  bar.finish();
  return reader.stats();
}

/// poses[k] (when there is one) replaces the log's pose of scan k.
void use_pose(const std::vector<laser::Pose2d>& poses, std::size_t k, laser::LaserScan& s) {
  if (k < poses.size()) s.robot_pose_map = poses[k];
}

/// The mapping pass; fills run.stats, scans_skipped, scans_mapped and path_m.
laser::OccupancyMap map_pass(const std::string& path, const LaserMapConfig& cfg, int every,
                             const std::vector<laser::Pose2d>& poses, LaserMapRun& run) {
  auto mapper = laser::make_mapper(cfg.method, cfg.grid, cfg.himm, cfg.log_odds);
  run.path_m.clear();
  run.stats =
      log_pass(path, cfg, every, "mapping", static_cast<std::int64_t>(poses.size()),
               run.scans_skipped, [&](std::size_t k, laser::LaserScan& s) {
                 use_pose(poses, k, s);
                 mapper->integrate(s);
                 // The path for the picture: a point per cell moved.
                 const Eigen::Vector2d p = s.robot_pose_map.position_m();
                 if (run.path_m.empty() || (p - run.path_m.back()).norm() >= cfg.grid.cell_m)
                   run.path_m.push_back(p);
               });
  run.scans_mapped = mapper->scan_count();
  return run.scans_mapped == 0 ? laser::OccupancyMap{} : mapper->snapshot();
}

/// One refinement pass: every scan aligned to `map`; poses updated (filled on the first pass).
PoseRefineStats refine_pass(const std::string& path, const LaserMapConfig& cfg, int every,
                            const laser::OccupancyMap& map, std::vector<laser::Pose2d>& poses) {
  const laser::MatchField field(map.cells, map.geometry, cfg.pose_refine.field_sigma_m);
  PoseRefineStats st;
  std::vector<double> shifts;
  std::size_t skipped = 0;
  const std::size_t known = poses.size();
  log_pass(path, cfg, every, "aligning scans", static_cast<std::int64_t>(known), skipped,
           [&](std::size_t k, laser::LaserScan& s) {
             use_pose(poses, k, s);
             const auto c = laser::refine_pose(s, field, cfg.grid.max_range_m, cfg.pose_refine);
             if (k >= poses.size()) poses.resize(k + 1, s.robot_pose_map);
             poses[k] = c.robot_pose_map;
             ++st.scans;
             if (!c.applied) return;
             ++st.scans_moved;
             shifts.push_back(c.shift_m);
             st.max_shift_m = std::max(st.max_shift_m, c.shift_m);
             st.max_turn_deg = std::max(st.max_turn_deg, c.turn_rad * 180.0 / 3.141592653589793);
           });
  if (!shifts.empty()) {
    std::nth_element(shifts.begin(), shifts.begin() + shifts.size() / 2, shifts.end());
    st.median_shift_m = shifts[shifts.size() / 2];
  }
  return st;
}

}  // namespace

LaserMapRun map_log(const std::string& path, const LaserMapConfig& cfg, bool quiet) {
  LaserMapRun run;
  run.log_path = path;
  run.config = cfg;
  const int every = quiet ? 0 : cfg.progress_every_scans;
  auto t0 = Clock::now();
  std::vector<laser::Pose2d> poses;  // refined robot poses, one per usable scan
  run.map = map_pass(path, cfg, every, poses, run);
  for (int pass = 0; pass < cfg.pose_refine.passes && run.scans_mapped > 0; ++pass) {
    run.refine.push_back(refine_pass(path, cfg, every, run.map, poses));
    run.map = map_pass(path, cfg, every, poses, run);
  }
  run.map_ms = ms_since(t0);
  if (run.scans_mapped == 0) return run;
  t0 = Clock::now();
  laser::ConsistencyParams cp = cfg.consistency;
  cp.max_range_m = cfg.grid.max_range_m;
  laser::ConsistencyCheck check(run.map.cells, run.map.geometry, cp);
  std::size_t skipped = 0;
  log_pass(path, cfg, every, "checking", static_cast<std::int64_t>(run.stats.scans), skipped,
           [&](std::size_t k, laser::LaserScan& s) {
             use_pose(poses, k, s);
             check.add(s);
           });
  run.check = check.result();
  run.check_ms = ms_since(t0);
  return run;
}

}  // namespace indoormap::app
