// scan_features on a real log: consecutive scans of the first 200 of freiburg-079 aligned by both
// ICP variants against the log's corrected poses (the full-log figures of all three logs come
// from scan-features --align: docs/scan-features.md), and features found in every scan.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "indoormap/formats/carmen_laser.hpp"
#include "indoormap/scan_features/features.hpp"
#include "indoormap/scan_features/icp.hpp"
#include "test_support.hpp"

namespace {

using namespace indoormap;
using namespace indoormap::scan_features;

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

TEST(ScanFeaturesLog, Freiburg079AlignmentWithinTargets) {
  INDOORMAP_REQUIRE_DATA(log, "carmen-logs/freiburg-079-corrected.log.gz");
  formats::CarmenReader reader(log.string());
  formats::CarmenScan c;
  laser::LaserScan prev, cur;
  std::vector<double> t_err[2], r_err[2];
  laser::Pose2d last[2];
  int scans = 0, walls = 0;
  while (scans < 200 && reader.next(c)) {
    cur = formats::to_laser_scan(c);
    walls += static_cast<int>(extract_features(cur, {}).walls.size());
    if (scans++ == 0) {
      prev = cur;
      continue;
    }
    const laser::Pose2d truth = relative_pose(prev.laser_pose_map(), cur.laser_pose_map());
    for (int k = 0; k < 2; ++k) {
      IcpParams p;
      p.kind = k == 0 ? IcpKind::kPointToPoint : IcpKind::kPointToLine;
      const laser::Pose2d guesses[] = {last[k], {}};  // constant velocity, then standing still
      const IcpResult r = align_scans(prev, cur, p, {}, guesses);
      last[k] = r.transform;
      t_err[k].push_back((r.transform.position_m() - truth.position_m()).norm());
      r_err[k].push_back(std::abs(laser::wrap_angle(r.transform.theta_rad - truth.theta_rad)));
    }
    prev = cur;
  }
  ASSERT_EQ(scans, 200);
  EXPECT_GT(walls, 200 * 3);  // an office: several walls in every scan
  for (int k = 0; k < 2; ++k) {
    const double t = median(t_err[k]), r = median(r_err[k]) * 180.0 / std::numbers::pi;
    std::printf("freiburg-079, 199 pairs, %s: median error %.4f m, %.3f deg\n",
                k == 0 ? "point-to-point" : "point-to-line", t, r);
    EXPECT_LE(t, 0.03);
    EXPECT_LE(r, 0.5);
  }
}

}  // namespace
