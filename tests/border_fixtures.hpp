#pragma once
// Shared fixtures of the test_border_*.cpp files: generated rooms, chain checks, Hausdorff
// distance, debug pictures.
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

namespace border_fixtures {

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
inline Polygon offset_rectilinear(const Polygon& p, double d) {
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

inline void fill(cv::Mat& img, const Polygon& poly_m, const GridGeometry& geo, int value) {
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
inline Room make_room(std::uint64_t seed, bool l_shape, int doors) {
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

inline void expect_valid_chain(const border::BorderResult& r, const std::string& what) {
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

// Appends rather than `"(" + std::to_string(...)`, which gcc 12 at -O3 flags with a false
// -Wstringop-overflow.
inline std::string fmt(const Eigen::Vector2d& v) {
  std::string s = "(";
  s.append(std::to_string(v.x())).append(", ").append(std::to_string(v.y())).append(")");
  return s;
}

// Symmetric Hausdorff distance between polygon boundaries sampled every 1 cm.
inline double hausdorff(const Polygon& a, const Polygon& b) {
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
inline void debug_picture(const std::string& path, const Grid<Cell>& lay, const GridGeometry& geo,
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
inline std::string edge_offsets_mm(const Polygon& truth, const Polygon& result) {
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

}  // namespace border_fixtures
