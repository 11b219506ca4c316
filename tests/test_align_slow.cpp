// --align-walls on the Jacobs lab (issue 19), run as a user runs it: the walls of the written
// map.pgm measured independently (OpenCV Hough segments refined by a line fit on the wall
// pixels), and every other output in the same, aligned frame. App-level: labelled slow.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/core/polygon.hpp"
#include "json_support.hpp"
#include "map_yaml.hpp"
#include "test_support.hpp"

using namespace indoormap;
using nlohmann::json;
using test::read_json;
using test::run_app;

namespace {

namespace fs = std::filesystem;

// Distance of an angle (degrees) from the nearest axis direction, [0, 45].
double off_axis_deg(double deg) {
  const double d = std::fmod(std::abs(deg), 90.0);
  return std::min(d, 90.0 - d);
}

// The largest 8-connected component of a map image's occupied (black) pixels: the room's walls
// with what stands against them.
cv::Mat largest_occupied(const fs::path& pgm) {
  const cv::Mat img = cv::imread(pgm.string(), cv::IMREAD_GRAYSCALE);
  EXPECT_FALSE(img.empty()) << pgm;
  const cv::Mat occ = img == 0;
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(occ, labels, stats, centroids, 8);
  int best = 1;
  for (int k = 1; k < n; ++k)
    if (stats.at<int>(k, cv::CC_STAT_AREA) > stats.at<int>(best, cv::CC_STAT_AREA)) best = k;
  return labels == best;
}

// The four outer walls of the component: per row its leftmost and rightmost pixel, per column its
// top- and bottommost; of each side the points within 3 px of the side's median (the wall, not a
// corner or a cupboard standing out), fitted by a robust line (cv::fitLine, Huber), refitted on
// the points within 1 px of it. Each side's
// angle off the axes, degrees.
std::vector<double> outer_wall_off_axis(const cv::Mat& comp) {
  std::vector<std::vector<cv::Point2f>> sides(4);
  for (int r = 0; r < comp.rows; ++r)
    for (int c = 0; c < comp.cols; ++c)
      if (comp.at<std::uint8_t>(r, c)) {
        sides[0].emplace_back(c, r);  // leftmost of row r (first seen)
        break;
      }
  for (int r = 0; r < comp.rows; ++r)
    for (int c = comp.cols - 1; c >= 0; --c)
      if (comp.at<std::uint8_t>(r, c)) {
        sides[1].emplace_back(c, r);
        break;
      }
  for (int c = 0; c < comp.cols; ++c)
    for (int r = 0; r < comp.rows; ++r)
      if (comp.at<std::uint8_t>(r, c)) {
        sides[2].emplace_back(c, r);
        break;
      }
  for (int c = 0; c < comp.cols; ++c)
    for (int r = comp.rows - 1; r >= 0; --r)
      if (comp.at<std::uint8_t>(r, c)) {
        sides[3].emplace_back(c, r);
        break;
      }
  std::vector<double> out;
  for (int k = 0; k < 4; ++k) {
    const bool vertical = k < 2;
    std::vector<float> across;
    for (const auto& p : sides[k]) across.push_back(vertical ? p.x : p.y);
    std::nth_element(across.begin(), across.begin() + across.size() / 2, across.end());
    const float median = across[across.size() / 2];
    std::vector<cv::Point2f> wall;
    for (const auto& p : sides[k])
      if (std::abs((vertical ? p.x : p.y) - median) <= 3.0f) wall.push_back(p);
    cv::Vec4f fit;
    for (int round = 0; round < 2 && wall.size() >= 2; ++round) {
      // Second round: the points within 1 px of the first line (a jog of the wall, a door
      // frame 2-3 px out, no longer pulls the line round).
      cv::fitLine(wall, fit, cv::DIST_HUBER, 0, 0.01, 0.01);
      std::vector<cv::Point2f> near;
      for (const auto& p : wall)
        if (std::abs((p.x - fit[2]) * fit[1] - (p.y - fit[3]) * fit[0]) <= 1.0f) near.push_back(p);
      wall.swap(near);
    }
    EXPECT_GT(wall.size(), 30u) << "side " << k;  // 1.5 m of straight wall at least
    if (wall.size() < 2) continue;
    cv::fitLine(wall, fit, cv::DIST_HUBER, 0, 0.01, 0.01);
    out.push_back(off_axis_deg(std::atan2(fit[1], fit[0]) * 180.0 / CV_PI));
  }
  return out;
}

// The angle off the axes of the component's minimum-area rectangle.
double min_rect_off_axis(const cv::Mat& comp) {
  std::vector<cv::Point> pts;
  cv::findNonZero(comp, pts);
  return off_axis_deg(cv::minAreaRect(pts).angle);
}

Eigen::Matrix3d matrix(const json& rows) {
  Eigen::Matrix3d m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = rows[r][c].get<double>();
  return m;
}

// The outer rings of every Polygon feature of a GeoJSON file (map metres).
std::vector<Polygon> polygons(const fs::path& geojson) {
  std::vector<Polygon> out;
  const json doc = read_json(geojson);
  for (const auto& f : doc["features"]) {
    if (f["geometry"]["type"] != "Polygon") continue;
    Polygon p;
    for (const auto& v : f["geometry"]["coordinates"][0])
      p.emplace_back(v[0].get<double>(), v[1].get<double>());
    out.push_back(p);
  }
  return out;
}

// Whether a cell of `kind` lies within radius_m of p (map metres).
bool near_cell(const formats::RosMap& m, const Eigen::Vector2d& p, Cell kind, double radius_m) {
  const CellIndex c = m.geometry.cell_of(p);
  const int r = static_cast<int>(std::ceil(radius_m / m.geometry.cell_m()));
  for (int dr = -r; dr <= r; ++dr)
    for (int dc = -r; dc <= r; ++dc) {
      const int col = c.col + dc, row = c.row + dr;
      if (col >= 0 && row >= 0 && col < m.cells.width && row < m.cells.height &&
          m.cells.at(col, row) == kind)
        return true;
    }
  return false;
}

// Share of the polygon's vertices with an occupied map.pgm cell within radius_m.
double vertices_on_walls(const formats::RosMap& m, const Polygon& p, double radius_m) {
  std::size_t on = 0;
  for (const auto& v : p) on += near_cell(m, v, Cell::kWall, radius_m);
  return p.empty() ? 0.0 : static_cast<double>(on) / static_cast<double>(p.size());
}

struct JacobsRuns {
  fs::path plain, aligned;
  bool have_data = false;
  bool ok = false;
};

// pcd-to-map on the Jacobs lab, as it is and with --align-walls (once for every test).
const JacobsRuns* jacobs_runs() {
  static const JacobsRuns* runs = [] {
    auto* r = new JacobsRuns;
    const auto data = test::shared_data_dir();
    if (!data || !fs::exists(*data / "jacobs-thermocolorlab")) return r;
    r->have_data = true;
    const std::string in = (*data / "jacobs-thermocolorlab").string();
    r->plain = test::scratch_dir() / "plain";
    r->aligned = test::scratch_dir() / "aligned";
    const auto a = run_app("pcd-to-map", in + " -q -o " + r->plain.string());
    const auto b = run_app("pcd-to-map", in + " -q --align-walls -o " + r->aligned.string());
    EXPECT_EQ(a.exit_code, 0) << a.err;
    EXPECT_EQ(b.exit_code, 0) << b.err;
    r->ok = a.exit_code == 0 && b.exit_code == 0;
    return r;
  }();
  return runs;
}

#define REQUIRE_JACOBS(runs)                                            \
  const JacobsRuns* runs = jacobs_runs();                               \
  if (!runs->have_data)                                                 \
    GTEST_SKIP() << "real data 'jacobs-thermocolorlab' not found: set " \
                    "INDOORMAP_DATA or provide ../shared/data";         \
  ASSERT_TRUE(runs->ok)

}  // namespace

TEST(AlignWallsApp, JacobsWallsWithinOneDegreeOfTheAxesInMapPgm) {
  REQUIRE_JACOBS(runs);
  const cv::Mat plain = largest_occupied(runs->plain / "map.pgm");
  const cv::Mat aligned = largest_occupied(runs->aligned / "map.pgm");
  // In the scan's frame the lab stands some 37 degrees off the axes ...
  EXPECT_GT(min_rect_off_axis(plain), 20.0);
  // ... aligned, its bounding rectangle and each of its four outer walls run along them.
  const double rect = min_rect_off_axis(aligned);
  EXPECT_LT(rect, 1.0);
  const auto walls = outer_wall_off_axis(aligned);
  ASSERT_EQ(walls.size(), 4u);
  std::string text;
  for (double w : walls) {
    EXPECT_LT(w, 1.0) << "an outer wall";
    text += std::to_string(w) + " ";
  }
  RecordProperty("aligned_walls_off_axis_deg", text);
  RecordProperty("aligned_rect_off_axis_deg", std::to_string(rect));
  RecordProperty("plain_rect_off_axis_deg", std::to_string(min_rect_off_axis(plain)));
}

TEST(AlignWallsApp, SummaryAndMapYamlSayHowToGoBack) {
  REQUIRE_JACOBS(runs);
  const json p = read_json(runs->plain / "summary.json");
  const json s = read_json(runs->aligned / "summary.json");
  EXPECT_FALSE(p["align_walls"]["applied"].get<bool>());
  EXPECT_FALSE(p["align_walls"]["enabled"].get<bool>());
  const json& al = s["align_walls"];
  ASSERT_TRUE(al["applied"].get<bool>()) << al.dump();
  const double yaw = al["yaw_deg"].get<double>();
  EXPECT_GT(al["confidence"].get<double>(), 0.3);
  // map_from_input = Rz(yaw) * the levelling of the plain run; input_from_map its transpose.
  const Eigen::Matrix3d tilt = matrix(p["levelling"]["map_from_input"]);
  const Eigen::Matrix3d full = matrix(s["levelling"]["map_from_input"]);
  const double a = yaw * CV_PI / 180.0;
  Eigen::Matrix3d rz = Eigen::Matrix3d::Identity();
  rz << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  EXPECT_LT((full - rz * tilt).norm(), 1e-9);
  EXPECT_LT((matrix(al["input_from_map"]) - full.transpose()).norm(), 1e-12);
  // The scanner maps back to where the plain run has it (the same input point).
  const auto& sp = p["scanners_map_m"][0];
  const auto& sa = s["scanners_map_m"][0];
  const Eigen::Vector3d in_plain =
      tilt.transpose() * Eigen::Vector3d(sp[0].get<double>(), sp[1], sp[2]);
  const Eigen::Vector3d in_aligned =
      full.transpose() * Eigen::Vector3d(sa[0].get<double>(), sa[1], sa[2]);
  EXPECT_LT((in_plain - in_aligned).norm(), 1e-6);
  // map.yaml: the yaw and R as comments after the keys; still read as the same map.
  const std::string yaml = test::read_text(runs->aligned / "map.yaml");
  EXPECT_NE(yaml.find("# frame: levelled, then turned"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("input = R^T * map"), std::string::npos) << yaml;
  EXPECT_EQ(test::read_text(runs->plain / "map.yaml").find('#'), std::string::npos);
  EXPECT_NO_THROW(app::read_ros_map(runs->aligned / "map.yaml"));
}

TEST(AlignWallsApp, RoomPolygonsObjectsAndScannerLieOnTheAlignedMap) {
  REQUIRE_JACOBS(runs);
  const formats::RosMap m = app::read_ros_map(runs->aligned / "map.yaml");
  const json s = read_json(runs->aligned / "summary.json");
  const double yaw = s["align_walls"]["yaw_deg"].get<double>();
  // The room border (room.geojson) and the rooms (rooms.geojson) run along map.pgm's walls ...
  for (const char* file : {"room.geojson", "rooms.geojson"}) {
    const auto polys = polygons(runs->aligned / file);
    ASSERT_FALSE(polys.empty()) << file;
    const double on = vertices_on_walls(m, polys[0], 0.25);
    // rooms.geojson's rooms also cross the openings between them, where map.pgm is free, and end
    // where the seen space ends: in the aligned run the piece of corridor seen through the door
    // joins the lab (its core, 0.595 m2, is just below rooms.segmentation.min_core_area_m2), and
    // the vertices along its unseen far end lie on no wall.
    EXPECT_GT(on, std::string(file) == "room.geojson" ? 0.9 : 0.6) << file;
    // ... which they would miss turned back into the levelled (scan) frame.
    Polygon back;
    const double a = -yaw * CV_PI / 180.0;
    for (const auto& v : polys[0])
      back.emplace_back(std::cos(a) * v.x() - std::sin(a) * v.y(),
                        std::sin(a) * v.x() + std::cos(a) * v.y());
    EXPECT_LT(vertices_on_walls(m, back, 0.25), on - 0.25) << file;
  }
  // Every object stands on occupied map cells and inside the room border.
  const auto room = polygons(runs->aligned / "room.geojson")[0];
  const json objs = read_json(runs->aligned / "objects.json");
  ASSERT_GT(objs["count"].get<int>(), 5);
  EXPECT_NE(objs["frame"].get<std::string>().find("wall-aligned"), std::string::npos);
  std::size_t on_map = 0, inside = 0;
  for (const auto& o : objs["objects"]) {
    const auto& bb = o["bbox_m"];
    const Eigen::Vector2d lo(bb["min"][0].get<double>(), bb["min"][1].get<double>());
    const Eigen::Vector2d hi(bb["max"][0].get<double>(), bb["max"][1].get<double>());
    bool any = false;  // an occupied map.pgm cell under the object's box (or 1 cell round it)
    for (double x = lo.x(); x <= hi.x() && !any; x += m.geometry.cell_m())
      for (double y = lo.y(); y <= hi.y() && !any; y += m.geometry.cell_m())
        any = near_cell(m, {x, y}, Cell::kWall, m.geometry.cell_m());
    on_map += any;
    inside += contains(room, 0.5 * (lo + hi));
  }
  const auto n = objs["objects"].size();
  EXPECT_GT(on_map, 0.9 * static_cast<double>(n)) << on_map << " of " << n;
  EXPECT_GT(inside, 0.8 * static_cast<double>(n)) << inside << " of " << n;
  // The scanner stands on free floor.
  const auto& sc = s["scanners_map_m"][0];
  EXPECT_TRUE(near_cell(m, {sc[0].get<double>(), sc[1].get<double>()}, Cell::kFree, 0.1));
}

TEST(AlignWallsApp, FurnitureCropsInTheAlignedFrame) {
  const auto data = test::shared_data_dir();
  if (!data || !fs::exists(*data / "jacobs-thermocolorlab"))
    GTEST_SKIP() << "real data 'jacobs-thermocolorlab' not found: set INDOORMAP_DATA or provide "
                    "../shared/data";
  const fs::path out = test::scratch_dir();
  const auto r = run_app("furniture-extract", (*data / "jacobs-thermocolorlab").string() +
                                                  " -q --align-walls -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json objs = read_json(out / "objects.json");
  EXPECT_EQ(objs["crop_frame"], "map");
  const double margin = read_json(out / "summary.json")["parameters"]["objects"]["crop_margin_m"];
  std::size_t checked = 0;
  for (const auto& o : objs["objects"]) {
    if (!o.contains("crop_file") || o["crop_points"].get<std::size_t>() < 50) continue;
    const auto crop = cloud_io::load_cloud((out / o["crop_file"].get<std::string>()).string());
    const auto& bb = o["bbox_m"];
    std::size_t in = 0;
    for (const auto& p : crop.cloud.points)
      in += p.x() >= bb["min"][0].get<double>() - margin - 0.05 &&
            p.x() <= bb["max"][0].get<double>() + margin + 0.05 &&
            p.y() >= bb["min"][1].get<double>() - margin - 0.05 &&
            p.y() <= bb["max"][1].get<double>() + margin + 0.05;
    EXPECT_GT(in, 0.99 * static_cast<double>(crop.cloud.points.size())) << o["crop_file"];
    ++checked;
  }
  EXPECT_GT(checked, 5u);
}
