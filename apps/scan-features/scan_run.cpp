#include "scan_run.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>

#include "indoormap/core/errors.hpp"
#include "indoormap/formats/carmen_laser.hpp"

namespace indoormap::app {

namespace {

namespace sf = scan_features;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

/// The laser's motion t (laser frame) as the robot's: offset o, then t, then o undone.
laser::Pose2d robot_motion(const laser::Pose2d& o, const laser::Pose2d& t) {
  return o.compose(t).compose(sf::relative_pose(o, laser::Pose2d{}));
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

/// Aligns cur onto prev with both variants (starts: each variant's previous estimate, a
/// constant-velocity guess, then the identity).
formats::AlignRecord align_pair(const laser::LaserScan& prev, const laser::LaserScan& cur,
                                const ScanFeaturesConfig& cfg, laser::Pose2d last[2],
                                std::vector<double> ms[2]) {
  formats::AlignRecord rec;
  rec.log_motion = sf::relative_pose(prev.robot_pose_map, cur.robot_pose_map);
  for (int k = 0; k < 2; ++k) {
    sf::IcpParams p = cfg.icp;
    p.kind = k == 0 ? sf::IcpKind::kPointToPoint : sf::IcpKind::kPointToLine;
    const laser::Pose2d guesses[] = {last[k], laser::Pose2d{}};
    const auto t0 = Clock::now();
    sf::IcpResult r = sf::align_scans(prev, cur, p, cfg.search, guesses);
    ms[k].push_back(ms_since(t0));
    last[k] = r.transform;
    r.transform = robot_motion(cur.laser_offset, r.transform);
    (k == 0 ? rec.point_to_point : rec.point_to_line) = r;
  }
  return rec;
}

}  // namespace

ScanFeaturesRun run_scan_features(const std::string& log_path, const ScanFeaturesConfig& cfg,
                                  int picture_scan, bool align, bool quiet) {
  ScanFeaturesRun run;
  run.log_path = log_path;
  run.config = cfg;
  run.picture_scan = picture_scan;
  run.align = align;
  const auto t_start = Clock::now();
  formats::CarmenReader reader(log_path, cfg.log);
  formats::CarmenScan c;
  laser::LaserScan prev, cur;
  laser::Pose2d last[2];
  std::vector<double> ms[2];
  int index = -1;
  bool have_prev = false;
  while (reader.next(c)) {
    ++index;
    cur = formats::to_laser_scan(c);
    try {
      laser::validate(cur);
    } catch (const UsageError&) {
      ++run.scans_skipped;
      have_prev = false;  // no pair across an unusable scan
      continue;
    }
    auto t0 = Clock::now();
    run.records.push_back(
        {index, cur.time_s, cur.robot_pose_map, sf::extract_features(cur, cfg.features)});
    run.features_ms += ms_since(t0);
    if (index == picture_scan) run.picture = cur;
    if (align && have_prev) {
      t0 = Clock::now();
      run.pairs.push_back(align_pair(prev, cur, cfg, last, ms));
      run.pairs.back().scan_ref = run.records[run.records.size() - 2].scan;
      run.pairs.back().scan_cur = index;
      run.align_ms += ms_since(t0);
    }
    std::swap(prev, cur);
    have_prev = true;
    const int every = quiet ? 0 : cfg.progress_every_scans;
    if (every > 0 && (index + 1) % every == 0)
      std::cerr << "scan-features: " << index + 1 << " scans (line " << c.line << ")\n";
  }
  run.stats = reader.stats();
  formats::AlignSummary thresholds;
  thresholds.moved_m = cfg.moved_m;
  thresholds.moved_rad = cfg.moved_rad;
  run.align_summary = formats::summarise_alignment(run.pairs, thresholds);
  for (int k = 0; k < 2; ++k) run.align_summary.median_ms[k] = median(ms[k]);
  run.read_ms = ms_since(t_start) - run.features_ms - run.align_ms;
  return run;
}

}  // namespace indoormap::app
