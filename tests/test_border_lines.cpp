// Room border closure (lib/border), the face lines of step 6 on hand-checkable points: how far a
// line fitted to a wall's face points can be trusted from them (extrapolation_error), the fit that
// falls back to the chain edge's direction where they cannot fix it (fit_face_line), and an edge
// reaching over a dropped neighbour (extend_to). These are the module's internals (src/).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "indoormap/border/border.hpp"
#include "internal.hpp"

using indoormap::border::detail::extend_to;
using indoormap::border::detail::extrapolation_error;
using indoormap::border::detail::FaceLine;
using indoormap::border::detail::fit_face_line;
using indoormap::border::detail::fit_tls;

namespace {

FaceLine line_through(std::vector<Eigen::Vector2d> pts, Eigen::Vector2d a, Eigen::Vector2d b) {
  FaceLine l;
  l.inliers = std::move(pts);
  l.a = a;
  l.b = b;
  fit_tls(l.inliers, b - a, l);
  return l;
}

}  // namespace

// Five exact points at x = -2 .. 2 on y = 0: the residuals' spread is the quantisation floor
// (1/12), sum (x - mean)^2 = 10; the error is sqrt(s2 / n) at their centre and grows with the
// distance d as sqrt(s2 / n + d^2 s2 / 10). Spread residuals (+-0.5 cells) raise s2 to
// 1.25 / 3; fewer than three points, or all at one place, fix nothing.
TEST(BorderLines, ExtrapolationErrorGrowsWithTheDistanceFromThePoints) {
  std::vector<Eigen::Vector2d> pts;
  for (int x = -2; x <= 2; ++x) pts.emplace_back(x, 0.0);
  const FaceLine l = line_through(pts, {-2, 0}, {2, 0});
  const double s2 = 1.0 / 12.0;
  EXPECT_NEAR(extrapolation_error(l, {0, 0}), std::sqrt(s2 / 5), 1e-12);
  EXPECT_NEAR(extrapolation_error(l, {10, 0}), std::sqrt(s2 / 5 + 100 * s2 / 10), 1e-12);
  EXPECT_NEAR(extrapolation_error(l, {10, 3}), extrapolation_error(l, {10, 0}), 1e-12);

  std::vector<Eigen::Vector2d> noisy;
  for (int x = -2; x <= 2; ++x) noisy.emplace_back(x, x % 2 == 0 ? 0.5 : -0.5);
  const FaceLine ln = line_through(noisy, {-2, 0}, {2, 0});
  const double mean_y = 0.1;  // three at +0.5, two at -0.5
  double srr = 0;
  for (const auto& p : noisy) srr += (p.y() - mean_y) * (p.y() - mean_y);
  EXPECT_NEAR(ln.u.y(), 0.0, 1e-12);
  EXPECT_NEAR(extrapolation_error(ln, {0, 0}), std::sqrt(srr / 3 / 5), 1e-12);

  EXPECT_TRUE(
      std::isinf(extrapolation_error(line_through({{0, 0}, {1, 0}}, {0, 0}, {1, 0}), {0, 0})));
  EXPECT_TRUE(std::isinf(
      extrapolation_error(line_through({{1, 1}, {1, 1}, {1, 1}}, {0, 0}, {5, 0}), {0, 0})));
}

// Five points along a line turned by 20 degrees, within 4 cells of the edge's start: over an edge
// 5 cells long they fix the direction (the fitted line keeps its turn); over one 40 cells long
// they do not (the error 36 cells away is about 2.5 cells), and the line runs along the edge
// through their centre.
TEST(BorderLines, FewPointsAtOneEndOfALongEdgeKeepTheEdgesDirection) {
  const double t = std::tan(20.0 * M_PI / 180.0);
  std::vector<Eigen::Vector2d> pts;
  for (int x = 0; x <= 4; ++x) pts.emplace_back(x, t * x);
  FaceLine short_edge;
  short_edge.inliers = pts;
  short_edge.a = {0, 0};
  short_edge.b = {5, 0};
  fit_face_line(short_edge, short_edge.b - short_edge.a, 1.5);
  EXPECT_NEAR(std::atan2(short_edge.u.y(), short_edge.u.x()), 20.0 * M_PI / 180.0, 1e-9);

  FaceLine long_edge = short_edge;
  long_edge.b = {40, 0};
  EXPECT_GT(extrapolation_error(long_edge, long_edge.b), 1.5);
  fit_face_line(long_edge, long_edge.b - long_edge.a, 1.5);
  EXPECT_NEAR(long_edge.u.x(), 1.0, 1e-12);
  EXPECT_NEAR(long_edge.c.x(), 2.0, 1e-12);
  EXPECT_NEAR(long_edge.c.y(), 2.0 * t, 1e-12);
}

// An unfitted line (no face points) is its chain edge at a depth: reaching over a dropped
// neighbour it turns with the new edge and keeps the depth. A fitted one is fitted again.
TEST(BorderLines, AnEdgeReachingOverItsNeighbourFollowsTheNewEdge) {
  FaceLine l;
  l.a = {0, 0};
  l.b = {5, 0};
  l.u = {1, 0};
  l.c = {0, 1};  // depth 1 inside (the room lies to the left)
  extend_to(l, {10, 10}, 1.5);
  EXPECT_EQ(l.b, Eigen::Vector2d(10, 10));
  EXPECT_NEAR(l.u.x(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(l.u.y(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR((l.c - l.a).dot(l.normal()), 1.0, 1e-12);
  EXPECT_NEAR((l.c - l.a).dot(l.u), 0.0, 1e-12);

  const double t = std::tan(20.0 * M_PI / 180.0);
  FaceLine f;
  for (int x = 0; x <= 4; ++x) f.inliers.emplace_back(x, t * x);
  f.a = {0, 0};
  f.b = {5, 0};
  fit_tls(f.inliers, f.b - f.a, f);
  extend_to(f, {40, 0}, 1.5);
  EXPECT_NEAR(f.u.x(), 1.0, 1e-12);  // 36 cells past its points: the edge's direction
}
