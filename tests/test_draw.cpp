// The drawing layer (lib/draw): label placement without overlap, the kinds' palette, the legend
// with its scale bar and table in layout pictures (objects.png).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <string>
#include <vector>

#include "indoormap/core/object_kind.hpp"
#include "indoormap/draw/labels.hpp"
#include "indoormap/draw/layout_png.hpp"
#include "indoormap/draw/palette.hpp"
#include "test_support.hpp"

namespace indoormap::draw {
namespace {

bool boxes_meet(const cv::Rect& a, const cv::Rect& b) {
  return (a & b).area() > 0;
}

/// Asserts the contract of place_labels on one case: every placed box inside the area, no two
/// boxes intersecting, no leader crossing another box, and the box either centred on its anchor
/// or flagged with a leader when it is away from it.
void check_placement(const std::vector<LabelRequest>& req, const std::vector<PlacedLabel>& out,
                     const cv::Rect& area) {
  ASSERT_EQ(out.size(), req.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (!out[i].placed) continue;
    const cv::Rect& b = out[i].box_px;
    EXPECT_EQ((b & area), b) << "label " << i << " leaves the area";
    EXPECT_EQ(b.size(), req[i].size_px);
    const cv::Point2d c(b.x + b.width / 2.0, b.y + b.height / 2.0);
    const double dist = cv::norm(c - req[i].anchor_px);
    if (!out[i].leader) {
      EXPECT_LT(dist, std::hypot(b.width, b.height) / 2 + 12) << i;
    }
    for (std::size_t j = 0; j < out.size(); ++j) {
      if (j == i || !out[j].placed) continue;
      if (j > i) {
        EXPECT_FALSE(boxes_meet(b, out[j].box_px)) << "labels " << i << " and " << j;
      }
      if (out[i].leader) {
        cv::Point p(req[i].anchor_px), q(nearest_on_box(b, req[i].anchor_px));
        EXPECT_FALSE(cv::clipLine(out[j].box_px, p, q))
            << "leader of " << i << " crosses label " << j;
      }
    }
  }
}

TEST(PlaceLabels, ManyCloseObjectsGetBoxesThatNeverIntersect) {
  // 40 objects, their anchors within a 60 x 60 px patch of a 400 x 300 px map: most labels must
  // move away (leader lines), none may overlap another.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 60.0);
  std::vector<LabelRequest> req;
  for (int i = 1; i <= 40; ++i)
    req.push_back({{170.0 + u(rng), 120.0 + u(rng)}, {i < 10 ? 14 : 22, 14}});
  const cv::Rect area(0, 0, 400, 300);
  const auto out = place_labels(req, area);
  check_placement(req, out, area);
  int placed = 0, leaders = 0;
  for (const auto& p : out) {
    placed += p.placed;
    leaders += p.leader;
  }
  EXPECT_GE(placed, 20);   // the ring round the patch holds at least half of them
  EXPECT_GE(leaders, 10);  // and many could not stay on their anchor
}

TEST(PlaceLabels, LabelsWithoutFreePlaceAreLeftForTheTable) {
  // Ten labels on one anchor in an area of two boxes side by side: a box on the anchor would
  // hide the others' (equal) anchors, so the first moves beside it (no leader at 3 px) and the
  // rest find no place (placed = false): they go to the picture's table.
  const cv::Rect area(0, 0, 44, 14);
  std::vector<LabelRequest> req(10, LabelRequest{{11.0, 7.0}, {20, 14}});
  const auto out = place_labels(req, area);
  check_placement(req, out, area);
  ASSERT_TRUE(out[0].placed);
  EXPECT_EQ(out[0].box_px, cv::Rect(14, 0, 20, 14));
  EXPECT_FALSE(out[0].leader);
  int placed = 0;
  for (const auto& p : out) placed += p.placed;
  EXPECT_EQ(placed, 1);
}

TEST(PlaceLabels, SeparateObjectsKeepTheirLabelsOnTheirAnchors) {
  const std::vector<LabelRequest> req = {{{50, 50}, {20, 12}}, {{150, 50}, {20, 12}}};
  const auto out = place_labels(req, {0, 0, 200, 100});
  ASSERT_TRUE(out[0].placed && out[1].placed);
  EXPECT_EQ(out[0].box_px, cv::Rect(40, 44, 20, 12));
  EXPECT_EQ(out[1].box_px, cv::Rect(140, 44, 20, 12));
  EXPECT_FALSE(out[0].leader || out[1].leader);
}

TEST(PlaceLabels, KeepClearBoxesAndTheAreaEdgeAreRespected) {
  // The anchor's own place is taken by a marker; the label moves beside it, inside the area.
  const std::vector<LabelRequest> req = {{{10, 50}, {16, 10}}};
  const cv::Rect marker(0, 40, 21, 21);
  const auto out = place_labels(req, {0, 0, 100, 100}, {marker});
  ASSERT_TRUE(out[0].placed);
  EXPECT_FALSE(boxes_meet(out[0].box_px, marker));
  EXPECT_GE(out[0].box_px.x, 0);
}

TEST(PlaceLabels, NearestOnBox) {
  const cv::Rect b(10, 20, 30, 10);
  EXPECT_EQ(nearest_on_box(b, {0, 25}), cv::Point2d(10, 25));
  EXPECT_EQ(nearest_on_box(b, {50, 0}), cv::Point2d(40, 20));
  EXPECT_EQ(nearest_on_box(b, {15, 25}), cv::Point2d(15, 25));
}

// --- The kinds' palette -------------------------------------------------------------------

using Lab = cv::Vec3d;

/// CIELAB of an sRGB colour, by OpenCV's conversion (D65, sRGB gamma) as the reference.
Lab to_lab(const std::array<std::uint8_t, 3>& rgb) {
  cv::Mat m(1, 1, CV_32FC3, cv::Scalar(rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0)), lab;
  cv::cvtColor(m, lab, cv::COLOR_RGB2Lab);
  const cv::Vec3f v = lab.at<cv::Vec3f>(0, 0);
  return {v[0], v[1], v[2]};
}

double delta_e76(const Lab& a, const Lab& b) {
  return cv::norm(a - b);
}

/// CIEDE2000 (Sharma, Wu, Dalal 2005), kL = kC = kH = 1.
double delta_e2000(const Lab& p, const Lab& q) {
  const double deg = std::numbers::pi / 180.0;
  const double c1 = std::hypot(p[1], p[2]), c2 = std::hypot(q[1], q[2]);
  const double cm7 = std::pow((c1 + c2) / 2, 7),
               g = 0.5 * (1 - std::sqrt(cm7 / (cm7 + 6103515625.0)));
  const double a1 = (1 + g) * p[1], a2 = (1 + g) * q[1];
  const double c1p = std::hypot(a1, p[2]), c2p = std::hypot(a2, q[2]);
  const auto hue = [&](double b, double a) {
    if (a == 0 && b == 0) return 0.0;
    const double h = std::atan2(b, a) / deg;
    return h < 0 ? h + 360 : h;
  };
  const double h1 = hue(p[2], a1), h2 = hue(q[2], a2);
  double dh = 0;
  if (c1p * c2p != 0) dh = h2 - h1 > 180 ? h2 - h1 - 360 : h2 - h1 < -180 ? h2 - h1 + 360 : h2 - h1;
  const double dL = q[0] - p[0], dC = c2p - c1p;
  const double dH = 2 * std::sqrt(c1p * c2p) * std::sin(dh / 2 * deg);
  const double lm = (p[0] + q[0]) / 2, cmp = (c1p + c2p) / 2;
  double hm = h1 + h2;
  if (c1p * c2p != 0)
    hm = std::abs(h1 - h2) <= 180 ? (h1 + h2) / 2
         : h1 + h2 < 360          ? (h1 + h2 + 360) / 2
                                  : (h1 + h2 - 360) / 2;
  const double t = 1 - 0.17 * std::cos((hm - 30) * deg) + 0.24 * std::cos(2 * hm * deg) +
                   0.32 * std::cos((3 * hm + 6) * deg) - 0.20 * std::cos((4 * hm - 63) * deg);
  const double dth = 30 * std::exp(-std::pow((hm - 275) / 25, 2));
  const double cmp7 = std::pow(cmp, 7), rc = 2 * std::sqrt(cmp7 / (cmp7 + 6103515625.0));
  const double sl = 1 + 0.015 * (lm - 50) * (lm - 50) / std::sqrt(20 + (lm - 50) * (lm - 50));
  const double sc = 1 + 0.045 * cmp, sh = 1 + 0.015 * cmp * t;
  const double rt = -std::sin(2 * dth * deg) * rc;
  return std::sqrt(std::pow(dL / sl, 2) + std::pow(dC / sc, 2) + std::pow(dH / sh, 2) +
                   rt * (dC / sc) * (dH / sh));
}

TEST(KindPalette, ColourDifferenceReferencesHold) {
  // Pairs 1, 7, 17 and 25 of Sharma et al.'s published CIEDE2000 test data.
  EXPECT_NEAR(delta_e2000({50, 2.6772, -79.7751}, {50, 0, -82.7485}), 2.0425, 1e-4);
  EXPECT_NEAR(delta_e2000({50, 0, 0}, {50, -1, 2}), 2.3669, 1e-4);
  EXPECT_NEAR(delta_e2000({50, 2.5, 0}, {73, 25, -18}), 27.1492, 1e-4);
  EXPECT_NEAR(delta_e2000({60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}), 1.2644,
              1e-4);
  // OpenCV's Lab of sRGB red and white.
  const Lab red = to_lab({255, 0, 0}), white = to_lab({255, 255, 255});
  EXPECT_NEAR(red[0], 53.24, 0.1);
  EXPECT_NEAR(red[1], 80.09, 0.2);
  EXPECT_NEAR(red[2], 67.20, 0.2);
  EXPECT_NEAR(white[0], 100.0, 0.1);
  // The palette before issue 19: hanging (0,130,200) and lamp (0,170,170) were "nearly the
  // same" to users, 25.6 apart in CIEDE2000 (CIE76 said 47.8: it overrates blues, hence 2000).
  EXPECT_LT(delta_e2000(to_lab({0, 130, 200}), to_lab({0, 170, 170})), 30.0);
  EXPECT_GT(delta_e76(to_lab({0, 130, 200}), to_lab({0, 170, 170})), 40.0);
}

TEST(KindPalette, EveryPairOfKindsIsClearlyDistinct) {
  for (std::size_t i = 0; i < kObjectKinds.size(); ++i)
    for (std::size_t j = i + 1; j < kObjectKinds.size(); ++j) {
      const Lab a = to_lab(kind_rgb(kObjectKinds[i])), b = to_lab(kind_rgb(kObjectKinds[j]));
      EXPECT_GE(delta_e2000(a, b), 30.0)
          << to_string(kObjectKinds[i]) << " vs " << to_string(kObjectKinds[j]);
      EXPECT_GE(delta_e76(a, b), 25.0)
          << to_string(kObjectKinds[i]) << " vs " << to_string(kObjectKinds[j]);
    }
}

TEST(KindPalette, KindsStandOutFromTheCellsBelowThem) {
  for (const ObjectKind k : kObjectKinds)
    for (const Cell c : {Cell::kFurniture, Cell::kFree, Cell::kUnknown}) {
      const cv::Scalar bgr = cell_colour(c);
      const std::array<std::uint8_t, 3> rgb = {static_cast<std::uint8_t>(bgr[2]),
                                               static_cast<std::uint8_t>(bgr[1]),
                                               static_cast<std::uint8_t>(bgr[0])};
      EXPECT_GE(delta_e2000(to_lab(kind_rgb(k)), to_lab(rgb)), 25.0)
          << to_string(k) << " on " << to_string(c);
    }
  // Ids are drawn in their kind's colour on a white halo: WCAG 2's contrast ratio with white,
  // (1.05) / (Y + 0.05) for relative luminance Y, at least 3 (its minimum for large text).
  const auto linear = [](double v) {
    v /= 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  };
  for (const ObjectKind k : kObjectKinds) {
    const auto c = kind_rgb(k);
    const double y = 0.2126 * linear(c[0]) + 0.7152 * linear(c[1]) + 0.0722 * linear(c[2]);
    EXPECT_GE(1.05 / (y + 0.05), 3.0) << to_string(k);
  }
  const cv::Scalar bgr = kind_colour(ObjectKind::kLamp);
  const auto rgb = kind_rgb(ObjectKind::kLamp);
  EXPECT_EQ(bgr, cv::Scalar(rgb[2], rgb[1], rgb[0]));
}

// --- Layout pictures: legend, scale bar, table --------------------------------------------

/// A 56 x 40 grid of 5 cm cells, free inside a wall ring: 12 px per cell, 1 m = 240 px.
Grid<Cell> ring_grid() {
  Grid<Cell> g(56, 40, Cell::kFree);
  for (int r = 0; r < g.height; ++r)
    for (int c = 0; c < g.width; ++c)
      if (r == 0 || c == 0 || r == g.height - 1 || c == g.width - 1) g.at(c, r) = Cell::kWall;
  return g;
}

/// The longest run of black pixels in any row from y0 down.
int longest_black_run(const cv::Mat& img, int y0) {
  int best = 0;
  for (int y = y0; y < img.rows; ++y) {
    int run = 0;
    for (int x = 0; x < img.cols; ++x) {
      const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
      run = (p[0] < 40 && p[1] < 40 && p[2] < 40) ? run + 1 : 0;
      best = std::max(best, run);
    }
  }
  return best;
}

TEST(LayoutPicture, ScaleBarSurvivesALongLegend) {
  // Six kinds in the legend no longer fit one row with the bar: the legend wraps and the 1 m bar
  // (240 px here) is still drawn.
  const auto dir = test::scratch_dir();
  const Grid<Cell> g = ring_grid();
  const GridGeometry geo(Eigen::Vector2d(0, 0), 0.05, g.width, g.height);
  RenderOptions ro;
  ro.title = "objects";
  for (const ObjectKind k : kObjectKinds)
    ro.legend.push_back({std::string(to_string(k)) + " (id)", kind_rgb(k)});
  write_layout_png(dir / "a.png", g, geo, ro);
  const cv::Mat img = cv::imread((dir / "a.png").string());
  ASSERT_FALSE(img.empty());
  EXPECT_EQ(img.cols, 56 * 12);
  EXPECT_GT(img.rows, 28 + 40 * 12 + 44);  // more than one legend row
  const int bar = longest_black_run(img, 28 + 40 * 12);
  EXPECT_GE(bar, 240);
  EXPECT_LE(bar, 243);
}

TEST(LayoutPicture, UnplaceableLabelsGoToTheTable) {
  // 200 labelled squares on one spot of a small map: the first four ids sit right beside the
  // spot (right, left, above, below), which then blocks every leader line out of it, so the other
  // 196 go to a table and the picture grows by it; with no labels there is no table.
  const auto dir = test::scratch_dir();
  const Grid<Cell> g = ring_grid();
  const GridGeometry geo(Eigen::Vector2d(0, 0), 0.05, g.width, g.height);
  RenderOptions plain, crowded;
  crowded.unlabelled.title = "not labelled:";
  crowded.unlabelled.header = {"id", "kind"};
  crowded.unlabelled.col_px = {40, 80};
  for (int i = 1; i <= 200; ++i) {
    Overlay ov;
    ov.points_m = {{1.3, 0.9}, {1.5, 0.9}, {1.5, 1.1}, {1.3, 1.1}};
    plain.overlays.push_back(ov);
    ov.label = std::to_string(i);
    ov.table_row = {ov.label, "furniture"};
    crowded.overlays.push_back(ov);
  }
  write_layout_png(dir / "plain.png", g, geo, plain);
  write_layout_png(dir / "crowded.png", g, geo, crowded);
  const cv::Mat a = cv::imread((dir / "plain.png").string());
  const cv::Mat b = cv::imread((dir / "crowded.png").string());
  ASSERT_FALSE(a.empty() || b.empty());
  EXPECT_EQ(a.cols, b.cols);
  // A table of n rows in blocks of (16 + 120) px: 18 px per row, a title and a header row.
  const int blocks = (b.cols - 6) / 136;
  const int extra = b.rows - a.rows;
  ASSERT_GT(extra, 0);
  const int rows_per_block = (extra - 6) / 18 - 2;
  EXPECT_EQ((extra - 6) % 18, 0);
  EXPECT_GE(rows_per_block * blocks, 196);
  EXPECT_LT(rows_per_block * blocks, 196 + blocks);
}

}  // namespace
}  // namespace indoormap::draw
