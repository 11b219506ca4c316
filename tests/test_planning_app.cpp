// Tests of lib/planning on real data, and of plan-route and its config file.
#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <set>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/formats/ros_map.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "indoormap/planning/planner.hpp"
#include "plan_config.hpp"
#include "planning_fixtures.hpp"
#include "test_support.hpp"

using namespace indoormap;
using namespace indoormap::planning;
using namespace planning_fixtures;

// --- real data --------------------------------------------------------------------------------

namespace {

void expect_routes(const Grid<Cell>& cells, const GridGeometry& geo,
                   const std::vector<std::pair<Pose2, Pose2>>& pairs, const std::string& name) {
  app::PlanConfig cfg;  // the documented defaults, except:
  // no wall-clock budget: these routes take seconds in Release, several times more under the
  // sanitizers or a loaded machine; the node budget (max_nodes) still bounds the searches.
  cfg.planner.max_seconds = 86400;
  const auto tmpl = make_templates(cfg.robot, cfg.planner, geo.cell_m());
  const auto safe = safe_zone(cells, tmpl.disk, cfg.safe_zone);
  for (const auto& [s, g] : pairs) {
    const auto res = plan_routes(safe, geo, s, g, tmpl, cfg.planner);
    ASSERT_FALSE(res.routes.empty()) << name << ": " << res.message;
    EXPECT_TRUE(res.exact_complete) << name;
    EXPECT_EQ(res.routes.front().moves, res.exact_best_moves) << name;
    for (const auto& r : res.routes)
      EXPECT_EQ(check_route(r, safe, geo, res.start_cell, res.goal_cell, cfg.planner), "") << name;
  }
}

}  // namespace

TEST(PlanningRealData, JacobsRoomRoutes) {
  INDOORMAP_REQUIRE_DATA(dir, "jacobs-thermocolorlab");
  auto loaded = cloud_io::load_clouds({dir.string()}, {});
  const auto m = layout::make_map(std::move(loaded.cloud), {});
  expect_routes(m.layout.layout, m.geometry,
                {{{{-1.2, 0.1}, 0.0}, {{2.6, -1.6}, {}}},
                 {{{0.9, 1.6}, 90.0}, {{0.77, -2.0}, 90.0}},
                 {{{-1.2, 0.1}, 0.0}, {{0.9, 1.6}, {}}},
                 {{{2.6, -1.6}, 180.0}, {{0.77, -2.0}, {}}}},
                "jacobs");
}

TEST(PlanningRealData, RoomSegmentationMapRoutes) {
  INDOORMAP_REQUIRE_DATA(dir, "room-segmentation-maps");
  const auto f52 = formats::read_plain_map(dir / "Freiburg52_scan.png", 0.05);
  expect_routes(f52.cells, f52.geometry, {{{{5.0, 12.0}, 0.0}, {{20.0, 10.0}, {}}}},
                "Freiburg52_scan");
  const auto oa = formats::read_plain_map(dir / "office_a.png", 0.05);
  expect_routes(oa.cells, oa.geometry, {{{{10.0, 20.0}, 0.0}, {{25.0, 25.0}, {}}}}, "office_a");
}

// --- the app
// ----------------------------------------------------------------------------------------

TEST(PlanRoute, OutputsErrorsAndExitCodes) {
  const auto dir = test::scratch_dir();
  // A 6 x 3 m room at 0.05 m with a dividing wall that has a door.
  Grid<Cell> room(120, 60, Cell::kFree);
  for (int c = 0; c < 120; ++c) room.at(c, 0) = room.at(c, 59) = Cell::kWall;
  for (int r = 0; r < 60; ++r) room.at(0, r) = room.at(119, r) = Cell::kWall;
  for (int r = 0; r < 60; ++r)
    if (r < 35 || r > 50) room.at(60, r) = Cell::kWall;
  formats::write_ros_map(dir, "map", room, GridGeometry({0, 0}, 0.05, 120, 60));
  const std::string map = " --map " + (dir / "map.yaml").string();
  auto r =
      test::run_app("plan-route", map + " --start 1,1,0 --goal 5,1 -o " + (dir / "o").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"route.json", "route.png", "safe.pgm", "safe.yaml", "summary.json"})
    EXPECT_TRUE(std::filesystem::exists(dir / "o" / f)) << f;
  const auto j = nlohmann::json::parse(test::read_text(dir / "o" / "route.json"));
  EXPECT_TRUE(j["found"].get<bool>());
  EXPECT_GE(j["routes"].size(), 1u);
  EXPECT_GE(j["routes"][0]["moves"].get<int>(), 2);  // through the door
  EXPECT_DOUBLE_EQ(j["parameters"]["d_save_m"].get<double>(), 0.3);
  EXPECT_TRUE(j["parameters"].contains("d_min_m") && j["parameters"].contains("d_max_m"));
  // Unsafe start: exit 2, the distance to the nearest safe cell.
  r = test::run_app("plan-route", map + " --start 0.1,1 --goal 5,1 -o " + (dir / "o2").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("plan-route: start"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nearest safe cell"), std::string::npos) << r.err;
  r = test::run_app("plan-route", map + " --start 100,1 --goal 5,1 -o " + (dir / "o2").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("outside the map"), std::string::npos) << r.err;
  // A robot too wide for the door: no route, exit 3, outputs still written.
  test::write_text(dir / "wide.yaml", "robot:\n  width_m: 0.9\n");
  r = test::run_app("plan-route", map + " -c " + (dir / "wide.yaml").string() +
                                      " --start 1,1.5 --goal 5,1.5 -o " + (dir / "o3").string());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("plan-route: no route"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "o3" / "route.json"));
  // Config errors name the key; --print-config round-trips to the documented defaults.
  test::write_text(dir / "typo.yaml", "planner:\n  d_mx_m: 2\n");
  r = test::run_app("plan-route", map + " -c " + (dir / "typo.yaml").string() +
                                      " --start 1,1 --goal 5,1 -o " + (dir / "o4").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("planner.d_mx_m"), std::string::npos) << r.err;
  r = test::run_app("plan-route", "--print-config");
  EXPECT_EQ(r.exit_code, 0);
  app::PlanConfig from_file;
  app::merge_plan_config_file(from_file,
                              std::string(INDOORMAP_SOURCE_DIR) + "/config/plan-route.yaml");
  EXPECT_EQ(app::to_yaml(from_file), app::to_yaml(app::PlanConfig{}));
  EXPECT_EQ(r.out, app::to_yaml(app::PlanConfig{}));
  r = test::run_app("plan-route", "--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("Examples"), std::string::npos);
}

// Options that cannot act are refused, not ignored (issue 19): a rotated map (origin yaw != 0,
// whose safe.yaml would come out with yaw 0) and --free-min with a map YAML (its thresholds
// decide). Both exit 2 naming the problem, nothing written; the same map with yaw 0 plans.
TEST(PlanRoute, RefusesRotatedMapsAndFreeMinWithAYaml) {
  const auto dir = test::scratch_dir();
  Grid<Cell> room(60, 40, Cell::kFree);
  for (int c = 0; c < 60; ++c) room.at(c, 0) = room.at(c, 39) = Cell::kWall;
  for (int r = 0; r < 40; ++r) room.at(0, r) = room.at(59, r) = Cell::kWall;
  formats::write_ros_map(dir, "map", room, GridGeometry({0, 0}, 0.05, 60, 40));
  const std::string yaml = test::read_text(dir / "map.yaml");
  const std::string rotated = test::replace_all(yaml, ", 0.0]", ", 0.5]");
  ASSERT_NE(rotated, yaml) << yaml;
  test::write_text(dir / "rotated.yaml", rotated);
  const std::string args = " --start 1,1,0 --goal 2,1 -o ";
  auto r = test::run_app("plan-route",
                         "--map " + (dir / "map.yaml").string() + args + (dir / "ok").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = test::run_app("plan-route",
                    "--map " + (dir / "rotated.yaml").string() + args + (dir / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("rotated.yaml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("yaw 0.5 rad is not supported"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "o" / "safe.yaml"));
  r = test::run_app("plan-route", "--map " + (dir / "map.yaml").string() + " --free-min 200" +
                                      args + (dir / "o2").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--free-min is for plain PNG/PGM maps"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "o2" / "route.json"));
  r = test::run_app("explore-sim",
                    (dir / "map.yaml").string() + " --free-min 200 -o " + (dir / "o3").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--free-min is for plain PNG/PGM maps"), std::string::npos) << r.err;
  r = test::run_app("explore-sim",
                    (dir / "rotated.yaml").string() + " -o " + (dir / "o4").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("yaw 0.5 rad is not supported"), std::string::npos) << r.err;
}

TEST(PlanConfig, MalformedFilesAreTypedErrorsNamingFileAndLine) {
  // The planner config shares the pipeline config's checks (apps/common/config_reader.hpp): a list
  // used as a key or an unknown key is an InputError, never an untyped yaml-cpp exception.
  const auto dir = test::scratch_dir();
  test::write_text(dir / "list_key.yaml", "robot:\n  [a, b]: 1\n");
  test::write_text(dir / "typo.yaml", "robot:\n  widht_m: 0.5\n");
  for (const char* f : {"list_key.yaml", "typo.yaml"}) {
    app::PlanConfig c;
    try {
      app::merge_plan_config_file(c, (dir / f).string());
      FAIL() << f << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string(f) + ":2"), std::string::npos) << e.what();
    }
  }
}
