// Room border closure (lib/border): properties of the chain and polygon on generated rooms
// (rotated, L-shaped, with doors and furniture along the walls), openings, the choice among
// several rings, open scans, accuracy against the true wall faces, and the real Jacobs scan.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <set>

#include "indoormap/border/border.hpp"
#include "indoormap/cloud_io/load.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "indoormap/sim/eval.hpp"
#include "indoormap/sim/random_scene.hpp"
#include "indoormap/sim/simulate.hpp"
#include "objects_outputs.hpp"
#include "test_support.hpp"

using namespace indoormap;
using indoormap::Polygon;

namespace {

constexpr double kCell = 0.05;

struct Door {
  Eigen::Vector2d a, b;  ///< end points on the wall face (map m)
  double width_m = 0.0;
};

struct Room {
  Grid<Cell> layout;
  GridGeometry geo;
  Polygon face;  ///< true room polygon (wall faces), map m, counter-clockwise
  std::vector<Door> doors;
  Eigen::Vector2d scanner;
};

// Outward miter offset of a counter-clockwise rectilinear polygon.
Polygon offset_rectilinear(const Polygon& p, double d) {
  const std::size_t n = p.size();
  Polygon out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d e1 = (p[i] - p[(i + n - 1) % n]).normalized(),
                          e2 = (p[(i + 1) % n] - p[i]).normalized();
    const Eigen::Vector2d n1(e1.y(), -e1.x()), n2(e2.y(), -e2.x());  // outward for ccw
    out[i] = p[i] + (n1 + n2) * d;
  }
  return out;
}

void fill(cv::Mat& img, const Polygon& poly_m, const GridGeometry& geo, int value) {
  constexpr int shift = 4;
  std::vector<cv::Point> pts;
  for (const auto& v : poly_m) {
    const Eigen::Vector2d u = (v - geo.origin_m()) / geo.cell_m() - Eigen::Vector2d(0.5, 0.5);
    pts.emplace_back(static_cast<int>(std::lround(u.x() * (1 << shift))),
                     static_cast<int>(std::lround(u.y() * (1 << shift))));
  }
  cv::fillPoly(img, std::vector<std::vector<cv::Point>>{pts}, cv::Scalar(value), cv::LINE_8, shift);
}

// A room: rectangle or L (local frame), rotated by yaw, walls wall_m thick outside the faces,
// furniture blocks against some walls, door gaps in others.
Room make_room(std::uint64_t seed, bool l_shape, int doors) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double W = 3.0 + 4.0 * U(rng), H = 2.5 + 3.5 * U(rng);
  Polygon local;
  if (l_shape) {
    const double nw = W * (0.3 + 0.3 * U(rng)), nh = H * (0.3 + 0.3 * U(rng));
    local = {{0, 0}, {W, 0}, {W, H - nh}, {W - nw, H - nh}, {W - nw, H}, {0, H}};
  } else {
    local = {{0, 0}, {W, 0}, {W, H}, {0, H}};
  }
  const double yaw = U(rng) * M_PI / 2, wall_m = 0.05 + 0.1 * U(rng);
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(yaw).toRotationMatrix();
  const Eigen::Vector2d c0(W / 2, H / 2), centre(10.0, 10.0);
  auto place = [&](const Polygon& p) {
    Polygon q;
    for (const auto& v : p) q.push_back(centre + R * (v - c0));
    return q;
  };
  Room room;
  room.geo = GridGeometry({0.0, 0.0}, kCell, 400, 400);
  room.face = place(local);
  cv::Mat img(400, 400, CV_8U, cv::Scalar(0));
  fill(img, place(offset_rectilinear(local, wall_m)), room.geo, static_cast<int>(Cell::kWall));
  // As in a scan, the cells holding the wall face are wall cells (a cell is marked when a point
  // falls in it): the free space is the face polygon shrunk by one cell (cv::fillPoly also fills
  // every cell its boundary touches, half a cell beyond the polygon).
  fill(img, place(offset_rectilinear(local, -kCell)), room.geo, static_cast<int>(Cell::kFree));
  // Edges 0 .. doors-1 get a door; the others a furniture block against the wall.
  const std::size_t n = local.size();
  for (std::size_t e = 0; e < n; ++e) {
    const Eigen::Vector2d a = local[e], b = local[(e + 1) % n];
    const double len = (b - a).norm();
    const Eigen::Vector2d t = (b - a) / len, in(-t.y(), t.x());
    if (static_cast<int>(e) < doors && len > 1.6) {
      const double w = 0.7 + 0.4 * U(rng);
      const double s = 0.3 + (len - w - 0.6) * U(rng);
      const Eigen::Vector2d p = a + t * s, q = a + t * (s + w);
      // The gap reaches into the free space, which stops a cell short of the face.
      fill(img,
           place({p + in * 0.06, q + in * 0.06, q - in * (wall_m + 0.2), p - in * (wall_m + 0.2)}),
           room.geo, static_cast<int>(Cell::kUnknown));
      room.doors.push_back({centre + R * (p - c0), centre + R * (q - c0), w});
    } else if (len > 1.2) {
      const double w = 0.5 + (len - 1.0) * 0.5 * U(rng), s = 0.1 + (len - w - 0.2) * U(rng);
      const double depth = 0.3 + 0.4 * U(rng);
      const Eigen::Vector2d p = a + t * s, q = a + t * (s + w);
      fill(img, place({p, q, q + in * depth, p + in * depth}), room.geo,
           static_cast<int>(Cell::kFurniture));
    }
  }
  room.layout = Grid<Cell>(400, 400);
  for (int r = 0; r < 400; ++r)
    for (int c = 0; c < 400; ++c)
      room.layout.at(c, r) = static_cast<Cell>(img.at<std::uint8_t>(r, c));
  // The scanner stands in the part of the room every shape keeps: near the (0, 0) corner.
  room.scanner = centre + R * (Eigen::Vector2d(0.25 * W, 0.25 * H) - c0);
  return room;
}

void expect_valid_chain(const border::BorderResult& r, const std::string& what) {
  ASSERT_TRUE(r.closed) << what << ": " << r.reason;
  ASSERT_GE(r.chain.size(), 4u) << what;
  std::set<std::pair<int, int>> seen;
  for (std::size_t i = 0; i < r.chain.size(); ++i) {
    const auto a = r.chain[i], b = r.chain[(i + 1) % r.chain.size()];
    EXPECT_EQ(std::max(std::abs(a.col - b.col), std::abs(a.row - b.row)), 1)
        << what << ": step " << i << " is not to an 8-neighbour";
    EXPECT_TRUE(seen.insert({a.col, a.row}).second) << what << ": cell repeats at " << i;
  }
  Polygon raw;
  for (const auto& c : r.chain) raw.emplace_back(c.col, c.row);
  EXPECT_TRUE(indoormap::is_simple(raw)) << what << ": chain polygon self-intersects";
  EXPECT_GT(indoormap::signed_area(raw), 0.0) << what << ": chain not counter-clockwise";
  EXPECT_TRUE(indoormap::is_simple(r.polygon_m)) << what << ": polygon self-intersects";
  EXPECT_GT(indoormap::signed_area(r.polygon_m), 0.0) << what;
  EXPECT_NEAR(r.area_m2, indoormap::signed_area(r.polygon_m), 1e-9);
  EXPECT_NEAR(r.perimeter_m, indoormap::perimeter(r.polygon_m), 1e-9);
}

std::string fmt(const Eigen::Vector2d& v) {
  return "(" + std::to_string(v.x()) + ", " + std::to_string(v.y()) + ")";
}

// Symmetric Hausdorff distance between polygon boundaries sampled every 1 cm.
double hausdorff(const Polygon& a, const Polygon& b) {
  auto sample = [](const Polygon& p) {
    std::vector<Eigen::Vector2d> s;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto u = p[i], v = p[(i + 1) % p.size()];
      const int k = std::max(1, static_cast<int>((v - u).norm() / 0.01));
      for (int j = 0; j < k; ++j) s.push_back(u + (v - u) * (static_cast<double>(j) / k));
    }
    return s;
  };
  auto dist_to = [](const Eigen::Vector2d& q, const Polygon& p) {
    double best = 1e300;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto u = p[i], v = p[(i + 1) % p.size()];
      const double t = std::clamp((q - u).dot(v - u) / (v - u).squaredNorm(), 0.0, 1.0);
      best = std::min(best, (u + (v - u) * t - q).norm());
    }
    return best;
  };
  double h = 0.0;
  for (const auto& q : sample(a)) h = std::max(h, dist_to(q, b));
  for (const auto& q : sample(b)) h = std::max(h, dist_to(q, a));
  return h;
}

// Debug picture (written when INDOORMAP_BORDER_DEBUG names a directory), cropped to the true
// polygon: the layout (unknown black, wall grey, furniture brown, free white), heavy-border cells
// dotted green, chain cells blue, the chain polygon cyan, the result red, the truth green.
void debug_picture(const std::string& path, const Grid<Cell>& lay, const GridGeometry& geo,
                   const border::BorderResult& r, const Polygon& truth) {
  int k = 8;
  Eigen::Vector2d lo = truth[0], hi = truth[0];
  for (const auto& v : truth) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  lo -= Eigen::Vector2d(0.6, 0.6);
  hi += Eigen::Vector2d(0.6, 0.6);
  // INDOORMAP_BORDER_DEBUG_BOX="x0,y0,x1,y1" (map m): a close-up at 16 px per cell.
  if (const char* box = std::getenv("INDOORMAP_BORDER_DEBUG_BOX")) {
    double v[4];
    if (std::sscanf(box, "%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3]) == 4) {
      lo = {v[0], v[1]};
      hi = {v[2], v[3]};
      k = 16;
    }
  }
  const CellIndex a = geo.cell_of(lo), b = geo.cell_of(hi);
  const int c0 = std::max(0, a.col), r0 = std::max(0, a.row);
  const int c1 = std::min(lay.width - 1, b.col), r1 = std::min(lay.height - 1, b.row);
  if (c1 < c0 || r1 < r0) return;
  cv::Mat img((r1 - r0 + 1) * k, (c1 - c0 + 1) * k, CV_8UC3);
  for (int row = r0; row <= r1; ++row)
    for (int c = c0; c <= c1; ++c) {
      cv::Scalar col(0, 0, 0);
      switch (lay.at(c, row)) {
        case Cell::kWall:
          col = {90, 90, 90};
          break;
        case Cell::kFurniture:
          col = {60, 120, 180};
          break;
        case Cell::kFree:
          col = {255, 255, 255};
          break;
        default:
          break;
      }
      const cv::Rect cell((c - c0) * k, (row - r0) * k, k, k);
      img(cell).setTo(col);
      if (r.heavy.size() && r.heavy.at(c, row))
        img(cv::Rect(cell.x + 1, cell.y + 1, 2, 2)).setTo(cv::Scalar(0, 160, 0));
    }
  for (const auto& c : r.chain)
    if (c.col >= c0 && c.col <= c1 && c.row >= r0 && c.row <= r1)
      img(cv::Rect((c.col - c0) * k + 3, (c.row - r0) * k + 3, 3, 3)).setTo(cv::Scalar(255, 0, 0));
  auto draw = [&](const Polygon& p, const cv::Scalar& colour) {
    std::vector<cv::Point> pts;
    for (const auto& v : p) {
      const Eigen::Vector2d u =
          ((v - geo.origin_m()) / geo.cell_m() - Eigen::Vector2d(c0, r0)) * k * 16;
      pts.emplace_back(static_cast<int>(std::lround(u.x())), static_cast<int>(std::lround(u.y())));
    }
    cv::polylines(img, std::vector<std::vector<cv::Point>>{pts}, true, colour, 1, cv::LINE_AA, 4);
  };
  draw(r.chain_polygon_m, {255, 255, 0});
  draw(truth, {0, 200, 0});
  draw(r.polygon_m, {0, 0, 255});
  cv::flip(img, img, 0);  // north up
  cv::imwrite(path, img);
  std::cout << "[ border ] picture " << path << ": x from " << geo.center_of({c0, r0}).x()
            << ", y from " << geo.center_of({c0, r0}).y() << " m (cell centres), " << k
            << " px per cell\n";
}

// Per true edge: the mean distance from its points (20-80 % of its length) to the result
// boundary in mm, negative where the result lies inside the truth (debug output).
std::string edge_offsets_mm(const Polygon& truth, const Polygon& result) {
  std::string out;
  for (std::size_t e = 0; e < truth.size(); ++e) {
    double sum = 0.0;
    int cnt = 0;
    for (double f = 0.2; f <= 0.8; f += 0.05) {
      const Eigen::Vector2d q = truth[e] + (truth[(e + 1) % truth.size()] - truth[e]) * f;
      double best = 1e300;
      for (std::size_t i = 0; i < result.size(); ++i) {
        const auto u = result[i], v = result[(i + 1) % result.size()];
        const double t = std::clamp((q - u).dot(v - u) / (v - u).squaredNorm(), 0.0, 1.0);
        best = std::min(best, (u + (v - u) * t - q).norm());
      }
      sum += indoormap::contains(result, q) ? best : -best;
      ++cnt;
    }
    out += ' ';
    out += std::to_string(std::lround(1000 * sum / cnt));
  }
  return out;
}

}  // namespace

TEST(BorderPolygon, HelpersOnHandCheckableShapes) {
  const Polygon sq{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_DOUBLE_EQ(indoormap::signed_area(sq), 4.0);
  EXPECT_DOUBLE_EQ(indoormap::perimeter(sq), 8.0);
  EXPECT_TRUE(indoormap::contains(sq, {1, 1}));
  EXPECT_FALSE(indoormap::contains(sq, {3, 1}));
  EXPECT_TRUE(indoormap::is_simple(sq));
  EXPECT_FALSE(indoormap::is_simple({{0, 0}, {2, 2}, {2, 0}, {0, 2}}));  // bow tie
  EXPECT_NEAR(border::min_area_rect_area(sq), 4.0, 1e-6);
}

TEST(Border, HeavyBorderOfASquareIsARingAroundIt) {
  Grid<Cell> lay(30, 30, Cell::kUnknown);
  for (int r = 10; r < 20; ++r)
    for (int c = 10; c < 20; ++c)
      lay.at(c, r) = (r == 10 || r == 19 || c == 10 || c == 19) ? Cell::kWall : Cell::kFree;
  const auto heavy = border::heavy_border(lay);
  // 5x5 + cross dilation reaches 3 cells out; two 5x5 erosions take 4 back: the ring spans
  // [7, 22] outside and stops one cell inside the marked square.
  EXPECT_TRUE(heavy.at(7, 15));
  EXPECT_TRUE(heavy.at(10, 15));
  EXPECT_FALSE(heavy.at(11, 15));
  EXPECT_FALSE(heavy.at(6, 15));
  EXPECT_FALSE(heavy.at(15, 15));
  const auto mk = border::mark_border_components(lay, heavy);
  ASSERT_EQ(mk.components.size(), 1u);
  EXPECT_EQ(mk.components[0].label, border::kFirstLeeLabel);
  EXPECT_EQ(mk.components[0].switches, 2);
  EXPECT_EQ(mk.components[0].kind, border::ComponentKind::kRing);
  EXPECT_EQ(mk.lee.at(15, 15), border::lee_value(border::LeeMark::kRoom));
  EXPECT_EQ(mk.lee.at(0, 0), border::lee_value(border::LeeMark::kVirgin));
  EXPECT_TRUE(border::is_lee_label(mk.lee.at(7, 15)));
  // Tracing writes the opening lines on the mid-line (row 14 of the ring's rows 7 .. 22) and the
  // wave into the ring.
  Grid<std::int32_t> lee = mk.lee;
  const border::RingTrace t = border::trace_ring(lee, mk.components[0]);
  ASSERT_TRUE(t) << t.why;
  EXPECT_TRUE(t.why.empty());
  EXPECT_GE(t.chain.size(), 4u);
  EXPECT_EQ(lee.at(7, 14), border::lee_value(border::LeeMark::kOpenStart));
  EXPECT_EQ(lee.at(7, 13), border::lee_value(border::LeeMark::kOpenEnd));
  EXPECT_EQ(lee.at(7, 15), 1);  // the wave starts beside the opening line
  EXPECT_TRUE(border::is_lee_distance(lee.at(15, 22)));
}

TEST(Border, TraceRingGivesTheReasonWhenTheRingIsBroken) {
  Grid<Cell> lay(30, 30, Cell::kUnknown);
  for (int r = 10; r < 20; ++r)
    for (int c = 10; c < 20; ++c)
      lay.at(c, r) = (r == 10 || r == 19 || c == 10 || c == 19) ? Cell::kWall : Cell::kFree;
  auto mk = border::mark_border_components(lay, border::heavy_border(lay));
  ASSERT_EQ(mk.components.size(), 1u);
  for (int r = 15; r < 30; ++r)  // cut the ring's top side (rows 19 .. 22) at column 15
    if (mk.lee.at(15, r) == mk.components[0].label)
      mk.lee.at(15, r) = border::lee_value(border::LeeMark::kVirgin);
  const border::RingTrace t = border::trace_ring(mk.lee, mk.components[0]);
  EXPECT_FALSE(t);
  EXPECT_TRUE(t.chain.empty());
  EXPECT_NE(t.why.find("broken"), std::string::npos) << t.why;
}

TEST(Border, FaceFitThresholdsInMetresAreTheTunedCellCountsAtTheDefaultCell) {
  const border::BorderParams p;
  const GridGeometry geo({0, 0}, 0.05, 1, 1);
  EXPECT_EQ(geo.to_cells(p.face_out_reach_m), 4.0);
  EXPECT_EQ(geo.to_cells(p.chamfer_margin_m), 4.0);
  EXPECT_EQ(geo.to_cells(p.recess_margin_m), 4.0);
  // 1.5 cells: no double gives exactly 1.5 at 0.05 m; 0.075 m gives the double just below.
  for (const double v : {p.face_in_margin_m, p.face_tol_m, p.shadow_chain_tol_m})
    EXPECT_DOUBLE_EQ(geo.to_cells(v), 1.5);
}

TEST(Border, PropertiesOnManyGeneratedRooms) {
  int checked = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const bool l_shape = seed % 2 == 0;
    const Room room = make_room(seed, l_shape, static_cast<int>(seed % 3));
    const auto r = border::close_border(room.layout, room.geo, {room.scanner});
    const std::string what = "seed " + std::to_string(seed) + (l_shape ? " (L)" : " (rect)");
    expect_valid_chain(r, what);
    EXPECT_TRUE(indoormap::contains(r.polygon_m, room.scanner)) << what;
    ++checked;
  }
  EXPECT_EQ(checked, 40);
}

TEST(Border, DoorGapsAreFoundWithTheirWidth) {
  int doors = 0, good_width = 0;
  for (std::uint64_t seed = 100; seed < 120; ++seed) {
    const Room room = make_room(seed, seed % 2 == 1, 2);
    const auto r = border::close_border(room.layout, room.geo, {room.scanner});
    ASSERT_TRUE(r.closed) << r.reason;
    for (const auto& d : room.doors) {
      ++doors;
      const Eigen::Vector2d mid = 0.5 * (d.a + d.b);
      const border::Opening* found = nullptr;
      for (const auto& o : r.openings)
        if ((0.5 * (o.a_m + o.b_m) - mid).norm() < 0.3) found = &o;
      std::string seen;
      for (const auto& o : r.openings) {
        const Eigen::Vector2d om = 0.5 * (o.a_m + o.b_m);
        seen += " (" + std::to_string(om.x()) + ", " + std::to_string(om.y()) + ")";
      }
      ASSERT_NE(found, nullptr) << "seed " << seed << ": door at (" << mid.x() << ", " << mid.y()
                                << ") not found; openings at" << seen;
      if (std::abs(found->width_m - d.width_m) <= 0.12 && found->is_door_candidate) ++good_width;
    }
    EXPECT_EQ(r.openings.size(), room.doors.size()) << "seed " << seed << ": spurious openings";
  }
  EXPECT_GE(doors, 30);
  // Every door is found, a door candidate within 0.12 m of its width (before the hand-built walls
  // marked the cell holding the face, 3 of 39 doors with a furniture block or a corner as a jamb
  // measured wider).
  EXPECT_EQ(good_width, doors) << good_width << " of " << doors;
  std::cout << "[ doors ] " << doors << " doors found, " << good_width
            << " with width within 0.12 m\n";
}

// Accuracy against the true wall faces on hand-built layouts: rotated rectangles and L-shapes with
// 1-3 cell walls, furniture against the walls and door gaps without lintels. The targets
// are Hausdorff <= 0.15 m and area error <= 3 %; every room is within 0.15 m, the area error
// within 4 % (docs/border-closure.md). INDOORMAP_BORDER_DEBUG=DIR prints every room's figures
// and writes DIR/room_<seed>.png.
TEST(Border, AccuracyAgainstTrueWallFaces) {
  double worst_h = 0.0, worst_a = 0.0;
  std::vector<double> hs, as;
  for (std::uint64_t seed = 200; seed < 225; ++seed) {
    const Room room = make_room(seed, seed % 3 == 0, static_cast<int>(seed % 2));
    const auto r = border::close_border(room.layout, room.geo, {room.scanner});
    ASSERT_TRUE(r.closed) << r.reason;
    if (const char* dir = std::getenv("INDOORMAP_BORDER_DEBUG"))
      debug_picture(std::string(dir) + "/room_" + std::to_string(seed) + ".png", room.layout,
                    room.geo, r, room.face);
    const double h = hausdorff(r.polygon_m, room.face);
    const double true_area = indoormap::signed_area(room.face);
    const double rel = std::abs(r.area_m2 - true_area) / true_area;
    EXPECT_LE(h, 0.15) << "seed " << seed << (r.warnings.empty() ? "" : ": " + r.warnings[0]);
    EXPECT_LE(rel, 0.04) << "seed " << seed << ": area " << r.area_m2 << " vs " << true_area;
    hs.push_back(h);
    as.push_back(rel);
    if (std::getenv("INDOORMAP_BORDER_DEBUG"))
      std::cout << "[ accuracy ] seed " << seed << " true " << true_area << " poly " << r.area_m2
                << " chainpoly " << indoormap::signed_area(r.chain_polygon_m) << " h " << h
                << " hchain " << hausdorff(r.chain_polygon_m, room.face) << " edge offsets"
                << edge_offsets_mm(room.face, r.polygon_m) << " mm\n";
    worst_h = std::max(worst_h, h);
    worst_a = std::max(worst_a, rel);
  }
  std::sort(hs.begin(), hs.end());
  std::sort(as.begin(), as.end());
  EXPECT_LE(hs[hs.size() / 2], 0.075);
  EXPECT_LE(as[as.size() / 2], 0.015);
  const auto within = std::count_if(hs.begin(), hs.end(), [](double h) { return h <= 0.15; });
  std::cout << "[ accuracy ] 25 hand-built rooms: median Hausdorff " << hs[hs.size() / 2]
            << " m (worst " << worst_h << ", " << within << "/25 <= 0.15 m), median area error "
            << 100 * as[as.size() / 2] << " % (worst " << 100 * worst_a << " %)\n";
}

// A round pillar (radius_m) at centre as a scanner at scanner sees it: the lit part of its rim
// (rim_m deep) is wall, its inside and everything behind it (its shadow, walls included) unknown.
void add_round_pillar(Grid<Cell>& lay, const GridGeometry& geo, const Eigen::Vector2d& scanner,
                      const Eigen::Vector2d& centre, double radius_m, double rim_m = 0.1) {
  for (int r = 0; r < geo.height(); ++r)
    for (int c = 0; c < geo.width(); ++c) {
      const Eigen::Vector2d p = geo.center_of({c, r});
      const Eigen::Vector2d ray = (p - scanner).normalized();
      const double along = (centre - scanner).dot(ray);
      const double miss = (scanner + ray * along - centre).norm();
      // The ray enters the pillar more than the rim's depth before it reaches p.
      const bool behind =
          along > 0 && miss <= radius_m &&
          along - std::sqrt(radius_m * radius_m - miss * miss) < (p - scanner).norm() - rim_m;
      const double to_centre = (p - centre).norm();
      if (to_centre <= radius_m && to_centre > radius_m - rim_m && !behind)
        lay.at(c, r) = Cell::kWall;  // the lit rim
      else if (to_centre <= radius_m || (behind && lay.at(c, r) != Cell::kUnknown))
        lay.at(c, r) = Cell::kUnknown;  // the pillar's inside and its shadow
    }
}

Grid<Cell> to_layout(const cv::Mat& img) {
  Grid<Cell> lay(img.cols, img.rows);
  for (int r = 0; r < img.rows; ++r)
    for (int c = 0; c < img.cols; ++c) lay.at(c, r) = static_cast<Cell>(img.at<std::uint8_t>(r, c));
  return lay;
}

// A rectangular room (faces x in [1, 6] m, y in [1, 4] m, walls 0.1 m) as a single scan sees it:
// a round pillar (radius 0.3 m) stands 0.7 m in front of the north wall and hides a wedge of the
// floor and of that wall from the scanner (unknown cells reaching the wall, 1.1 m wide there; of
// the pillar only the lit part of its rim is seen). On the south wall a column (1.2 m wide, 0.5 m
// deep) protrudes into the room; its three faces are seen (wall cells), its inside is not: unknown,
// as the shadow. The polygon runs straight along the north wall across the shadow, and keeps the
// column's notch.
TEST(Border, ShadowBehindAPillarIsBridgedASeenColumnKeepsItsNotch) {
  const GridGeometry geo({0.0, 0.0}, kCell, 140, 100);
  const Polygon truth{{1.0, 1.0}, {3.8, 1.0}, {3.8, 1.5}, {5.0, 1.5},
                      {5.0, 1.0}, {6.0, 1.0}, {6.0, 4.0}, {1.0, 4.0}};
  cv::Mat img(geo.height(), geo.width(), CV_8U, cv::Scalar(0));
  fill(img, offset_rectilinear(truth, 0.1), geo, static_cast<int>(Cell::kWall));
  fill(img, offset_rectilinear(truth, -kCell), geo, static_cast<int>(Cell::kFree));
  // The column's inside (behind its 0.1 m faces) and the wall behind it are not seen.
  fill(img, {{3.9, 0.85}, {4.9, 0.85}, {4.9, 1.4}, {3.9, 1.4}}, geo,
       static_cast<int>(Cell::kUnknown));
  Grid<Cell> lay = to_layout(img);
  const Eigen::Vector2d scanner(2.5, 1.8);
  add_round_pillar(lay, geo, scanner, {2.5, 3.0}, 0.3);
  const auto r = border::close_border(lay, geo, {scanner});
  if (const char* dir = std::getenv("INDOORMAP_BORDER_DEBUG"))
    debug_picture(std::string(dir) + "/shadow_room.png", lay, geo, r, truth);
  expect_valid_chain(r, "room with a pillar's shadow");
  EXPECT_TRUE(r.warnings.empty()) << r.warnings[0];
  const double h = hausdorff(r.polygon_m, truth);
  const double rel = (r.area_m2 - indoormap::signed_area(truth)) / indoormap::signed_area(truth);
  EXPECT_LE(h, 0.15) << "Hausdorff to the true faces";
  EXPECT_LE(std::abs(rel), 0.02) << "area " << r.area_m2;
  // Along the north wall (y = 4 m) the polygon has no vertex below 3.8 m between x 1.5 and 5.5 m.
  for (const auto& v : r.polygon_m) {
    if (v.x() > 1.5 && v.x() < 5.5 && v.y() > 2.5) {
      EXPECT_GT(v.y(), 3.8) << fmt(v);
    }
  }
  // The shadow's flanks run along free space, but they are no opening of the room.
  EXPECT_TRUE(r.openings.empty()) << r.openings.size() << " opening(s), the first at "
                                  << fmt(r.openings[0].a_m);
  // The column stays outside the polygon, and its front corners are vertices. (The chain cuts
  // the column's hollow at 45 degrees, and a face line may turn only 30 degrees from its chain
  // edge: the flanks lean by up to 0.1 m.)
  EXPECT_FALSE(indoormap::contains(r.polygon_m, {4.4, 1.35}));
  for (const Eigen::Vector2d& corner : {Eigen::Vector2d(3.8, 1.5), Eigen::Vector2d(5.0, 1.5)}) {
    double best = 1e300;
    for (const auto& v : r.polygon_m) best = std::min(best, (v - corner).norm());
    EXPECT_LE(best, 0.1) << "column corner " << fmt(corner);
  }
}

// The same room without the column; the pillar (radius 0.35 m) stands before the north-east
// corner, seen from the far side of the room, and hides the corner and the ends of both walls
// (0.55 m of the north wall, 0.7 m of the east one). The polygon takes the two walls to their
// crossing across the shadow. Beside it, a room whose north-east corner is cut by two seen walls
// with the unseen outside behind them (a bay): its chain cuts into the corner like the shadow's,
// but its flanks are wall faces, and the cut stays.
TEST(Border, ShadowOverACornerIsBridgedToTheWallsCrossingASeenChamferStays) {
  const GridGeometry geo({0.0, 0.0}, kCell, 140, 100);
  const Polygon truth{{1.0, 1.0}, {6.0, 1.0}, {6.0, 4.0}, {1.0, 4.0}};
  cv::Mat img(geo.height(), geo.width(), CV_8U, cv::Scalar(0));
  fill(img, offset_rectilinear(truth, 0.1), geo, static_cast<int>(Cell::kWall));
  fill(img, offset_rectilinear(truth, -kCell), geo, static_cast<int>(Cell::kFree));
  Grid<Cell> lay = to_layout(img);
  const Eigen::Vector2d scanner(2.0, 1.8);
  add_round_pillar(lay, geo, scanner, {5.0, 3.3}, 0.35);
  auto r = border::close_border(lay, geo, {scanner});
  if (const char* dir = std::getenv("INDOORMAP_BORDER_DEBUG"))
    debug_picture(std::string(dir) + "/corner_shadow_room.png", lay, geo, r, truth);
  expect_valid_chain(r, "room with a pillar's shadow over a corner");
  EXPECT_TRUE(r.warnings.empty()) << r.warnings[0];
  EXPECT_LE(hausdorff(r.polygon_m, truth), 0.15) << "Hausdorff to the true faces";
  EXPECT_NEAR(r.area_m2, 15.0, 0.3);
  double best = 1e300;
  for (const auto& v : r.polygon_m) best = std::min(best, (v - Eigen::Vector2d(6.0, 4.0)).norm());
  EXPECT_LE(best, 0.1) << "the hidden corner is a vertex";
  EXPECT_TRUE(r.openings.empty()) << r.openings.size() << " opening(s), the first at "
                                  << fmt(r.openings[0].a_m);

  // The cut corner in two facets, so the chain's detour has a vertex well inside both walls.
  const Polygon cut{{1.0, 1.0}, {6.0, 1.0}, {6.0, 3.0}, {5.7, 3.7}, {5.0, 4.0}, {1.0, 4.0}};
  auto miter = [](const Polygon& p, double d) {  // outward offset of a convex ccw polygon
    const std::size_t n = p.size();
    Polygon out(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d e1 = (p[i] - p[(i + n - 1) % n]).normalized(),
                            e2 = (p[(i + 1) % n] - p[i]).normalized();
      const Eigen::Vector2d n1(e1.y(), -e1.x()), n2(e2.y(), -e2.x());
      out[i] = p[i] + (n1 + n2) * (d / (1.0 + n1.dot(n2)));
    }
    return out;
  };
  cv::Mat img2(geo.height(), geo.width(), CV_8U, cv::Scalar(0));  // unknown behind the walls
  fill(img2, miter(cut, 0.1), geo, static_cast<int>(Cell::kWall));
  fill(img2, miter(cut, -kCell), geo, static_cast<int>(Cell::kFree));
  r = border::close_border(to_layout(img2), geo, {scanner});
  if (const char* dir = std::getenv("INDOORMAP_BORDER_DEBUG"))
    debug_picture(std::string(dir) + "/chamfer_room.png", to_layout(img2), geo, r, cut);
  expect_valid_chain(r, "room with a cut corner");
  EXPECT_LE(hausdorff(r.polygon_m, cut), 0.15) << "Hausdorff to the true faces";
  EXPECT_NEAR(r.area_m2, indoormap::signed_area(cut), 0.3);
  EXPECT_FALSE(indoormap::contains(r.polygon_m, {5.85, 3.85}));
}

TEST(Border, ScannerChoosesAmongSeveralRings) {
  // Two closed rooms side by side: each scanner picks its own room; the other is a ring.
  Grid<Cell> lay(100, 50, Cell::kUnknown);
  auto box = [&](int c0, int c1) {
    for (int r = 10; r < 40; ++r)
      for (int c = c0; c < c1; ++c)
        lay.at(c, r) = (r == 10 || r == 39 || c == c0 || c == c1 - 1) ? Cell::kWall : Cell::kFree;
  };
  box(5, 40);
  box(55, 95);
  const GridGeometry geo({0, 0}, kCell, 100, 50);
  const auto left = border::close_border(lay, geo, {geo.center_of({20, 25})});
  const auto right = border::close_border(lay, geo, {geo.center_of({75, 25})});
  expect_valid_chain(left, "left");
  expect_valid_chain(right, "right");
  EXPECT_LT(left.polygon_m[0].x(), 2.0);
  EXPECT_GT(right.polygon_m[0].x(), 2.5);
  ASSERT_EQ(left.interior_objects.size(), 1u);
  EXPECT_EQ(left.interior_objects[0].kind, border::ComponentKind::kRing);
  // A scanner outside both rooms: no closed border containing it.
  const auto none = border::close_border(lay, geo, {geo.center_of({47, 5})});
  EXPECT_FALSE(none.closed);
  EXPECT_NE(none.reason.find("contains the scanner"), std::string::npos) << none.reason;
}

TEST(Border, RingInsideARoomIsAnInteriorRing) {
  // A room with a large unobserved block in the middle (an installation): its border is a ring
  // inside the room; the scanner beside it picks the room border.
  Grid<Cell> lay(80, 80, Cell::kUnknown);
  for (int r = 5; r < 75; ++r)
    for (int c = 5; c < 75; ++c)
      lay.at(c, r) = (r == 5 || r == 74 || c == 5 || c == 74) ? Cell::kWall : Cell::kFree;
  for (int r = 30; r < 50; ++r)
    for (int c = 30; c < 50; ++c) lay.at(c, r) = Cell::kUnknown;
  const GridGeometry geo({0, 0}, kCell, 80, 80);
  const auto res = border::close_border(lay, geo, {geo.center_of({15, 15})});
  expect_valid_chain(res, "room with installation");
  EXPECT_NEAR(res.area_m2, 3.4 * 3.4, 0.35);
  ASSERT_FALSE(res.interior_objects.empty());
  bool ring = false;
  for (const auto& o : res.interior_objects) ring |= o.kind == border::ComponentKind::kRing;
  EXPECT_TRUE(ring);
}

TEST(Border, OpenScanIsReportedNotThrown) {
  // Two walls of a corner and free space beyond what the walls enclose (an open scan).
  Grid<Cell> lay(60, 60, Cell::kUnknown);
  for (int r = 10; r < 50; ++r)
    for (int c = 10; c < 50; ++c) lay.at(c, r) = (r == 10 || c == 10) ? Cell::kWall : Cell::kFree;
  const GridGeometry geo({0, 0}, kCell, 60, 60);
  const auto res = border::close_border(lay, geo, {geo.center_of({30, 30})});
  EXPECT_FALSE(res.closed);
  EXPECT_FALSE(res.reason.empty());
  EXPECT_NE(res.reason.find("open"), std::string::npos) << res.reason;
  const auto empty = border::close_border(Grid<Cell>(10, 10, Cell::kUnknown),
                                          GridGeometry({0, 0}, kCell, 10, 10), {});
  EXPECT_FALSE(empty.closed);
  EXPECT_NE(empty.reason.find("no marked cells"), std::string::npos);
}

TEST(Border, BrokenPreconditionsThrowTypedErrors) {
  Grid<Cell> lay(10, 10, Cell::kFree);
  EXPECT_THROW(border::close_border(lay, GridGeometry({0, 0}, kCell, 11, 10), {}), Error);
  border::BorderParams p;
  p.dilate_full_size = 4;
  EXPECT_THROW(border::close_border(lay, GridGeometry({0, 0}, kCell, 10, 10), {}, p), UsageError);
  p = {};
  p.door_min_m = 2.0;
  p.door_max_m = 1.0;
  EXPECT_THROW(p.validate(), UsageError);
  p = {};
  p.face_tol_m = 0;
  try {
    p.validate();
    ADD_FAILURE() << "face_tol_m = 0 passed";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("border.face_tol_m"), std::string::npos) << e.what();
  }
  p = {};
  p.corner_shadow_min_turn_deg = 130;  // above the maximum
  EXPECT_THROW(border::close_border(lay, GridGeometry({0, 0}, kCell, 10, 10), {}, p), UsageError);
  p = {};
  p.max_cells = 50;
  EXPECT_THROW(border::close_border(lay, GridGeometry({0, 0}, kCell, 10, 10), {}, p), BudgetError);
}

TEST(BorderJacobs, OneClosedRoughlyRectangularPolygonWithTheDoor) {
  INDOORMAP_REQUIRE_DATA(dir, "jacobs-thermocolorlab");
  auto loaded = cloud_io::load_clouds({dir.string()}, {});
  const auto m = layout::make_map(std::move(loaded.cloud), {});
  const auto r = border::close_border(m);
  expect_valid_chain(r, "jacobs");
  ASSERT_FALSE(m.cloud_map.scanners.empty());
  const Eigen::Vector2d s(m.cloud_map.scanners[0].x(), m.cloud_map.scanners[0].y());
  EXPECT_TRUE(indoormap::contains(r.polygon_m, s));
  const double rect = border::min_area_rect_area(r.polygon_m);
  EXPECT_GT(r.area_m2, 0.85 * rect) << "area " << r.area_m2 << " vs min-area rectangle " << rect;
  EXPECT_GT(r.area_m2, 25.0);
  EXPECT_LT(r.area_m2, 60.0);
  // The door to the corridor: a door-sized opening through which the corridor is seen.
  int doors = 0;
  for (const auto& o : r.openings) doors += o.is_door_candidate ? 1 : 0;
  EXPECT_GE(doors, 1);
  std::cout << "[ jacobs ] area " << r.area_m2 << " m2, perimeter " << r.perimeter_m << " m, "
            << r.openings.size() << " opening(s)\n";
}

// Accuracy on simulated scenes (lib/sim): 20 random furnished rooms (some L-shaped, rotated,
// with doors to a corridor), scanned from inside without tilt so the map frame is the scene frame.
// The targets: Hausdorff <= 0.15 m to the true polygon (wall faces), area error <= 3 %,
// every door of the room found as an opening. The figures are printed and listed in
// docs/border-closure.md. Every scene closes, every door is found and no other opening is
// reported; the targets are met on every scene whose layout (lib/layout) covers the room (asserted
// per scene) and, since the polygon bridges the shadows objects in the room cast on a wall, on all
// 20. On 2 of the 20 the layout leaves 4-5 % of the room unknown (seed 9, an L with a sloped
// ceiling; seed 17, the shadow of a pillar): those are counted, not asserted one by one.
//
// INDOORMAP_BORDER_DEBUG=DIR prints the figures of every scene and writes DIR/sim_<seed>.png
// (INDOORMAP_BORDER_DEBUG_SEED=N: only that scene; INDOORMAP_BORDER_DEBUG_BOX=x0,y0,x1,y1: a
// close-up of that box in map metres).
namespace {

// The figures of the border closure on the random scenes of seeds [first, last].
struct SimBorderFigures {
  int scenes = 0, closed = 0, doors = 0, doors_found = 0, within_h = 0, within_a = 0;
  int covered = 0;             // scenes whose layout leaves less than 1 % of the room unknown
  int spurious = 0;            // openings more than 0.4 m from every door of the room
  std::vector<double> hs, as;  // Hausdorff [m] and |area error| of the closed scenes, sorted
  double median_h() const { return hs.empty() ? 1e9 : hs[hs.size() / 2]; }
  double median_a() const { return as.empty() ? 1e9 : as[as.size() / 2]; }
};

// With assert_covered, the targets are asserted on each scene whose layout covers the room.
SimBorderFigures border_on_sim_scenes(std::uint64_t first, std::uint64_t last,
                                      bool assert_covered) {
  SimBorderFigures f;
  for (std::uint64_t seed = first; seed <= last; ++seed) {
    sim::Scene scene = sim::random_scene(seed, {.rooms = 1, .scanner_in_corridor = false});
    scene.tilt = {};
    scene.scanner.azimuth_step_deg = scene.scanner.elevation_step_deg = 0.4;
    const sim::SimResult s = sim::simulate(scene);
    PointCloud cloud;
    cloud.points = s.points;
    cloud.scanners = s.scanner_positions_m;
    const auto m = layout::make_map(std::move(cloud), {});
    const auto r = border::close_border(m);
    ++f.scenes;
    const sim::Scene norm = sim::normalised(scene);
    const sim::Room* room = nullptr;
    for (const auto& rm : norm.rooms)
      if (rm.kind == sim::RoomKind::kRoom) room = &rm;
    if (room == nullptr) {
      ADD_FAILURE() << "seed " << seed << ": no room in the scene";
      continue;
    }
    // The share of the true room that the layout leaves unknown (not wall, furniture or free).
    std::int64_t in_room = 0, unknown = 0;
    for (int row = 0; row < m.geometry.height(); ++row)
      for (int col = 0; col < m.geometry.width(); ++col)
        if (indoormap::contains(room->polygon, m.geometry.center_of({col, row}))) {
          ++in_room;
          unknown += m.layout.layout.at(col, row) == Cell::kUnknown;
        }
    const double unknown_share = in_room ? static_cast<double>(unknown) / in_room : 1.0;
    const char* debug_dir = std::getenv("INDOORMAP_BORDER_DEBUG");
    const char* debug_seed = std::getenv("INDOORMAP_BORDER_DEBUG_SEED");
    if (debug_dir && (!debug_seed || std::to_string(seed) == debug_seed))
      debug_picture(std::string(debug_dir) + "/sim_" + std::to_string(seed) + ".png",
                    m.layout.layout, m.geometry, r, room->polygon);
    if (!r.closed) {
      std::cout << "[ sim ] seed " << seed << ": not closed: " << r.reason << "\n";
      continue;
    }
    ++f.closed;
    const auto match = sim::evaluate_rooms({{room->name, "room", room->polygon}}, {r.polygon_m});
    if (match.size() != 1u) {
      ADD_FAILURE() << "seed " << seed << ": " << match.size() << " room matches";
      continue;
    }
    f.hs.push_back(match[0].hausdorff_m);
    f.as.push_back(std::abs(match[0].area_error_rel));
    f.within_h += match[0].hausdorff_m <= 0.15;
    f.within_a += std::abs(match[0].area_error_rel) <= 0.03;
    if (unknown_share < 0.01) {
      ++f.covered;
      if (assert_covered) {
        EXPECT_LE(match[0].hausdorff_m, 0.15) << "seed " << seed;
        EXPECT_LE(std::abs(match[0].area_error_rel), 0.03) << "seed " << seed;
        EXPECT_TRUE(r.warnings.empty()) << "seed " << seed << ": " << r.warnings[0];
      }
    }
    if (debug_dir) {
      const auto chain_match =
          sim::evaluate_rooms({{room->name, "room", room->polygon}}, {r.chain_polygon_m});
      std::cout << "[ sim ] seed " << seed << ": Hausdorff " << match[0].hausdorff_m
                << " m, area error " << 100 * match[0].area_error_rel << " % (chain polygon "
                << chain_match[0].hausdorff_m << " m, " << 100 * chain_match[0].area_error_rel
                << " %), " << room->polygon.size() << " corners, " << r.polygon_m.size()
                << " vertices, " << 100 * unknown_share << " % of the room unknown"
                << (r.warnings.empty() ? "" : "; " + r.warnings[0]) << "; edge offsets"
                << edge_offsets_mm(room->polygon, r.polygon_m) << " mm\n";
      for (const auto& o : r.openings)
        std::cout << "[ sim ]   opening " << fmt(o.a_m) << " - " << fmt(o.b_m) << ", " << o.width_m
                  << " m" << (o.is_door_candidate ? ", door candidate" : "") << "\n";
    }
    const auto& poly = room->polygon;
    std::vector<std::uint8_t> at_door(r.openings.size(), 0);
    for (const auto& d : room->doors) {
      ++f.doors;
      const Eigen::Vector2d a = poly[static_cast<std::size_t>(d.edge)],
                            b = poly[(static_cast<std::size_t>(d.edge) + 1) % poly.size()];
      const Eigen::Vector2d mid = a + (b - a).normalized() * d.at_m;
      bool found = false;
      for (std::size_t i = 0; i < r.openings.size(); ++i)
        if ((0.5 * (r.openings[i].a_m + r.openings[i].b_m) - mid).norm() < 0.4) {
          found = true;
          at_door[i] = 1;
        }
      f.doors_found += found;
    }
    f.spurious += static_cast<int>(std::count(at_door.begin(), at_door.end(), 0));
  }
  std::sort(f.hs.begin(), f.hs.end());
  std::sort(f.as.begin(), f.as.end());
  std::cout << "[ sim ] seeds " << first << "-" << last << ": " << f.scenes << " scenes, "
            << f.closed << " closed; Hausdorff <= 0.15 m: " << f.within_h
            << ", area error <= 3 %: " << f.within_a << " (layout covers the room in " << f.covered
            << "); median Hausdorff " << f.median_h() << " m, median area error "
            << 100 * f.median_a() << " %; worst " << (f.hs.empty() ? 0.0 : f.hs.back()) << " m, "
            << 100 * (f.as.empty() ? 0.0 : f.as.back()) << " %; doors found " << f.doors_found
            << " / " << f.doors << ", other openings " << f.spurious << "\n";
  return f;
}

}  // namespace

TEST(BorderSim, AccuracyOnSimulatedScenes) {
  const SimBorderFigures f = border_on_sim_scenes(1, 20, /*assert_covered=*/true);
  EXPECT_EQ(f.scenes, 20);
  EXPECT_EQ(f.closed, 20);
  EXPECT_EQ(f.doors_found, f.doors);  // every door of every room
  EXPECT_EQ(f.doors, 20);
  // Openings other than doors: before the polygon bridged shadows, the edges of the shadows of
  // a pillar (seed 17: a 1.11 m door candidate) and of a round object (seed 9: 0.47 and 0.52 m).
  EXPECT_EQ(f.spurious, 0);
  EXPECT_GE(f.covered, 18);   // the targets hold on each of them (above)
  EXPECT_EQ(f.within_h, 20);  // 19 before the polygon bridged shadows (seed 17: 0.61 m)
  EXPECT_EQ(f.within_a, 20);  // 19 before (seed 17: -3.3 %)
  EXPECT_LE(f.median_h(), 0.05);
  EXPECT_LE(f.median_a(), 0.02);
}

// The same on 20 further scenes (seeds 21-40), as a check against overfitting the first 20.
// Measured first with the code tuned on seeds 1-20: 19 of 20 within the targets, every door
// found; seed 29 missed (1.12 m, -11.5 %, and one opening at a shadow's edge): a pillar's shadow
// hid a corner of the room. The polygon now takes the walls to their crossing across such a
// shadow (corner_shadow_bridge; seed 29: 0.10 m, -1.8 %), so these scenes are no longer unseen;
// seeds 41-60 (next test) were measured only after that change.
TEST(BorderSim, AccuracyOnFurtherScenes) {
  const SimBorderFigures f = border_on_sim_scenes(21, 40, /*assert_covered=*/true);
  EXPECT_EQ(f.scenes, 20);
  EXPECT_EQ(f.closed, 20);
  EXPECT_EQ(f.doors_found, f.doors);
  EXPECT_EQ(f.spurious, 0);   // 1 before the corner bridge (seed 29)
  EXPECT_EQ(f.within_h, 20);  // 19 before (seed 29)
  EXPECT_EQ(f.within_a, 20);  // 19 before (seed 29)
  EXPECT_LE(f.median_h(), 0.05);
  EXPECT_LE(f.median_a(), 0.02);
}

// Seeds 41-60, first measured with today's code (2026-12-01): 20 of 20 within the targets
// (median 0.019 m, 0.84 %; worst 0.043 m, 1.8 %), every door found, no other opening.
TEST(BorderSim, AccuracyOnUnseenScenes) {
  const SimBorderFigures f = border_on_sim_scenes(41, 60, /*assert_covered=*/true);
  EXPECT_EQ(f.scenes, 20);
  EXPECT_EQ(f.closed, 20);
  EXPECT_EQ(f.doors_found, f.doors);
  EXPECT_EQ(f.spurious, 0);
  EXPECT_EQ(f.within_h, 20);
  EXPECT_EQ(f.within_a, 20);
  EXPECT_LE(f.median_h(), 0.05);
  EXPECT_LE(f.median_a(), 0.02);
}

// Issue 5: the border analysis's other components feed the object list (pcd-to-map's
// objects.json). Inside the room and not already listed: added; outside, or covered by a listed
// object (a pillar found from the layout): not.
TEST(BorderObjects, InteriorComponentsInsideTheRoomJoinTheObjectList) {
  border::BorderResult r;
  r.closed = true;
  r.polygon_m = {{0, 0}, {5, 0}, {5, 4}, {0, 4}};
  const GridGeometry geo({0.0, 0.0}, 0.1, 80, 50);  // 0.1 m cells from the map origin
  auto interior = [&](Eigen::Vector2d lo, Eigen::Vector2d hi, border::ComponentKind k) {
    border::InteriorObject o;
    o.min_m = lo;
    o.max_m = hi;
    o.min = geo.cell_of(lo + Eigen::Vector2d(0.05, 0.05));
    o.max = geo.cell_of(hi - Eigen::Vector2d(0.05, 0.05));
    o.cells = 10;
    o.kind = k;
    return o;
  };
  r.interior_objects = {interior({2.0, 2.0}, {2.4, 2.6}, border::ComponentKind::kRing),
                        interior({3.0, 1.0}, {3.2, 1.2}, border::ComponentKind::kObject),
                        interior({6.0, 1.0}, {6.5, 1.5}, border::ComponentKind::kRing),
                        interior({1.0, 3.0}, {1.2, 3.2}, border::ComponentKind::kObject)};
  objects::ObjectsResult objs;
  objects::FurnitureObject pillar;
  pillar.id = 1;
  pillar.kind = ObjectKind::kPillar;
  pillar.min_m = {0.9, 2.9};
  pillar.max_m = {1.3, 3.3};
  objs.objects.push_back(pillar);
  app::add_border_objects(objs, r);
  ASSERT_EQ(objs.objects.size(), 3u);
  EXPECT_EQ(objs.objects[1].id, 2);
  EXPECT_EQ(objs.objects[1].kind, ObjectKind::kColumn);
  EXPECT_NEAR(objs.objects[1].area_m2, 0.4 * 0.6, 1e-9);
  EXPECT_NEAR(objs.objects[1].box.length_m, 0.6, 1e-9);
  EXPECT_NEAR(objs.objects[1].box.angle_deg, 90.0, 1e-9);
  EXPECT_EQ(objs.objects[1].footprint_m.size(), 4u);
  EXPECT_FALSE(objs.objects[1].has_height);
  EXPECT_EQ(objs.objects[2].kind, ObjectKind::kInstallation);
  // Its crop is its box at every height: on a hand-made cloud, exactly the points in the box.
  EXPECT_EQ(objs.objects[1].own_cells.size(), 4u * 6u);
  std::vector<Eigen::Vector3f> pts;
  std::vector<std::size_t> want;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> ux(0.0f, 7.9f), uy(0.0f, 4.9f), uz(-0.5f, 3.5f);
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3f p(ux(rng), uy(rng), uz(rng));
    const CellIndex c = geo.cell_of({p.x(), p.y()});
    if (c.col >= 20 && c.col <= 23 && c.row >= 20 && c.row <= 25) want.push_back(pts.size());
    pts.push_back(p);
  }
  objs.labels = Grid<std::int32_t>(geo.width(), geo.height(), 0);  // the pillar: no cells here
  const auto crops = objects::crop_indices(objs, geo, pts, 0.0);
  ASSERT_EQ(crops.size(), 3u);
  EXPECT_EQ(crops[1], want);
  EXPECT_GT(want.size(), 100u);
  r.closed = false;  // no room polygon: nothing to place them in
  objects::ObjectsResult none;
  app::add_border_objects(none, r);
  EXPECT_TRUE(none.objects.empty());
}
