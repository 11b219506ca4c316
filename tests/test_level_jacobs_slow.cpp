// Levelling says when the input cannot support it (issue 17): sectors of the real Jacobs scan
// (nine 40 degree sectors from one position) give a warning and either the whole scan's tilt
// within 0.3 degrees or no levelling, never a larger wrong correction. Skips without the data.
#include <gtest/gtest.h>

#include <cmath>

#include "indoormap/cloud/level.hpp"
#include "indoormap/cloud_io/load.hpp"
#include "test_support.hpp"

using namespace indoormap;

namespace {

const PointCloud* jacobs_cloud() {
  static const PointCloud* c = []() -> const PointCloud* {
    auto root = test::shared_data_dir();
    if (!root || !std::filesystem::exists(*root / "jacobs-thermocolorlab")) return nullptr;
    return new PointCloud(cloud_io::load_cloud((*root / "jacobs-thermocolorlab").string()).cloud);
  }();
  return c;
}

// The points and scanners of the 3DTK scans first..last (one origin span each).
PointCloud sectors(const PointCloud& all, std::size_t first, std::size_t last) {
  PointCloud out;
  for (std::size_t k = first; k <= last && k < all.origins.size(); ++k) {
    const auto& span = all.origins[k];
    out.points.insert(out.points.end(), all.points.begin() + span.first,
                      all.points.begin() + span.first + span.count);
    if (span.scanner < all.scanners.size()) out.scanners.push_back(all.scanners[span.scanner]);
  }
  return out;
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace

TEST(LevelJacobs, PartialScansWarnAndNeverTiltWrong) {
  const PointCloud* all = jacobs_cloud();
  if (!all)
    GTEST_SKIP() << "real data 'jacobs-thermocolorlab' not found: set INDOORMAP_DATA or provide "
                    "../shared/data next to the source tree";
  ASSERT_EQ(all->origins.size(), 9u);
  const cloud::LevelResult full = cloud::estimate_level(all->points, {}, all->scanners);
  ASSERT_TRUE(full.levelled) << full.note;
  EXPECT_NEAR(full.tilt_deg, 2.13, 0.1);
  EXPECT_TRUE(full.warnings.empty()) << full.warnings.front();
  // Each single sector, and three consecutive sectors from each start.
  std::vector<std::pair<std::size_t, std::size_t>> parts;
  for (std::size_t k = 0; k < 9; ++k) parts.push_back({k, k});
  for (std::size_t k = 0; k < 9; k += 3) parts.push_back({k, k + 2});
  for (const auto& [a, b] : parts) {
    const PointCloud part = sectors(*all, a, b);
    const cloud::LevelResult r = cloud::estimate_level(part.points, {}, part.scanners);
    SCOPED_TRACE("scans " + std::to_string(a) + "-" + std::to_string(b) + ": " + r.note);
    bool horizon_warning = false;
    for (const auto& w : r.warnings)
      horizon_warning |= w.find("of the horizon") != std::string::npos;
    EXPECT_TRUE(horizon_warning);
    if (r.levelled) {
      EXPECT_LE(angle_deg(r.up_input, full.up_input), 0.3);
    }
    std::printf("scans %zu-%zu: levelled %d tilt %.2f (full %.2f), surround %.2f, horizon %.2f\n",
                a, b, r.levelled, r.tilt_deg, full.tilt_deg, r.support.plane_surround_share,
                r.support.horizon_share);
  }
}

// Too little floor, or a tilt above max_tilt_deg: the cloud is left as it is, with the reason.
TEST(LevelSupport, RefusesATiltOnTooLittleFloorOrTooSteep) {
  // A 1.5 x 1.5 m patch of floor tilted 2 degrees, seen all round from its centre.
  std::vector<Eigen::Vector3f> pts;
  const double t = 2.0 * M_PI / 180.0;
  for (double x = -0.75; x <= 0.75; x += 0.01)
    for (double y = -0.75; y <= 0.75; y += 0.01)
      pts.emplace_back(static_cast<float>(x), static_cast<float>(y),
                       static_cast<float>(std::tan(t) * x));
  const std::vector<Eigen::Vector3d> scanner{{0, 0, 1.2}};
  const cloud::LevelResult small = cloud::estimate_level(pts, {}, scanner);
  EXPECT_FALSE(small.levelled);
  EXPECT_NE(small.note.find("min_support_area_m2"), std::string::npos) << small.note;
  cloud::LevelParams p;
  p.min_support_area_m2 = 1.0;
  const cloud::LevelResult ok = cloud::estimate_level(pts, p, scanner);
  EXPECT_TRUE(ok.levelled) << ok.note;
  EXPECT_NEAR(ok.tilt_deg, 2.0, 0.05);
  p.max_tilt_deg = 1.5;  // steeper than allowed: not a floor
  EXPECT_FALSE(cloud::estimate_level(pts, p, scanner).levelled);
  // Seen from one side only (scanner beyond the patch's edge): refused, with the horizon warning.
  p.max_tilt_deg = 5.0;
  const cloud::LevelResult side = cloud::estimate_level(pts, p, {{3.0, 0.0, 1.2}});
  EXPECT_FALSE(side.levelled);
  EXPECT_NE(side.note.find("min_support_surround"), std::string::npos) << side.note;
  ASSERT_FALSE(side.warnings.empty());
}
