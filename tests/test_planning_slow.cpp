// Slow tests of the route searches on the shared room-segmentation maps (label "slow": not in the
// sanitizer tree): the min-link search against the exact search's count on a real building (the
// exact search itself takes a minute there; tests/test_planning_minlink.cpp compares the two
// searches live on small maps) and against the exact counts on all twelve maps.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "indoormap/formats/ros_map.hpp"
#include "indoormap/planning/planner.hpp"
#include "planning_fixtures.hpp"
#include "test_support.hpp"

using namespace indoormap;
using namespace indoormap::planning;
using namespace planning_fixtures;

namespace {

struct RealCase {
  Grid<SafeCell> safe;
  GridGeometry geo;
  CellIndex s, g;
};

/// The map's safe zone (default robot) and its far-apart pair.
RealCase real_case(const std::filesystem::path& png, const Templates& t) {
  const Grid<Cell> cells = formats::read_plain_map(png, 0.05).cells;
  RealCase rc{
      safe_zone(cells, t.disk), GridGeometry({0, 0}, 0.05, cells.width, cells.height), {}, {}};
  const auto far = far_apart_cells(rc.safe);
  EXPECT_TRUE(far);
  if (far) rc.s = far->first, rc.g = far->second;
  return rc;
}

}  // namespace

TEST(PlanningSlow, MinLinkEqualsExactOnARealBuilding) {
  INDOORMAP_REQUIRE_DATA(dir, "room-segmentation-maps");
  PlannerParams p;  // the defaults (D_max 3 m, D_min 0.3 m) without a work budget
  p.max_nodes = 1'000'000'000;
  p.max_seconds = 3600;
  const auto t = make_templates(RobotParams{}, p, 0.05);
  // The whole map's far-apart pair: 13 moves, the exact search's count (docs/benchmarks.md,
  // measured by exact_min_moves in 61 s; the min-link search takes a few seconds).
  const auto full = real_case(dir / "Freiburg52_scan.png", t);
  const auto t0 = std::chrono::steady_clock::now();
  const auto fm = min_link_moves(full.safe, full.s, full.g, t.neighbourhood, p);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(fm.cells);
  EXPECT_EQ(static_cast<int>(fm.cells->size()) - 1, 13);
  const Route fr = make_route(*fm.cells, full.geo, 0.0, std::nullopt);
  EXPECT_EQ(check_route(fr, full.safe, full.geo, full.s, full.g, p), "");
  std::cout << "[ Freiburg52_scan ] far pair: " << fm.cells->size() - 1 << " moves in " << s
            << " s\n";
}

TEST(PlanningSlow, MinLinkOnEveryRoomSegmentationMap) {
  // The far-apart pair of each of the twelve maps (default robot and planner, no budget): the
  // fewest moves found by exact searches before the bit-parallel layers, the previous A* on moves
  // (2026-12-01) and the per-cell layered search (2026-12-02), both tested equal to the exact
  // search (docs/benchmarks.md, "Fewest-moves routes on building maps"; the exact search itself
  // agrees on Freiburg52_scan above); every move passes the safety checks.
  INDOORMAP_REQUIRE_DATA(dir, "room-segmentation-maps");
  const std::vector<std::pair<std::string, int>> expected = {
      {"Freiburg52_scan", 13}, {"Freiburg79_scan", 14}, {"freiburg_building79", 15},
      {"intel_map", 22},       {"lab_a_scan", 21},      {"lab_b_scan", 17},
      {"lab_c_scan", 12},      {"lab_intel", 18},       {"office_a", 24},
      {"office_b", 23},        {"office_c", 31},        {"office_d", 18}};
  PlannerParams p;
  p.max_nodes = 1'000'000'000;
  p.max_seconds = 3600;
  const auto t = make_templates(RobotParams{}, p, 0.05);
  for (const auto& [name, moves] : expected) {
    const auto rc = real_case(dir / (name + ".png"), t);
    const auto ml = min_link_moves(rc.safe, rc.s, rc.g, t.neighbourhood, p);
    ASSERT_TRUE(ml.cells) << name;
    EXPECT_EQ(static_cast<int>(ml.cells->size()) - 1, moves) << name;
    const Route r = make_route(*ml.cells, rc.geo, 0.0, std::nullopt);
    EXPECT_EQ(check_route(r, rc.safe, rc.geo, rc.s, rc.g, p), "") << name;
  }
}
