// Tests of the evaluation (lib/sim eval.hpp, apps/map-eval) on hand-made results with known scores.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "indoormap/core/errors.hpp"
#include "indoormap/core/polygon.hpp"
#include "indoormap/formats/ground_truth_json.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/formats/pgm.hpp"
#include "indoormap/formats/ros_map.hpp"
#include "indoormap/sim/eval.hpp"
#include "indoormap/sim/simulate.hpp"
#include "indoormap/sim/world.hpp"
#include "json_support.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using namespace indoormap::sim;
using nlohmann::json;
using test::read_json;

namespace {

/// Truth: a 4 x 3 m room with one cabinet, simulated coarsely and written with its ground truth.
fs::path make_truth(const fs::path& dir) {
  Scene s;
  Room r;
  r.name = "lab";
  r.polygon = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  s.rooms.push_back(r);
  Furniture cab;
  cab.id = "cab";
  cab.type = FurnitureType::kCabinet;
  cab.center_m = {1.0, 2.5};
  cab.size_m = {1.0, 0.4};
  cab.height_m = 1.2;
  s.furniture.push_back(cab);
  Furniture desk = cab;
  desk.id = "desk";
  desk.type = FurnitureType::kDesk;
  desk.center_m = {3.0, 1.0};
  desk.size_m = {1.2, 0.6};
  desk.height_m = 0.75;
  s.furniture.push_back(desk);
  Furniture lamp = cab;
  lamp.id = "lamp";
  lamp.type = FurnitureType::kLamp;
  lamp.center_m = {2, 1.5};
  s.furniture.push_back(lamp);
  s.scanners.push_back({{2.0, 1.5, 1.4}, 0});
  s.scanner.azimuth_step_deg = s.scanner.elevation_step_deg = 2;
  const SimResult sim = simulate(s);
  // What scene-sim writes for map-eval: ground_truth.json and the layout image it names.
  fs::create_directories(dir);
  const Scene n = normalised(s);
  const TruthLayout layout = truth_layout(n, build_geometry(n));
  formats::write_layout_pgm(dir / formats::kTruthLayoutImage, layout.cells);
  formats::write_json(dir / "ground_truth.json",
                      formats::ground_truth_json(n, sim, layout, "scene-sim"));
  return dir / "ground_truth.json";
}

}  // namespace

TEST(EvalLayout, IdenticalAndShiftedGrids) {
  // Truth 4 x 2 cells of 0.5 m at origin (0, 0): row 0 = wall wall free free, row 1 = free x4.
  GridGeometry tg({0, 0}, 0.5, 4, 2);
  Grid<Cell> t(4, 2, Cell::kFree);
  t.at(0, 0) = t.at(1, 0) = Cell::kWall;
  LayoutScores s = evaluate_layout(tg, t, tg, t);
  EXPECT_DOUBLE_EQ(*s.classes[1].iou, 1.0);
  EXPECT_DOUBLE_EQ(*s.classes[3].iou, 1.0);
  EXPECT_FALSE(s.classes[2].iou);  // no furniture anywhere
  EXPECT_DOUBLE_EQ(*s.mean_iou, 1.0);
  EXPECT_DOUBLE_EQ(s.accuracy, 1.0);
  EXPECT_DOUBLE_EQ(s.classes[1].truth_m2, 0.5);
  // Result: one wall cell called furniture, and the grid one cell narrower (x in [0, 1.5]).
  GridGeometry rg({0, 0}, 0.5, 3, 2);
  Grid<Cell> r(3, 2, Cell::kFree);
  r.at(0, 0) = Cell::kWall;
  r.at(1, 0) = Cell::kFurniture;
  s = evaluate_layout(tg, t, rg, r);
  EXPECT_DOUBLE_EQ(*s.classes[1].iou, 0.5);        // wall: 1 of 2 cells
  EXPECT_DOUBLE_EQ(*s.classes[2].iou, 0.0);        // furniture: none right
  EXPECT_DOUBLE_EQ(*s.classes[3].iou, 4.0 / 6.0);  // free: 4 agree; truth has 6 (2 not covered)
  EXPECT_DOUBLE_EQ(s.confusion_m2[3][0], 0.5);     // the uncovered free column counts as unknown
  EXPECT_DOUBLE_EQ(*s.mean_iou, (0.5 + 0.0 + 4.0 / 6.0) / 3);
  // A finer result grid (0.25 m) compares by metric position.
  GridGeometry fg({0, 0}, 0.25, 8, 4);
  Grid<Cell> f(8, 4, Cell::kFree);
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 2; ++row) f.at(c, row) = Cell::kWall;
  s = evaluate_layout(tg, t, fg, f);
  EXPECT_DOUBLE_EQ(*s.classes[1].iou, 1.0);
  EXPECT_DOUBLE_EQ(*s.classes[3].iou, 1.0);
}

TEST(EvalObjects, MatchingRecallPrecisionAndHeights) {
  std::vector<EvalObject> truth(3), result(3);
  truth[0] = {"a", "cabinet", rectangle({0, 0}, {1, 1}, 0), 0.0, 1.0, true};
  truth[1] = {"b", "desk", rectangle({5, 0}, {2, 1}, 0), 0.0, 0.75, true};
  truth[2] = {"c", "bin", rectangle({9, 9}, {0.4, 0.4}, 0), 0.0, 0.4, true};
  result[0] = {"r0", "", rectangle({0.1, 0}, {1, 1}, 0), 0.02, 1.1, true};  // IoU 0.9 / 1.1
  result[1] = {"r1", "", rectangle({5, 0}, {2, 1}, 0), std::nullopt, 0.7, true};
  result[2] = {"r2", "", rectangle({20, 0}, {1, 1}, 0), 0.0, 1.0, true};
  const ObjectScores s = evaluate_objects(truth, result, 0.5);
  EXPECT_EQ(s.matched, 2);
  EXPECT_DOUBLE_EQ(s.recall, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.precision, 2.0 / 3.0);
  ASSERT_EQ(s.matches.size(), 2u);
  EXPECT_EQ(s.matches[0].truth_id, "b");  // best IoU first
  EXPECT_NEAR(s.matches[0].iou, 1.0, 1e-9);
  EXPECT_NEAR(s.matches[1].iou, 0.9 / 1.1, 0.01);
  EXPECT_NEAR(*s.matches[1].z_max_error_m, 0.1, 1e-12);
  EXPECT_NEAR(*s.mean_abs_z_max_error_m, (0.05 + 0.1) / 2, 1e-12);
  EXPECT_NEAR(*s.max_abs_height_error_m, 0.1, 1e-12);
  EXPECT_EQ(s.missed, std::vector<std::string>{"c"});
  EXPECT_EQ(s.spurious, std::vector<std::string>{"r2"});
  // Half overlap (IoU 1/3) is not a match.
  const ObjectScores t =
      evaluate_objects({truth[0]}, {{"h", "", rectangle({0.5, 0}, {1, 1}, 0), {}, {}, true}}, 0.5);
  EXPECT_EQ(t.matched, 0);
}

// map-eval's entry point: params checked, and without include_hanging both sides keep only what
// stands on the floor.
TEST(EvalObjects, ParamsAreValidatedAndHangingItemsLeftOutUnlessAsked) {
  std::vector<EvalObject> truth(2), result(2);
  truth[0] = {"desk", "desk", rectangle({0, 0}, {1, 1}, 0), 0.0, 0.75, true};
  truth[1] = {"lamp", "lamp", rectangle({5, 0}, {1, 1}, 0), 2.0, 2.3, false};
  result[0] = {"1", "", rectangle({0, 0}, {1, 1}, 0), 0.0, 0.75, true};
  result[1] = {"2", "", rectangle({5, 0}, {1, 1}, 0), 2.0, 2.3, false};
  const ObjectScores floor_only = evaluate_objects(truth, result, EvalParams{});
  EXPECT_EQ(floor_only.truth_count, 1);
  EXPECT_EQ(floor_only.result_count, 1);
  EXPECT_EQ(floor_only.matched, 1);
  const ObjectScores all = evaluate_objects(truth, result, EvalParams{0.5, true});
  EXPECT_EQ(all.truth_count, 2);
  EXPECT_EQ(all.matched, 2);
  EXPECT_THROW(evaluate_objects(truth, result, EvalParams{0.0, false}), UsageError);
  EXPECT_THROW(validate(EvalParams{1.5, false}), UsageError);
}

TEST(EvalRooms, HausdorffAndAreaError) {
  std::vector<TruthRoom> truth = {{"lab", "room", rectangle({2, 1.5}, {4, 3}, 0)},
                                  {"corridor", "corridor", rectangle({2, -1.2}, {6, 2}, 0)}};
  const Polygon shifted = rectangle({2.1, 1.5}, {4, 3}, 0);
  const Polygon bigger = rectangle({2, 1.5}, {4.2, 3}, 0);
  const auto m = evaluate_rooms(truth, {shifted, bigger, rectangle({50, 50}, {1, 1}, 0)});
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0].truth_name, "lab");
  EXPECT_NEAR(m[0].hausdorff_m, 0.1, 1e-9);
  EXPECT_NEAR(m[0].area_error_m2, 0.0, 1e-9);
  EXPECT_NEAR(m[0].iou, 3.9 / 4.1, 0.01);
  EXPECT_NEAR(m[1].hausdorff_m, 0.1, 1e-9);
  EXPECT_NEAR(m[1].area_error_m2, 0.6, 1e-9);
  EXPECT_NEAR(m[1].area_error_rel, 0.05, 1e-9);
  EXPECT_EQ(m[2].truth_index, -1);
}

TEST(EvalPolygon, IouOfKnownShapes) {
  EXPECT_NEAR(polygon_iou(rectangle({0, 0}, {1, 1}, 0), rectangle({0.5, 0}, {1, 1}, 0)), 1.0 / 3.0,
              1e-3);
  // Same square turned by 45 degrees: intersection = the regular octagon of inradius 0.5,
  // area 2 (sqrt 2 - 1) = 0.8284; union = 2 - 0.8284.
  const double oct = 2 * (std::sqrt(2.0) - 1);
  EXPECT_NEAR(
      polygon_iou(rectangle({0, 0}, {1, 1}, 0), rectangle({0, 0}, {1, 1}, std::acos(-1.0) / 4)),
      oct / (2 - oct), 2e-3);
  EXPECT_EQ(polygon_iou(rectangle({0, 0}, {1, 1}, 0), rectangle({3, 0}, {1, 1}, 0)), 0.0);
  EXPECT_NEAR(std::abs(signed_area(circle_polygon({0, 0}, 1.0))), 3.14159265, 1e-6);
  EXPECT_NEAR(boundary_hausdorff(rectangle({0, 0}, {2, 2}, 0), rectangle({0, 0}, {2.4, 2}, 0)), 0.2,
              1e-9);
}

TEST(MapEval, HandMadeResultFilesGiveKnownScores) {
  const fs::path dir = test::scratch_dir();
  const fs::path truth = make_truth(dir / "truth");
  const fs::path res = dir / "result";
  fs::create_directories(res);
  // Layout: the truth itself (same grid) but with the cabinet's cells called free.
  const formats::TruthFile tf = formats::read_truth_json(truth);
  Grid<Cell> layout = formats::read_layout_pgm(tf.layout_image, tf.layout_geometry);
  const Grid<Cell> truth_cells = layout;
  std::int64_t n_free = 0, n_cab = 0, n_desk = 0;
  for (int r = 0; r < layout.height; ++r) {
    for (int c = 0; c < layout.width; ++c) {
      const Eigen::Vector2d p = tf.layout_geometry.center_of({c, r});
      if (layout.at(c, r) == Cell::kFree) ++n_free;
      if (layout.at(c, r) == Cell::kFurniture && p.y() > 2.0) {
        layout.at(c, r) = Cell::kFree;
        ++n_cab;
      } else if (layout.at(c, r) == Cell::kFurniture) {
        ++n_desk;
      }
    }
  }
  ASSERT_EQ(n_cab, 20 * 8);  // 1.0 x 0.4 m at 5 cm
  ASSERT_EQ(n_desk, 24 * 12);
  formats::write_layout_pgm(res / "layout.pgm", layout);
  formats::write_map_yaml(res / "map.yaml", formats::map_meta("map.pgm", tf.layout_geometry),
                          formats::MapYamlStyle::kShortest);
  // Objects: the cabinet as an obb (length along 0 degrees), 10 cm too tall; a spurious box.
  test::write_text(res / "objects.json", R"({"objects": [
    {"id": 7, "obb": {"center": [1.0, 2.5], "width_m": 0.4, "length_m": 1.0, "angle_deg": 0}, "z_min_m": 0.0, "z_max_m": 1.3},
    {"id": "x", "footprint": [[3.5, 2.5], [3.9, 2.5], [3.9, 2.9], [3.5, 2.9]], "z_min_m": 0.0, "z_max_m": 0.5},
    {"id": "h", "kind": "hanging", "footprint": [[0.5, 0.5], [0.9, 0.5], [0.9, 0.9], [0.5, 0.9]], "z_min_m": 2.0, "z_max_m": 2.1},
    {"id": "l", "kind": "lamp", "footprint": [[2.5, 0.5], [2.9, 0.5], [2.9, 0.9], [2.5, 0.9]], "z_min_m": 2.3, "z_max_m": 2.4}]})");
  // Room: the truth room shifted by 5 cm.
  test::write_text(res / "room.geojson", R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"kind": "room"},
     "geometry": {"type": "Polygon", "coordinates": [[[0.05, 0], [4.05, 0], [4.05, 3], [0.05, 3], [0.05, 0]]]}}]})");

  const auto r =
      test::run_app("map-eval", "--truth " + truth.string() + " --result " + res.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json e = read_json(res / "eval.json");
  EXPECT_EQ(e["missing"].size(), 0u);
  const json& cls = e["layout"]["classes"];
  EXPECT_DOUBLE_EQ(cls["wall"]["iou"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(cls["furniture"]["iou"].get<double>(),
                   static_cast<double>(n_desk) / (n_desk + n_cab));
  EXPECT_DOUBLE_EQ(cls["free"]["iou"].get<double>(),
                   static_cast<double>(n_free) / (n_free + n_cab));
  const json& ob = e["objects"];
  EXPECT_EQ(ob["truth_count"], 2);  // cabinet and desk; the lamp hangs from the ceiling
  EXPECT_EQ(ob["matched"], 1);
  EXPECT_EQ(ob["matched_all"], 1);   // precision's numerator, written for scripts
  EXPECT_EQ(ob["result_count"], 2);  // "hanging" and "lamp" results are compared only with lamps
  EXPECT_DOUBLE_EQ(ob["recall"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(ob["precision"].get<double>(), 0.5);
  EXPECT_EQ(ob["matches"][0]["truth_id"], "cab");
  EXPECT_EQ(ob["matches"][0]["result_id"], "7");
  EXPECT_NEAR(ob["matches"][0]["z_max_error_m"].get<double>(), 0.1, 1e-9);
  EXPECT_EQ(ob["missed"][0], "desk");
  const json& room = e["room"]["rooms"][0];
  EXPECT_EQ(room["truth_room"], "lab");
  EXPECT_NEAR(room["hausdorff_m"].get<double>(), 0.05, 1e-9);
  EXPECT_NEAR(room["area_error_m2"].get<double>(), 0.0, 1e-9);
  (void)truth_cells;

  // With the lamps, three objects are expected.
  const auto r2 =
      test::run_app("map-eval", "--truth " + truth.string() + " --result " + res.string() +
                                    " --include-hanging -o " + (dir / "e2").string());
  ASSERT_EQ(r2.exit_code, 0) << r2.err;
  EXPECT_EQ(read_json(dir / "e2" / "eval.json")["objects"]["truth_count"], 3);
  EXPECT_EQ(read_json(dir / "e2" / "eval.json")["objects"]["result_count"], 4);
}

TEST(MapEval, MissingOutputsAreReportedNotGuessed) {
  const fs::path dir = test::scratch_dir();
  const fs::path truth = make_truth(dir / "truth");
  const fs::path res = dir / "result";
  fs::create_directories(res);
  auto r = test::run_app("map-eval", "--truth " + truth.string() + " --result " + res.string());
  EXPECT_EQ(r.exit_code, 3);
  json e = read_json(res / "eval.json");
  EXPECT_EQ(e["missing"].size(), 3u);
  EXPECT_EQ(e["layout"]["status"], "missing");
  // Only a room polygon: the other two are missing, the run succeeds.
  test::write_text(res / "room.geojson", R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"kind": "room"},
     "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [4, 3], [0, 3]]]}}]})");
  r = test::run_app("map-eval", "--truth " + truth.string() + " --result " + res.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  e = read_json(res / "eval.json");
  EXPECT_EQ(e["room"]["status"], "ok");
  EXPECT_EQ(e["objects"]["status"], "missing");
  EXPECT_FALSE(e.contains("recall"));
}

TEST(MapEval, BadInputsExitWith2AndNameTheFile) {
  const fs::path dir = test::scratch_dir();
  const fs::path truth = make_truth(dir / "truth");
  const fs::path res = dir / "result";
  fs::create_directories(res);
  // A ROS map.pgm (0 / 205 / 254) passed as layout.pgm.
  Grid<Cell> g(4, 4, Cell::kFree);
  formats::write_layout_pgm(res / "layout.pgm", g);
  std::string bytes = test::read_text(res / "layout.pgm");
  bytes.back() = static_cast<char>(205);
  test::write_text(res / "layout.pgm", bytes);
  formats::write_map_yaml(res / "map.yaml",
                          formats::map_meta("map.pgm", GridGeometry({0, 0}, 0.05, 4, 4)),
                          formats::MapYamlStyle::kShortest);
  auto r = test::run_app("map-eval", "--truth " + truth.string() + " --result " + res.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("layout.pgm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("205"), std::string::npos) << r.err;
  fs::remove(res / "layout.pgm");
  test::write_text(res / "objects.json", R"({"objects": [{"id": 1, "z_max_m": 1}]})");
  r = test::run_app("map-eval", "--truth " + truth.string() + " --result " + res.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("objects.json: key 'objects[0]': needs 'footprint' or 'obb'"),
            std::string::npos)
      << r.err;
  test::write_text(res / "objects.json", "{not json");
  r = test::run_app("map-eval", "--truth " + truth.string() + " --result " + res.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("invalid JSON"), std::string::npos) << r.err;
  r = test::run_app("map-eval",
                    "--truth " + (dir / "nope.json").string() + " --result " + res.string());
  EXPECT_EQ(r.exit_code, 2);
  r = test::run_app("map-eval", "--result " + res.string());
  EXPECT_EQ(r.exit_code, 2);
}

namespace {

// The cell-by-cell raster IoU polygon_iou used before its row scan (the reference).
double iou_cell_by_cell(const Polygon& a, const Polygon& b, double cell_m) {
  const auto [alo, ahi] = bounds(a);
  const auto [blo, bhi] = bounds(b);
  const Eigen::Vector2d lo = alo.cwiseMin(blo), hi = ahi.cwiseMax(bhi);
  if (alo.x() > bhi.x() || blo.x() > ahi.x() || alo.y() > bhi.y() || blo.y() > ahi.y()) return 0.0;
  const double cell = std::max(cell_m, std::sqrt((hi - lo).prod() / 4e6));
  const int w = static_cast<int>(std::ceil((hi.x() - lo.x()) / cell));
  const int h = static_cast<int>(std::ceil((hi.y() - lo.y()) / cell));
  std::int64_t inter = 0, uni = 0;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const Eigen::Vector2d p(lo.x() + (c + 0.5) * cell, lo.y() + (r + 0.5) * cell);
      const bool ia = contains(a, p), ib = contains(b, p);
      inter += ia && ib;
      uni += ia || ib;
    }
  return uni > 0 ? static_cast<double>(inter) / static_cast<double>(uni) : 0.0;
}

}  // namespace

TEST(PolygonIou, RowScanEqualsTheCellByCellReferenceExactly) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0), s(0.05, 1.5);
  int overlapping = 0;
  for (int k = 0; k < 300; ++k) {
    Polygon a = rectangle({u(rng), u(rng)}, {s(rng), s(rng)}, 3 * u(rng));
    Polygon b;
    if (k % 3 == 0) {  // a non-convex star, vertices on grid-aligned values too
      for (int i = 0; i < 10; ++i) {
        const double r = i % 2 ? 0.3 : 0.8, t = i * 0.6283185307179586;
        b.push_back({0.5 * std::round(u(rng)) + r * std::cos(t), r * std::sin(t)});
      }
    } else {
      b = rectangle({u(rng), u(rng)}, {s(rng), s(rng)}, 3 * u(rng));
    }
    const double cell = k % 2 ? 0.01 : 0.05;
    const double ref = iou_cell_by_cell(a, b, cell);
    EXPECT_EQ(polygon_iou(a, b, cell), ref) << k;  // the same cell counts: bit-identical
    overlapping += ref > 0;
  }
  EXPECT_GT(overlapping, 50);
}
