// Tests of lib/formats: every format written, read back and compared (write -> read -> equal),
// the bytes the apps have always written, and the ROS map reader's refusals.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "indoormap/border/border.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/formats/ground_truth_json.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/formats/objects_json.hpp"
#include "indoormap/formats/pgm.hpp"
#include "indoormap/formats/room_geojson.hpp"
#include "indoormap/formats/ros_map.hpp"
#include "indoormap/formats/route_json.hpp"
#include "indoormap/objects/objects.hpp"
#include "indoormap/sim/eval.hpp"
#include "indoormap/sim/ground_truth.hpp"
#include "indoormap/sim/simulate.hpp"
#include "indoormap/sim/world.hpp"
#include "map_fixtures.hpp"
#include "map_yaml.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using map_fixtures::kPgm;
using map_fixtures::png_header;
using nlohmann::json;
using test::replace_all;

namespace {

void expect_same_polygon(const Polygon& a, const Polygon& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << i;
}

}  // namespace

// ------------------------------------------------------------------------------ ROS map

TEST(RosMap, WriteReadRoundTrip) {
  const fs::path dir = test::scratch_dir();
  Grid<Cell> g(5, 3, Cell::kFree);
  g.at(0, 0) = Cell::kWall;
  g.at(4, 2) = Cell::kFurniture;  // occupied: read back as wall
  g.at(2, 1) = Cell::kUnknown;
  const GridGeometry geo({-1.25, 2.5}, 0.1, 5, 3);
  formats::write_ros_map(dir, "map", g, geo);
  const formats::RosMap m = app::read_ros_map(dir / "map.yaml");
  EXPECT_EQ(m.geometry, geo);
  EXPECT_EQ(m.meta.image, "map.pgm");
  Grid<Cell> expected = g;
  expected.at(4, 2) = Cell::kWall;
  EXPECT_EQ(m.cells.data, expected.data);
}

TEST(RosMap, BothYamlSpellingsReadBackTheSame) {
  const fs::path dir = test::scratch_dir();
  const GridGeometry geo({0.0, -(0.1 + 0.2)}, 0.05, 10, 10);  // -0.30000000000000004
  const formats::RosMapMeta meta = formats::map_meta("map.pgm", geo);
  formats::write_map_yaml(dir / "a.yaml", meta, formats::MapYamlStyle::kRosMap);
  formats::write_map_yaml(dir / "b.yaml", meta, formats::MapYamlStyle::kShortest);
  // The bytes each app has always written: pcd-to-map's map.yaml, scene-sim's truth layout.
  EXPECT_EQ(test::read_text(dir / "a.yaml"),
            "image: map.pgm\nmode: trinary\nresolution: 0.05\norigin: [0, -0.3, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  EXPECT_EQ(test::read_text(dir / "b.yaml"),
            "image: map.pgm\nresolution: 0.05\norigin: [0.0, -0.30000000000000004, 0.0]\n"
            "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
  for (const char* f : {"a.yaml", "b.yaml"}) {
    const formats::RosMapMeta back = app::read_map_yaml(dir / f);
    EXPECT_EQ(back.image, meta.image) << f;
    EXPECT_EQ(back.resolution_m, meta.resolution_m) << f;
    EXPECT_EQ(back.negate, meta.negate) << f;
    EXPECT_EQ(back.occupied_thresh, meta.occupied_thresh) << f;
    EXPECT_EQ(back.free_thresh, meta.free_thresh) << f;
  }
  // Only the shortest spelling keeps every bit of the origin.
  EXPECT_EQ(app::read_map_yaml(dir / "b.yaml").origin, meta.origin);
  EXPECT_NEAR(app::read_map_yaml(dir / "a.yaml").origin.y(), meta.origin.y(), 1e-9);
}

TEST(RosMap, CommentsFollowTheKeysAndReadersIgnoreThem) {
  const fs::path dir = test::scratch_dir();
  formats::RosMapMeta meta = formats::map_meta("map.pgm", GridGeometry({1.0, 2.0}, 0.05, 4, 4));
  meta.comments = {"input = R^T * map", "two\nlines"};
  formats::write_map_yaml(dir / "c.yaml", meta);
  EXPECT_EQ(test::read_text(dir / "c.yaml"),
            "image: map.pgm\nmode: trinary\nresolution: 0.05\norigin: [1, 2, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n# input = R^T * map\n# two lines\n");
  const formats::RosMapMeta back = app::read_map_yaml(dir / "c.yaml");
  EXPECT_EQ(back.origin, meta.origin);
  EXPECT_TRUE(back.comments.empty());  // comments are not keys
  Grid<Cell> g(4, 4, Cell::kFree);
  formats::write_ros_map(dir, "m", g, GridGeometry({0, 0}, 0.1, 4, 4), {"yaw -40 deg"});
  EXPECT_NE(test::read_text(dir / "m.yaml").find("\n# yaw -40 deg\n"), std::string::npos);
  EXPECT_EQ(app::read_ros_map(dir / "m.yaml").cells.data, g.data);
}

TEST(PlainMap, GreyLevelsReadBackAsFreeAndOccupied) {
  const fs::path dir = test::scratch_dir();
  Grid<std::uint8_t> grey(4, 2, 255);
  grey.at(0, 0) = 0;
  grey.at(3, 1) = 249;  // below free_min 250: occupied
  grey.at(1, 1) = 250;
  formats::write_pgm(dir / "plan.pgm", grey);
  const formats::RosMap m = formats::read_plain_map(dir / "plan.pgm", 0.05);
  EXPECT_EQ(m.geometry, GridGeometry({0.0, 0.0}, 0.05, 4, 2));
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 4; ++c)
      EXPECT_EQ(m.cells.at(c, r), grey.at(c, r) >= 250 ? Cell::kFree : Cell::kWall) << c << r;
}

// ------------------------------------------------------------------------------ layout PGM

TEST(LayoutPgm, WriteReadRoundTrip) {
  const fs::path dir = test::scratch_dir();
  Grid<Cell> g(7, 4, Cell::kUnknown);
  for (int i = 0; i < 28; ++i) g.data[i] = static_cast<Cell>(i % 4);
  const GridGeometry geo({1.0, 1.0}, 0.05, 7, 4);
  formats::write_layout_pgm(dir / "layout.pgm", g);
  EXPECT_EQ(formats::read_layout_pgm(dir / "layout.pgm", geo).data, g.data);
  EXPECT_THROW(formats::read_layout_pgm(dir / "layout.pgm", GridGeometry({0, 0}, 0.05, 7, 5)),
               InputError);
}

TEST(LayoutPgm, RowsRunNorthUpAndReadBack) {
  Grid<Cell> g(3, 2, Cell::kFree);
  g.at(0, 0) = Cell::kWall;       // lowest y, lowest x
  g.at(2, 1) = Cell::kFurniture;  // highest y, highest x
  const fs::path dir = test::scratch_dir();
  formats::write_layout_pgm(dir / "l.pgm", g);
  const std::string bytes = test::read_text(dir / "l.pgm");
  ASSERT_EQ(bytes.substr(0, 11), "P5\n3 2\n255\n");
  EXPECT_EQ(bytes[11 + 2], 2);      // image row 0 = highest y: last column is furniture
  EXPECT_EQ(bytes[11 + 3 + 0], 1);  // image row 1 = lowest y: first column is wall
  const Grid<std::uint8_t> back = formats::read_pgm(dir / "l.pgm");
  EXPECT_EQ(back.at(0, 0), 1);
  EXPECT_EQ(back.at(2, 1), 2);
}

// ------------------------------------------------------------------------------ objects

TEST(ObjectsJson, WriteReadRoundTrip) {
  const fs::path dir = test::scratch_dir();
  objects::ObjectsResult res;
  objects::FurnitureObject a;
  a.id = 1;
  a.footprint_m = {{0, 0}, {1, 0}, {1, 0.5}, {0, 0.5}};
  a.has_height = true;
  a.z_min_m = 0.0;
  a.z_max_m = 0.75;
  a.box.center_m = {0.5, 0.25};
  a.box.length_m = 1.0;
  a.box.width_m = 0.5;
  objects::FurnitureObject b = a;
  b.id = 2;
  b.kind = ObjectKind::kHanging;
  b.z_min_m = 2.0;
  b.z_max_m = 2.1;
  b.footprint_m = {{2, 2}, {2.5, 2}, {2.5, 2.5}, {2, 2.5}};
  res.objects = {a, b};
  const GridGeometry geo({0, 0}, 0.05, 10, 10);
  formats::write_objects_json(dir / "objects.json", res, geo, {{"objects/object_1.pcd", 12}, {}});
  const auto back = formats::read_objects_json(dir / "objects.json");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].id, "1");
  expect_same_polygon(back[0].footprint, a.footprint_m);
  EXPECT_EQ(back[0].z_max_m, 0.75);
  EXPECT_TRUE(back[0].on_floor);
  EXPECT_EQ(back[1].id, "2");
  expect_same_polygon(back[1].footprint, b.footprint_m);
  EXPECT_EQ(back[1].z_max_m, 2.1);
  EXPECT_FALSE(back[1].on_floor);  // kind "hanging"
  const json j = json::parse(test::read_text(dir / "objects.json"));
  EXPECT_EQ(j["count"], 2);
  EXPECT_EQ(j["objects"][0]["crop_file"], "objects/object_1.pcd");
  EXPECT_EQ(j["objects"][0]["crop_points"], 12);

  formats::write_objects_csv(dir / "objects.csv", res);
  const std::string csv = test::read_text(dir / "objects.csv");
  EXPECT_EQ(
      csv.substr(0, csv.find('\n')),
      "id,kind,cells,area_m2,center_x_m,center_y_m,length_m,width_m,angle_deg,z_min_m,z_max_m,"
      "point_count,touches_wall");
  EXPECT_NE(csv.find("\n2,hanging,0,0,0.5,0.25,1,0.5,0,2,2.1,0,false\n"), std::string::npos) << csv;
  // Without heights both columns stay empty; objects.json writes them as null, which reads back
  // as "no height" (it was refused as "expected a number" before: map-eval exited 2).
  res.objects[1].has_height = false;
  const std::string csv2 = formats::objects_csv(res);
  EXPECT_NE(csv2.find("\n2,hanging,0,0,0.5,0.25,1,0.5,0,,,0,false\n"), std::string::npos) << csv2;
  formats::write_objects_json(dir / "objects2.json", res, geo, {{"objects/object_1.pcd", 12}, {}});
  const auto back2 = formats::read_objects_json(dir / "objects2.json");
  ASSERT_EQ(back2.size(), 2u);
  EXPECT_EQ(back2[0].z_max_m, 0.75);
  EXPECT_FALSE(back2[1].z_min_m.has_value());
  EXPECT_FALSE(back2[1].z_max_m.has_value());
}

// ------------------------------------------------------------------------------ room border

TEST(RoomGeojson, WriteReadRoundTrip) {
  const fs::path dir = test::scratch_dir();
  border::BorderResult r;
  r.closed = true;
  r.polygon_m = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  r.area_m2 = 12;
  border::Opening o;
  o.a_m = {1, 0};
  o.b_m = {1.9, 0};
  o.width_m = 0.9;
  o.is_door_candidate = true;
  r.openings = {o};
  formats::write_room_geojson(dir / "room.geojson", r);
  const auto rooms = formats::read_room_geojson(dir / "room.geojson");
  ASSERT_EQ(rooms.size(), 1u);  // the opening is a LineString, not a room
  expect_same_polygon(rooms[0], r.polygon_m);
  // No closed border: no room feature, the reason recorded.
  r.closed = false;
  r.reason = "open scan";
  formats::write_room_geojson(dir / "open.geojson", r);
  EXPECT_TRUE(formats::read_room_geojson(dir / "open.geojson").empty());
  EXPECT_EQ(json::parse(test::read_text(dir / "open.geojson"))["reason"], "open scan");
  const json room = formats::room_json(r, GridGeometry({0.5, 0.5}, 0.05, 4, 4));
  EXPECT_EQ(room["openings"][0]["width_m"], 0.9);
  EXPECT_EQ(room["origin_m"], json::array({0.5, 0.5}));
}

// room.geojson holds the room, its openings and the interior objects inside or on it; a box
// that crosses the room's edge or lies outside stays in room.json only (issue 17).
TEST(RoomGeojson, InteriorObjectsOnlyInsideOrOnTheRoom) {
  border::BorderResult r;
  r.closed = true;
  r.polygon_m = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  auto box = [](Eigen::Vector2d lo, Eigen::Vector2d hi) {
    border::InteriorObject o;
    o.min_m = lo;
    o.max_m = hi;
    o.cells = 4;
    return o;
  };
  r.interior_objects = {box({1, 1}, {1.5, 1.5}),    // inside
                        box({0, 2}, {0.5, 3}),      // on the edge (corner of the room)
                        box({3.8, 1}, {4.3, 1.4}),  // crosses the edge
                        box({6, 6}, {7, 7})};       // outside
  const json fc = formats::room_geojson(r);
  std::vector<json> objects;
  for (const auto& f : fc["features"]) {
    const std::string kind = f["properties"]["kind"];
    EXPECT_TRUE(kind == "room" || kind == "opening" || kind == "interior_object") << kind;
    if (kind == "interior_object") objects.push_back(f);
  }
  ASSERT_EQ(objects.size(), 2u);
  EXPECT_EQ(objects[0]["geometry"]["coordinates"][0][0], json::array({1.0, 1.0}));
  EXPECT_EQ(objects[1]["geometry"]["coordinates"][0][0], json::array({0.0, 2.0}));
  EXPECT_EQ(formats::room_json(r, GridGeometry({0, 0}, 0.05, 4, 4))["interior_objects"].size(), 4u);
  r.closed = false;  // no room: no interior object either
  const json open_room =
      formats::room_geojson(r);  // kept: a loop over a temporary's member dangles
  for (const auto& f : open_room["features"]) EXPECT_NE(f["properties"]["kind"], "interior_object");
}

// ------------------------------------------------------------------------------ route

TEST(RouteJson, WriteReadRoundTrip) {
  const fs::path dir = test::scratch_dir();
  Grid<planning::SafeCell> safe(6, 4, planning::SafeCell::kSafe);
  safe.at(0, 0) = planning::SafeCell::kObstacle;
  safe.at(5, 3) = planning::SafeCell::kOutside;
  safe.at(1, 0) = planning::SafeCell::kUnsafe;
  planning::PlanResult res;
  planning::Route route;
  route.commands = {{0.0, 0.2}, {90.0, 0.1}};
  route.waypoints_map = {{0.025, 0.025}, {0.225, 0.025}, {0.225, 0.125}};
  route.moves = 2;
  route.turns = 1;
  route.length_m = 0.3;
  route.source = "paper";
  res.routes = {route};
  res.start_cell = {0, 0};
  res.goal_cell = {4, 2};
  const GridGeometry geo({0, 0}, 0.05, 6, 4);
  const formats::RouteReport rep{&safe, geo, {{0.025, 0.025}, 0.0}, {{0.225, 0.125}, {}}, {},
                                 {},    &res};
  formats::write_route_json(dir / "route.json", rep);
  const json j = json::parse(test::read_text(dir / "route.json"));
  EXPECT_TRUE(j["found"].get<bool>());
  ASSERT_EQ(j["routes"].size(), 1u);
  EXPECT_EQ(j["routes"][0]["commands"][1]["turn_deg"], 90.0);
  EXPECT_EQ(j["routes"][0]["waypoints_map"][2], json::array({0.225, 0.125}));
  EXPECT_EQ(j["start"]["heading_deg"], 0.0);
  EXPECT_TRUE(j["goal"]["heading_deg"].is_null());
  EXPECT_EQ(j["goal"]["cell"], json::array({4, 2}));

  formats::write_safe_map(dir, safe, geo);
  const formats::RosMap m = app::read_ros_map(dir / "safe.yaml");
  EXPECT_EQ(m.geometry, geo);
  EXPECT_EQ(m.cells.at(0, 0), Cell::kWall);
  EXPECT_EQ(m.cells.at(1, 0), Cell::kWall);
  EXPECT_EQ(m.cells.at(5, 3), Cell::kUnknown);
  EXPECT_EQ(m.cells.at(2, 2), Cell::kFree);
}

// ------------------------------------------------------------------------------ ground truth

TEST(GroundTruthJson, WriteReadRoundTrip) {
  const fs::path dir = test::scratch_dir();
  sim::Scene s;
  sim::Room room;
  room.name = "lab";
  room.polygon = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  s.rooms.push_back(room);
  sim::Furniture desk;
  desk.id = "desk";
  desk.type = sim::FurnitureType::kDesk;
  desk.center_m = {3.0, 1.0};
  desk.size_m = {1.2, 0.6};
  s.furniture.push_back(desk);
  s.scanners.push_back({{2.0, 1.5, 1.4}, 0});
  s.scanner.azimuth_step_deg = s.scanner.elevation_step_deg = 4;
  const sim::Scene n = sim::normalised(s);
  const sim::SimResult result = sim::simulate(n);
  const sim::TruthLayout layout = sim::truth_layout(n, sim::build_geometry(n));
  const auto items = sim::furniture_truth(n);
  formats::write_json(dir / "ground_truth.json",
                      formats::ground_truth_json(n, result, layout, "test"));
  const formats::TruthFile t = formats::read_truth_json(dir / "ground_truth.json");
  ASSERT_EQ(t.rooms.size(), 1u);
  EXPECT_EQ(t.rooms[0].name, "lab");
  expect_same_polygon(t.rooms[0].polygon, n.rooms[0].polygon);
  ASSERT_EQ(t.furniture.size(), 1u);
  EXPECT_EQ(t.furniture[0].id, "desk");
  expect_same_polygon(t.furniture[0].footprint, items[0].footprint);
  EXPECT_EQ(t.furniture[0].z_max_m, items[0].z_max_m);
  EXPECT_EQ(t.layout_geometry, layout.geometry);
  EXPECT_EQ(t.layout_image, dir / formats::kTruthLayoutImage);
  const json j = json::parse(test::read_text(dir / "ground_truth.json"));
  EXPECT_EQ(j["generator"].get<std::string>().rfind("test ", 0), 0u);
  EXPECT_EQ(j["cloud"]["points"], result.points.size());
}

// ------------------------------------------------------------------------------ JSON

TEST(Json, WriteReadRoundTripKeepsOrderWhenAsked) {
  const fs::path dir = test::scratch_dir();
  const json j = {{"b", 1}, {"a", {1.5, nullptr, "x"}}};
  formats::write_json(dir / "j.json", j);
  EXPECT_EQ(json::parse(test::read_text(dir / "j.json")), j);
  nlohmann::ordered_json o;
  o["z"] = 1;
  o["a"] = 2;
  formats::write_json(dir / "o.json", o);
  EXPECT_EQ(test::read_text(dir / "o.json"), "{\n  \"z\": 1,\n  \"a\": 2\n}\n");
}

// ------------------------------------------------------------------------------ ROS map reader
// (moved from test_robustness.cpp: plan-route and map-eval read maps through it)

struct MapCase {
  std::string name;
  std::string yaml;
  std::string image;  ///< written as map.pgm ("<none>": not written)
  std::string expect;
  bool budget = false;  ///< BudgetError rather than InputError
};

void PrintTo(const MapCase& c, std::ostream* os) {
  *os << c.name;
}

class RosMapRefuses : public ::testing::TestWithParam<MapCase> {};

TEST_P(RosMapRefuses, WithTypedErrorNamingTheFile) {
  const auto& c = GetParam();
  const auto dir = test::scratch_dir();
  if (c.yaml != "<none>") test::write_text(dir / "map.yaml", c.yaml);
  if (c.image != "<none>") test::write_text(dir / "map.pgm", c.image);
  try {
    app::read_ros_map(dir / "map.yaml", 1'000'000);
    FAIL() << "accepted";
  } catch (const BudgetError& e) {
    EXPECT_TRUE(c.budget) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.expect), std::string::npos) << e.what();
    EXPECT_EQ(e.exit_code(), ExitCode::kBadInput);
  } catch (const InputError& e) {
    EXPECT_FALSE(c.budget) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.expect), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(dir.string()), std::string::npos) << e.what();
    EXPECT_EQ(e.exit_code(), ExitCode::kBadInput);
  }
}

namespace {
const std::string kYaml =
    "image: map.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\n"
    "free_thresh: 0.196\n";
}  // namespace

INSTANTIATE_TEST_SUITE_P(
    Cases, RosMapRefuses,
    ::testing::Values(
        MapCase{"yaml_missing", "<none>", "<none>", "map.yaml: cannot open the map YAML"},
        MapCase{"yaml_invalid", "image: [map.pgm\n", kPgm, "invalid YAML"},
        MapCase{"yaml_not_mapping", "- 1\n", kPgm, "the map YAML is not a mapping"},
        MapCase{"no_image_key", "resolution: 0.05\n", kPgm, "missing key 'image'"},
        MapCase{"resolution_zero", replace_all(kYaml, "0.05", "0"), kPgm,
                "key 'resolution' must be a positive number"},
        MapCase{"resolution_text", replace_all(kYaml, "0.05", "fine"), kPgm,
                "key 'resolution' is not a number"},
        MapCase{"origin_two_values", replace_all(kYaml, "[0.0, 0.0, 0.0]", "[1, 2]"), kPgm,
                "key 'origin' must be a list [x, y, yaw]"},
        MapCase{"origin_infinite", replace_all(kYaml, "[0.0, 0.0, 0.0]", "[.inf, 0, 0]"), kPgm,
                "key 'origin' is not finite"},
        MapCase{"negate_not_0_or_1", replace_all(kYaml, "negate: 0", "negate: 1e300"), kPgm,
                "key 'negate' must be 0 or 1"},
        MapCase{"thresholds_out_of_range", replace_all(kYaml, "0.65", ".nan"), kPgm,
                "keys 'free_thresh' <= 'occupied_thresh' must be numbers in [0, 1]"},
        MapCase{"image_not_found", kYaml, "<none>", "map image not found (named by 'image' in"},
        MapCase{"image_is_a_directory", replace_all(kYaml, "map.pgm", "."), kPgm,
                "is a directory, expected the map image named by 'image' in"},
        MapCase{"image_not_pgm_or_png", kYaml, "GIF89a....",
                "map image is neither PGM (P5/P2) nor PNG"},
        MapCase{"pgm_header_malformed", kYaml, "P5\n2 x\n255\n", "malformed PGM header"},
        MapCase{"pgm_truncated", kYaml, "P5\n100 100\n255\n" + std::string(99, '\0'),
                "PGM of 100 x 100 pixels is truncated"},
        MapCase{"pgm_huge_short", kYaml, "P5\n100000 100000\n255\n\0\0",
                "PGM of 100000 x 100000 pixels is truncated"},
        MapCase{"png_above_budget", kYaml, png_header(65536, 65536),
                "map of 65536 x 65536 cells is above the budget of 1000000 cells", true},
        MapCase{"png_zero_size", kYaml, png_header(0, 5), "map image has no pixels"},
        MapCase{"png_corrupt", kYaml, png_header(4, 4), "cannot decode the map image"}),
    [](const auto& info) { return info.param.name; });
