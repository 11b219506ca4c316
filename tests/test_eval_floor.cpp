// Tests of the whole-floor metrics (lib/sim floor_eval.hpp, map-eval's "floor" and "storeys"
// blocks) on small grids drawn by hand, and map-eval on a two-storey scene-sim truth.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "indoormap/formats/pgm.hpp"
#include "indoormap/sim/eval.hpp"
#include "indoormap/sim/floor_eval.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using namespace indoormap::sim;
using nlohmann::json;

namespace {

/// 4 m x 4 m at 5 cm (80 x 80), origin (0, 0): a wall band y in [2.0, 2.2) across, free
/// elsewhere, with a gap of gap_m centred on x = 2 (0: no gap).
Mask wall_grid(double gap_m, Mask* wall = nullptr) {
  const GridGeometry g({0, 0}, 0.05, 80, 80);
  Mask free(80, 80, 1);
  if (wall) *wall = Mask(80, 80, 0);
  for (int r = 0; r < 80; ++r)
    for (int c = 0; c < 80; ++c) {
      const Eigen::Vector2d p = g.center_of({c, r});
      const bool band = p.y() >= 2.0 && p.y() < 2.2;
      if (band && std::abs(p.x() - 2.0) >= gap_m / 2) {
        free.at(c, r) = 0;
        if (wall) wall->at(c, r) = 1;
      }
    }
  return free;
}

TruthDoor door(double width_m) {
  TruthDoor d;
  d.id.assign(1, 'd');
  d.a = {2.0 - width_m / 2, 2.0};
  d.b = {2.0 + width_m / 2, 2.0};
  d.outward = {0, 1};
  d.wall_thickness_m = 0.2;
  return d;
}

}  // namespace

TEST(FloorEval, DoorOpenOnlyWhenTheRobotFitsThrough) {
  const GridGeometry g({0, 0}, 0.05, 80, 80);
  // A 0.9 m gap: a 0.4 m robot passes; 0.3 m: it does not; 0.9 m closed by unknown cells: not.
  EXPECT_EQ(evaluate_doors({door(0.9)}, g, wall_grid(0.9)).open, 1);
  EXPECT_EQ(evaluate_doors({door(0.9)}, g, wall_grid(0.3)).open, 0);
  EXPECT_EQ(evaluate_doors({door(0.9)}, g, wall_grid(0.0)).open, 0);
  Mask half = wall_grid(0.9);
  for (int c = 0; c < 80; ++c) half.at(c, 43) = 0;  // a row of unknown just beyond the wall
  const DoorScores s = evaluate_doors({door(0.9), door(0.9)}, g, half);
  EXPECT_EQ(s.doors, 2);
  EXPECT_EQ(s.open, 0);
  EXPECT_EQ(s.list.size(), 2u);
  // A narrower robot passes the 0.3 m gap.
  EXPECT_EQ(evaluate_doors({door(0.3)}, g, wall_grid(0.3), 0.2).open, 1);
  ASSERT_TRUE(evaluate_doors({door(0.9)}, g, wall_grid(0.9)).open_share);
  EXPECT_FALSE(evaluate_doors({}, g, wall_grid(0.9)).open_share);
}

TEST(FloorEval, ReachabilityCountsComponentsHoldingScanners) {
  const GridGeometry g({0, 0}, 0.05, 80, 80);
  const std::vector<Eigen::Vector2d> two{{1.0, 1.0}, {3.0, 3.0}};
  const ReachScores closed = evaluate_reachability(two, g, wall_grid(0.0));
  EXPECT_EQ(closed.components, 2);
  EXPECT_FALSE(closed.all_reachable);
  const ReachScores open = evaluate_reachability(two, g, wall_grid(0.9));
  EXPECT_EQ(open.components, 1);
  EXPECT_TRUE(open.all_reachable);
  // A scanner on the wall band snaps to the nearest robot cell; one far outside stays unplaced.
  const ReachScores snap =
      evaluate_reachability({{1.0, 2.1}, {3.0, 3.0}, {40.0, 40.0}}, g, wall_grid(0.9));
  EXPECT_EQ(snap.unplaced, 1);
  EXPECT_EQ(snap.component[0], snap.component[1]);
  EXPECT_EQ(snap.components, 2);
}

TEST(FloorEval, WallFacesWithinOneCell) {
  const GridGeometry g({0, 0}, 0.05, 80, 80);
  Grid<Cell> truth(80, 80, Cell::kFree);
  Mask wall;
  wall_grid(0.0, &wall);
  for (std::size_t i = 0; i < wall.data.size(); ++i)
    if (wall.data[i]) truth.data[i] = Cell::kWall;
  // The truth's own walls: every face found, every wall cell within one cell of a face (the
  // band is 4 cells thick: its two middle rows lie 1 cell from a face).
  const FaceScores same = evaluate_wall_faces(g, truth, g, wall);
  EXPECT_EQ(same.truth_faces, 2 * 80);
  EXPECT_DOUBLE_EQ(*same.face_recall, 1.0);
  EXPECT_DOUBLE_EQ(*same.wall_precision, 1.0);
  // A result wall of one row, 1 cell below the lower face: the lower face is found, the upper
  // (4 cells away) is not; the row is within one cell of a face.
  Mask row(80, 80, 0);
  for (int c = 0; c < 80; ++c) row.at(c, 39) = 1;
  const FaceScores one = evaluate_wall_faces(g, truth, g, row);
  EXPECT_DOUBLE_EQ(*one.face_recall, 0.5);
  EXPECT_DOUBLE_EQ(*one.wall_precision, 1.0);
  // Three cells below: nothing within one cell either way.
  Mask far(80, 80, 0);
  for (int c = 0; c < 80; ++c) far.at(c, 37) = 1;
  const FaceScores none = evaluate_wall_faces(g, truth, g, far);
  EXPECT_DOUBLE_EQ(*none.face_recall, 0.0);
  EXPECT_DOUBLE_EQ(*none.wall_precision, 0.0);
}

TEST(FloorEval, SeenIouIgnoresUnseenFreeCells) {
  // 10 x 2 cells at 1 m, both rows alike: truth free 0..7, wall 8..9; seen 0..3.
  const GridGeometry g({0, 0}, 1.0, 10, 2);
  Mask truth_free(10, 2, 0), seen(10, 2, 0), result(10, 2, 0);
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 8; ++c) truth_free.at(c, r) = 1;
    for (int c = 0; c < 4; ++c) seen.at(c, r) = 1;
    // Result free 2..9: seen 2, 3 right, seen 0, 1 missed, 4..7 unseen (ignored), 8, 9 wrong.
    for (int c = 2; c < 10; ++c) result.at(c, r) = 1;
  }
  const SeenIou s = evaluate_seen_free(g, truth_free, seen, g, result);
  EXPECT_DOUBLE_EQ(s.intersection_m2, 4.0);
  EXPECT_DOUBLE_EQ(s.union_m2, 12.0);  // 8 seen + 4 wrong
  EXPECT_DOUBLE_EQ(*s.iou, 1.0 / 3.0);
  // Over every truth-free cell (the truth as its own seen mask): 12 / (16 + 4).
  EXPECT_DOUBLE_EQ(*evaluate_seen_free(g, truth_free, truth_free, g, result).iou, 0.6);
  // A coarser result grid (2 m cells) over the same area compares by position.
  const GridGeometry g2({0, 0}, 2.0, 5, 1);
  Mask r2(5, 1, 0);
  r2.at(1, 0) = 1;  // covers cells 2, 3 of both rows
  const SeenIou c = evaluate_seen_free(g, truth_free, seen, g2, r2);
  EXPECT_DOUBLE_EQ(*c.iou, 0.5);
}

// Issue 17, sparse scans: free cells farther than far_m from every seen cell are "far free".
TEST(FloorEval, FarFreeCountsFreeCellsAwayFromEverySeenCell) {
  // 12 x 1 cells of 0.25 m; seen 0..3 (centres 0.125 .. 0.875 m); result free 0..11.
  const GridGeometry g({0, 0}, 0.25, 12, 1);
  Mask seen(12, 1, 0), result(12, 1, 1);
  for (int c = 0; c < 4; ++c) seen.at(c, 0) = 1;
  // Cells 4 and 5 (centres 1.125, 1.375 m) lie within 0.5 m of cell 3 (0.875 m); 6..11 do not.
  const FarFree f = evaluate_far_free(g, seen, g, result, 0.5);
  EXPECT_DOUBLE_EQ(f.free_m2, 12 * 0.0625);
  EXPECT_DOUBLE_EQ(f.far_m2, 6 * 0.0625);
  EXPECT_DOUBLE_EQ(*f.share, 0.5);
  // A result cell beyond the truth grid is far too; no free cells: no share.
  const GridGeometry wide({0, 0}, 0.25, 14, 1);
  Mask r2(14, 1, 0);
  r2.at(13, 0) = 1;
  EXPECT_DOUBLE_EQ(evaluate_far_free(g, seen, wide, r2, 0.5).far_m2, 0.0625);
  EXPECT_FALSE(evaluate_far_free(g, seen, g, Mask(12, 1, 0), 0.5).share.has_value());
}

// Furniture that a map calls free (a table top the robot would be planned under).
TEST(FloorEval, FurnitureFreeCountsTruthFurnitureTheResultCallsFree) {
  // 4 x 1 cells of 1 m: free, furniture, furniture, wall. The result (0.5 m cells, 8 x 2) calls
  // free the cell holding the first furniture cell's centre (1.5, 0.5) and cells over the truth's
  // free and wall cells, which do not count.
  const GridGeometry g({0, 0}, 1.0, 4, 1);
  Grid<Cell> truth(4, 1, Cell::kFree);
  truth.at(1, 0) = truth.at(2, 0) = Cell::kFurniture;
  truth.at(3, 0) = Cell::kWall;
  const GridGeometry half({0, 0}, 0.5, 8, 2);
  Mask result(8, 2, 0);
  result.at(0, 1) = result.at(3, 1) = result.at(7, 1) = 1;  // row 1 holds y 0.5 .. 1.0
  const FurnitureFree f = evaluate_furniture_free(g, truth, half, result);
  EXPECT_DOUBLE_EQ(f.furniture_m2, 2.0);
  EXPECT_DOUBLE_EQ(f.free_m2, 1.0);
  EXPECT_DOUBLE_EQ(*f.share, 0.5);
  EXPECT_FALSE(
      evaluate_furniture_free(g, Grid<Cell>(4, 1, Cell::kFree), half, result).share.has_value());
}

TEST(FloorEval, ObjectRecallCountsItemsOfTheMinimumAreaPrecisionEverything) {
  auto box = [](std::string id, double x, double side) {
    EvalObject o;
    o.id = std::move(id);
    o.footprint = {{x, 0}, {x + side, 0}, {x + side, side}, {x, side}};
    return o;
  };
  const std::vector<EvalObject> truth{box("big", 0, 1.0), box("bin", 3, 0.2)};  // 1, 0.04 m2
  const std::vector<EvalObject> result{box("r1", 0, 1.0), box("r2", 3, 0.2), box("r3", 6, 0.5)};
  const ObjectScores s = evaluate_objects(truth, result, EvalParams{});
  EXPECT_EQ(s.truth_count, 1);
  EXPECT_EQ(s.truth_below_min_area, 1);
  EXPECT_EQ(s.matched, 1);
  EXPECT_EQ(s.matched_all, 2);
  EXPECT_DOUBLE_EQ(s.recall, 1.0);
  EXPECT_DOUBLE_EQ(s.precision, 2.0 / 3.0);  // the bin's match is no false positive
  EXPECT_TRUE(s.missed.empty());
  EvalParams all;
  all.min_truth_area_m2 = 0;
  EXPECT_EQ(evaluate_objects(truth, result, all).truth_count, 2);
}

TEST(MapEval, TwoStoreyTruthEvaluatedPerStorey) {
  const fs::path dir = test::scratch_dir();
  const fs::path sim = dir / "sim", res = dir / "result";
  auto r = test::run_app(
      "scene-sim", "--random --seed 2 --rooms 2 --storeys 2 --step-deg 3 --truth-cell 0.1 -q -o " +
                       sim.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The result: per storey the truth itself as layout and as navigation map (walls and
  // furniture occupied), with the result floors 3 cm above the truth.
  const json gt = json::parse(test::read_text(sim / "ground_truth.json"));
  ASSERT_EQ(gt["storeys"].size(), 2u);
  json summary = {{"storeys", json::array()}};
  for (int k = 0; k < 2; ++k) {
    const std::string s = "storey_" + std::to_string(k);
    fs::create_directories(res / s);
    fs::copy_file(sim / s / "ground_truth_layout.pgm", res / s / "layout.pgm");
    Grid<std::uint8_t> layout = formats::read_pgm(sim / s / "ground_truth_layout.pgm");
    for (auto& v : layout.data) v = v == 3 ? 254 : v == 0 ? 205 : 0;
    formats::write_pgm(res / s / "map.pgm", layout);
    std::string yaml = test::read_text(sim / s / "ground_truth_layout.yaml");
    yaml = test::replace_all(yaml, "ground_truth_layout.pgm", "map.pgm");
    test::write_text(res / s / "map.yaml", yaml);
    summary["storeys"].push_back(
        {{"floor_z_m", gt["storeys"][k]["floor_z_m"].get<double>() + 0.03}});
  }
  test::write_text(res / "summary.json", summary.dump());
  r = test::run_app("map-eval", "--truth " + (sim / "ground_truth.json").string() + " --result " +
                                    res.string() + " -o " + (dir / "eval").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json e = json::parse(test::read_text(dir / "eval" / "eval.json"));
  ASSERT_EQ(e["storeys"].size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const json& s = e["storeys"][k];
    EXPECT_EQ(s["result"], "storey_" + std::to_string(k));
    EXPECT_NEAR(s["floor_error_m"].get<double>(), 0.03, 1e-9);
    EXPECT_DOUBLE_EQ(s["floor"]["map"]["seen_free_iou"]["iou"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(s["floor"]["layout"]["wall_faces"]["face_recall"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(s["floor"]["doors"]["open_share"].get<double>(), 1.0);  // 2 rooms: 2 doors
    EXPECT_EQ(s["floor"]["doors"]["doors"], 2);
    EXPECT_TRUE(s["floor"]["reachability"]["all_reachable"].get<bool>());
    EXPECT_EQ(s["floor"]["reachability"]["scanners"], 3);  // 2 rooms + corridor
  }
  // The top level (storey 0's truth against the result directory itself): no layout.pgm there,
  // the floor metrics are null with a note, the run still succeeds.
  EXPECT_TRUE(e["floor"]["doors"]["value"].is_null());
  EXPECT_TRUE(e["floor"]["doors"].contains("note"));
}
