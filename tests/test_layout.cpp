// Room layout M_r on small hand-drawn grids: passage area, flood fill, furniture, closing.
#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <random>
#include <string>
#include <vector>

#include "indoormap/core/errors.hpp"
#include "indoormap/layout/layout.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "layout_fixtures.hpp"

using namespace indoormap;
using namespace indoormap::layout;

TEST(PassageArea, SquareRingAndLShape) {
  auto walls = parse({
      "..........",
      ".#####....",
      ".#...#....",
      ".#...####.",
      ".#......#.",
      ".########.",
      "..........",
  });
  // Inside: the walls and everything they enclose; the L's notch (top right) and the margin not.
  auto expected = parse({
      "..........",
      ".#####....",
      ".#####....",
      ".########.",
      ".########.",
      ".########.",
      "..........",
  });
  EXPECT_EQ(passage_area(walls).data, expected.data);     // the paper's row AND column passes
  EXPECT_EQ(passage_area(walls, 3).data, expected.data);  // 3 of 4 lines: the same here
}

TEST(PassageArea, AGapInAWallKeepsItsRowsWithThreeOfFourLines) {
  // The right wall has a 2-cell gap (a doorway, or the shadow of a pillar on the scan). The
  // paper's passes drop both rows through the gap from the room; with 3 of 4 lines the room keeps
  // them up to the cells next to the gap, and the outside stays outside.
  auto walls = parse({
      "................",
      ".############...",
      ".#..........#...",
      ".#..........#...",
      ".#..........#...",
      ".#..........#...",
      ".#..............",
      ".#..............",
      ".#..........#...",
      ".#..........#...",
      ".#..........#...",
      ".#..........#...",
      ".############...",
      "................",
  });
  const auto paper = passage_area(walls);
  const auto three = passage_area(walls, 3);
  for (int r = 6; r <= 7; ++r) {
    EXPECT_EQ(paper.at(5, r), 0) << "row " << r;  // the paper's weakness
    for (int c = 1; c <= 10; ++c) EXPECT_EQ(three.at(c, r), 1) << c << "," << r;
    EXPECT_EQ(three.at(14, r), 0);
  }
  for (int r = 0; r < 14; ++r) EXPECT_EQ(three.at(0, r) + three.at(15, r), 0);
  for (int c = 0; c < 16; ++c) EXPECT_EQ(three.at(c, 0) + three.at(c, 13), 0);
}

TEST(Layout, RoomWithFurnitureAndScanner) {
  auto walls = parse({
      "############",
      "#..........#",
      "#..........#",
      "#..........#",
      "#..........#",
      "#..........#",
      "############",
  });
  auto furn = parse(
      {
          "............",
          ".FFF........",
          ".FFF........",
          "............",
          "......FF....",
          "......FF....",
          "............",
      },
      'F');
  const std::vector<Eigen::Vector2d> scanner{{9.5, 3.5}};
  LayoutResult r = build_layout(walls, furn, geo_for(walls), scanner);
  EXPECT_EQ(render(r.layout),
            "WWWWWWWWWWWW\n"
            "WFFF.......W\n"
            "WFFF.......W\n"
            "W..........W\n"
            "W.....FF...W\n"
            "W.....FF...W\n"
            "WWWWWWWWWWWW\n");
  EXPECT_EQ(r.cells_wall, 34);
  EXPECT_EQ(r.cells_furniture, 10);
  EXPECT_EQ(r.cells_free, 40);
  EXPECT_EQ(r.cells_unknown, 0);
  EXPECT_FALSE(r.seeds_estimated);
  ASSERT_EQ(r.seeds.size(), 1u);
  EXPECT_EQ(r.seeds[0], (CellIndex{9, 3}));
}

TEST(Layout, ClosingJoinsFragmentsAndPocketsBehindObjectsAreFurniture) {
  auto walls = parse({
      "###########",
      "#.........#",
      "#.........#",
      "#.........#",
      "#.........#",
      "#.........#",
      "#.........#",
      "###########",
  });
  // Two fragments of one desk, one cell apart: the 3x3 cross closing joins them through their
  // middle row. The cell enclosed between the cabinet and the wall corner is a pocket.
  auto furn = parse(
      {
          "...........",
          "...........",
          ".....FF.FF.",
          ".....FF.FF.",
          ".....FF.FF.",
          ".FF........",
          "..F........",
          "...........",
      },
      'F');
  LayoutParams paper;
  paper.flood_barrier_closing = 0;  // the paper's flood: over the raw furniture map
  LayoutResult r = build_layout(walls, furn, geo_for(walls), {{2.5, 5.5}}, paper);
  EXPECT_EQ(render(r.layout),
            "WWWWWWWWWWW\n"
            "W.........W\n"
            "W....FF.FFW\n"
            "W....FFFFFW\n"
            "W....FF.FFW\n"
            "WFF.......W\n"
            "WFF.......W\n"
            "WWWWWWWWWWW\n");
  LayoutParams no_closing = paper;
  no_closing.furniture_closing_iterations = 0;
  r = build_layout(walls, furn, geo_for(walls), {{2.5, 5.5}}, no_closing);
  EXPECT_EQ(r.layout.at(7, 4), Cell::kFree);       // without the closing the fragments stay apart
  EXPECT_EQ(r.layout.at(1, 1), Cell::kFurniture);  // the corner pocket is furniture either way
}

TEST(Layout, LargeUnreachableRegionStaysUnknown) {
  // Two rooms sharing a wall; the scanner stands in the left one. The right room is not reachable
  // and far larger than a pocket behind furniture, so it must not become one big object.
  auto walls = parse({
      "#################",
      "#.......#.......#",
      "#.......#.......#",
      "#.......#.......#",
      "#################",
  });
  Grid<std::uint8_t> furn(walls.width, walls.height, 0);
  furn.at(9, 2) = 1;
  LayoutParams p;
  p.enclosed_max_area_m2 = 4.0;
  LayoutResult r = build_layout(walls, furn, geo_for(walls), {{2.5, 2.5}}, p);
  EXPECT_EQ(r.layout.at(3, 2), Cell::kFree);
  EXPECT_EQ(r.layout.at(12, 2), Cell::kUnknown);
  // An object in the unreachable room is not furniture of the scanned room.
  EXPECT_EQ(r.layout.at(9, 2), Cell::kUnknown);
}

TEST(Layout, ScannerOnAnObjectMovesToTheNearestFreeCell) {
  auto walls = parse({"#######", "#.....#", "#.....#", "#.....#", "#######"});
  Grid<std::uint8_t> furn(7, 5, 0);
  furn.at(3, 2) = 1;
  LayoutResult r = build_layout(walls, furn, geo_for(walls), {{3.5, 2.5}});
  ASSERT_EQ(r.seeds.size(), 1u);
  EXPECT_EQ(r.layout.at(r.seeds[0]), Cell::kFree);
  EXPECT_EQ(std::abs(r.seeds[0].col - 3) + std::abs(r.seeds[0].row - 2), 1);
}

TEST(Layout, NoScannerEstimatesTheSeedAndSaysSo) {
  auto walls =
      parse({"#########", "#.......#", "#.......#", "#.......#", "#.......#", "#########"});
  Grid<std::uint8_t> furn(9, 6, 0);
  LayoutResult r = build_layout(walls, furn, geo_for(walls), {});
  EXPECT_TRUE(r.seeds_estimated);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings[0].find("no scanner position known"), std::string::npos);
  EXPECT_EQ(r.cells_free, 28);
  // A scanner outside the map is reported and an estimate is used instead.
  r = build_layout(walls, furn, geo_for(walls), {{100.0, 100.0}});
  EXPECT_TRUE(r.seeds_estimated);
  EXPECT_NE(r.warnings[0].find("outside the map"), std::string::npos);
}

TEST(Layout, EmptyGridIsAnEmptyResultNotACrash) {
  Grid<std::uint8_t> empty;
  LayoutResult r = build_layout(empty, empty, GridGeometry({0, 0}, 0.05, 0, 0), {});
  EXPECT_EQ(r.layout.size(), 0u);
  EXPECT_FALSE(r.warnings.empty());
}

TEST(Layout, FreeSpaceEqualsOpenCvFloodFillOnRandomMaps) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    const int w = 40, h = 30;
    Grid<std::uint8_t> walls(w, h, 0), furn(w, h, 0);
    for (int c = 0; c < w; ++c) walls.at(c, 0) = walls.at(c, h - 1) = 1;
    for (int r = 0; r < h; ++r) walls.at(0, r) = walls.at(w - 1, r) = 1;
    std::bernoulli_distribution obstacle(0.25);
    for (int r = 1; r < h - 1; ++r)
      for (int c = 1; c < w - 1; ++c) furn.at(c, r) = obstacle(rng);
    furn.at(20, 15) = 0;
    LayoutParams p;
    p.furniture_closing_iterations = 0;
    p.flood_barrier_closing = 0;
    p.enclosed_max_area_m2 = 0.0;
    LayoutResult res = build_layout(walls, furn, geo_for(walls), {{20.5, 15.5}}, p);
    // Reference: OpenCV 4-connected flood fill over the passable cells.
    cv::Mat pass(h, w, CV_8U, cv::Scalar(0));
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c)
        pass.at<std::uint8_t>(r, c) = !walls.at(c, r) && !furn.at(c, r) ? 1 : 0;
    cv::floodFill(pass, cv::Point(20, 15), cv::Scalar(2), nullptr, cv::Scalar(0), cv::Scalar(0), 4);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c)
        ASSERT_EQ(res.layout.at(c, r) == Cell::kFree, pass.at<std::uint8_t>(r, c) == 2)
            << "trial " << trial << " cell " << c << "," << r;
  }
}

TEST(Layout, HangingLampIsNotWallButAPillarIs) {
  const std::vector<std::string> wall_band{
      "##########", "#........#", "#.LL...P.#", "#.LL.....#", "#........#", "##########",
  };
  Grid<std::uint8_t> walls(10, 6, 0), support(10, 6, 0), furn(10, 6, 0);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 10; ++c) {
      const char ch = wall_band[5 - r][c];
      walls.at(c, r) = ch != '.';
      // The slice below the wall band: the walls and the pillar continue down, the lamp does not.
      support.at(c, r) = ch == '#' || ch == 'P';
      furn.at(c, r) = ch == 'P';
    }
  const GridGeometry geo({0.0, 0.0}, 0.1, 10, 6);  // a 0.2 m x 0.2 m lamp
  LayoutResult r = build_layout(walls, furn, geo, {{0.55, 0.15}}, {}, &support);
  ASSERT_EQ(r.hanging.size(), 1u);
  EXPECT_EQ(r.hanging[0].cells, 4);
  EXPECT_EQ(r.layout.at(2, 3), Cell::kFree);  // under the lamp: floor
  EXPECT_EQ(r.layout.at(7, 3), Cell::kWall);  // the pillar stays an obstacle
  EXPECT_EQ(r.layout.at(0, 0), Cell::kWall);
  // Without the support map the paper's behaviour: the lamp is wall.
  LayoutParams off;
  off.hanging_max_area_m2 = 0.0;
  EXPECT_EQ(build_layout(walls, furn, geo, {{0.55, 0.15}}, off, &support).layout.at(2, 3),
            Cell::kWall);
}

TEST(Layout, SpeckledCabinetFaceStopsTheFlood) {
  auto walls = parse({
      "##########",
      "#........#",
      "#........#",
      "#........#",
      "#........#",
      "##########",
  });
  // A cabinet against the north wall seen only as a speckled front face: without the barrier
  // closing the flood leaks through the gaps and the cabinet's body counts as free floor.
  auto furn = parse(
      {
          "..........",
          "..........",
          ".F.F.F.F..",
          "..........",
          "..........",
          "..........",
      },
      'F');
  LayoutResult r = build_layout(walls, furn, geo_for(walls), {{4.5, 1.5}});
  EXPECT_EQ(r.layout.at(2, 4), Cell::kFurniture);  // behind the face
  EXPECT_EQ(r.layout.at(2, 3), Cell::kFurniture);  // a gap in the face
  EXPECT_EQ(r.layout.at(4, 1), Cell::kFree);
  LayoutParams paper;
  paper.flood_barrier_closing = 0;
  r = build_layout(walls, furn, geo_for(walls), {{4.5, 1.5}}, paper);
  EXPECT_EQ(r.layout.at(2, 4), Cell::kFree);
}

// make_map checks the cloud parameters (their validate()) before any work.
TEST(MakeMap, ValidatesTheCloudParametersFirst) {
  PointCloud cloud;  // empty: any stage would fail with an InputError
  MapParams p;
  p.ghosts.end_skip_m = -0.1;
  try {
    make_map(cloud, p);
    FAIL() << "no UsageError";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), "invalid parameter ghosts.end_skip_m: must be >= 0");
  }
}

// The parameter checks live beside LayoutParams and run in the library entry points, so a
// library user gets the command line's messages.
TEST(LayoutParams, ValidatedByBuildLayoutAndMakeMap) {
  EXPECT_NO_THROW(validate(LayoutParams{}));
  LayoutParams bad;
  bad.passage_min_lines = 5;
  try {
    validate(bad);
    FAIL() << "accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("invalid parameter layout.passage_min_lines"),
              std::string::npos);
  }
  const Grid<std::uint8_t> g(4, 4, 0);
  EXPECT_THROW(build_layout(g, g, geo_for(g), {}, bad), UsageError);
  MapParams mp;
  mp.layout.hanging_gap_m = 0;
  EXPECT_THROW(make_map(PointCloud{}, mp), UsageError);
  LayoutParams thick;
  thick.wall_max_thickness_m = -1;
  EXPECT_THROW(build_layout(g, g, geo_for(g), {}, thick), UsageError);
  for (const double depth : {-0.1, 2.5}) {
    LayoutParams deep;
    deep.hidden_body_max_depth_m = depth;
    try {
      build_layout(g, g, geo_for(g), {}, deep);
      ADD_FAILURE() << depth;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("layout.hidden_body_max_depth_m"), std::string::npos);
    }
  }
}

namespace {

// A 40 x 30 cell room (cells of 5 cm) whose walls are dotted as a 2 degree scan leaves them: one
// wall cell in every `period` along each side.
Grid<std::uint8_t> dotted_room(int period) {
  Grid<std::uint8_t> g(44, 34, 0);
  for (int c = 2; c <= 41; ++c)
    if ((c - 2) % period == 0) g.at(c, 2) = g.at(c, 31) = 1;
  for (int r = 2; r <= 31; ++r)
    if ((r - 2) % period == 0) g.at(2, r) = g.at(41, r) = 1;
  return g;
}

std::int64_t count_class(const Grid<Cell>& g, Cell c) {
  return std::count(g.data.begin(), g.data.end(), c);
}

}  // namespace

// Issue 17, sparse scans: with walls dotted every 4 cells whole rows and diagonals through the gaps
// hold no wall, and with the 3-of-4-lines rule alone most of the room fell out of the passage
// area. Bridging gaps up to passage_bridge_m for the test keeps the whole room.
TEST(PassageArea, DottedWallsOfASparseScanAreBridged) {
  const auto walls = dotted_room(4);
  const Grid<std::uint8_t> none(walls.width, walls.height, 0);
  const GridGeometry geo({0.0, 0.0}, 0.05, walls.width, walls.height);
  LayoutParams off;
  off.passage_bridge_m = 0;
  off.free_needs_evidence = false;
  LayoutParams on = off;
  on.passage_bridge_m = 0.25;  // a square of 7 cells: gaps of up to 6 cells bridged
  const LayoutResult a = build_layout(walls, none, geo, {{1.1, 0.85}}, off);
  const LayoutResult b = build_layout(walls, none, geo, {{1.1, 0.85}}, on);
  const std::int64_t interior = 38 * 28;
  EXPECT_LT(count_class(a.layout, Cell::kFree), interior / 2) << render(a.layout);
  EXPECT_GE(count_class(b.layout, Cell::kFree), interior - 4 * 38) << render(b.layout);
  // Nothing outside the dotted ring is free, and no cell became wall by the bridging.
  for (int r = 0; r < walls.height; ++r)
    for (int c = 0; c < walls.width; ++c) {
      if (c < 2 || c > 41 || r < 2 || r > 31) {
        EXPECT_NE(b.layout.at(c, r), Cell::kFree);
      }
      EXPECT_EQ(b.layout.at(c, r) == Cell::kWall, walls.at(c, r) != 0);
    }
}

// Issue 17, sparse scans: the flood runs only over cells the scan shows free. A closed room whose
// left half alone holds evidence (rays, observed floor): the right half stays unknown, no longer
// free by the paper's flood; a one-cell hole in the evidence does not cut the flood.
TEST(Layout, FreeSpaceOnlyWhereTheScanShowsIt) {
  auto walls = parse({
      "##########",
      "#........#",
      "#........#",
      "#........#",
      "##########",
  });
  const Grid<std::uint8_t> furn(walls.width, walls.height, 0);
  auto evidence = parse(
      {
          "..........",
          ".EEEE.....",
          ".E.EE.....",
          ".EEEE.....",
          "..........",
      },
      'E');
  const LayoutResult with =
      build_layout(walls, furn, geo_for(walls), {{1.5, 1.5}}, {}, nullptr, &evidence);
  EXPECT_EQ(render(with.layout),
            "WWWWWWWWWW\n"
            "W....    W\n"
            "W....    W\n"
            "W....    W\n"
            "WWWWWWWWWW\n");
  LayoutParams paper;
  paper.free_needs_evidence = false;
  const LayoutResult without =
      build_layout(walls, furn, geo_for(walls), {{1.5, 1.5}}, paper, nullptr, &evidence);
  EXPECT_EQ(without.cells_free, 24);
}
