// Issue 17, "Consistency": the same simulated room scanned from two different positions gives
// the same room. The default office scene (scenes/office.yaml) with its one scanner moved to
// eleven free spots (1.2-1.5 m high), ten pairs of them; each scan through scene-sim and
// pcd-to-map with their defaults; the room polygons of room.geojson compared pair by pair: area
// within 5 % and boundary Hausdorff within 0.2 m (the bounds). Both runs map into the
// same (levelled scene) frame, so the polygons are compared as written.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "indoormap/core/polygon.hpp"
#include "indoormap/formats/room_geojson.hpp"
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using indoormap::Polygon;
using indoormap::test::run_app;

struct Spot {
  double x, y, z;
};

// Free spots of the office (away from the furniture of scenes/office.yaml).
const std::map<int, Spot> kSpots = {
    {0, {3.9, 3.2, 1.4}}, {1, {1.5, 3.0, 1.3}}, {2, {7.2, 1.2, 1.5}}, {3, {3.5, 1.2, 1.2}},
    {4, {7.2, 4.0, 1.4}}, {5, {7.5, 3.0, 1.3}}, {6, {4.0, 4.2, 1.5}}, {7, {3.0, 2.6, 1.2}},
    {8, {6.9, 2.6, 1.4}}, {9, {1.2, 2.5, 1.5}}};
const int kPairs[10][2] = {{0, 1}, {0, 2}, {3, 4}, {1, 5}, {6, 3},
                           {7, 8}, {9, 6}, {2, 4}, {0, 8}, {1, 3}};

/// The office scene with its scanner at s, simulated and mapped; the room polygon (empty when
/// pcd-to-map found no closed room).
Polygon room_from(int id, const Spot& s, const fs::path& dir) {
  std::string scene =
      indoormap::test::read_text(fs::path(INDOORMAP_SOURCE_DIR) / "scenes/office.yaml");
  const std::string line = "  - {position: [3.9, 3.2, 1.4], heading_deg: 0}";
  const auto at = scene.find(line);
  EXPECT_NE(at, std::string::npos) << "scenes/office.yaml changed: update this test";
  if (at == std::string::npos) return {};
  char buf[128];
  std::snprintf(buf, sizeof buf, "  - {position: [%.2f, %.2f, %.2f], heading_deg: 0}", s.x, s.y,
                s.z);
  scene.replace(at, line.size(), buf);
  const fs::path yaml = dir / ("office_" + std::to_string(id) + ".yaml");
  indoormap::test::write_text(yaml, scene);
  const fs::path sim = dir / ("sim_" + std::to_string(id)),
                 map = dir / ("map_" + std::to_string(id));
  auto r = run_app("scene-sim", "-q " + yaml.string() + " -o " + sim.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_app("pcd-to-map", "-q " + (sim / "cloud.pcd").string() + " -o " + map.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const auto rooms = indoormap::formats::read_room_geojson(map / "room.geojson");
  EXPECT_EQ(rooms.size(), 1u) << "spot " << id;
  return rooms.empty() ? Polygon{} : rooms.front();
}

TEST(TwoPositions, TheSameRoomFromTwoScannerPositions) {
  const fs::path dir = indoormap::test::scratch_dir();
  std::map<int, Polygon> room;
  for (const auto& [id, s] : kSpots) room[id] = room_from(id, s, dir);
  int within = 0;
  for (const auto& p : kPairs) {
    const Polygon &a = room[p[0]], &b = room[p[1]];
    if (a.empty() || b.empty()) continue;
    const double area_a = std::abs(indoormap::signed_area(a)),
                 area_b = std::abs(indoormap::signed_area(b));
    const double area_diff = std::abs(area_a - area_b) / std::max(area_a, area_b);
    const double h = indoormap::boundary_hausdorff(a, b);
    const bool ok = area_diff <= 0.05 && h <= 0.2;
    within += ok;
    std::printf("[ figures  ] spots %d-%d: areas %.2f / %.2f m2 (%.1f %%), Hausdorff %.3f m%s\n",
                p[0], p[1], area_a, area_b, 100 * area_diff, h, ok ? "" : "  <- outside");
  }
  std::printf("[ figures  ] %d of 10 pairs within 5 %% area and 0.2 m\n", within);
  EXPECT_EQ(within, 10);
}

}  // namespace
