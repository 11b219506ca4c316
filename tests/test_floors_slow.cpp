// Whole floors (issue 15): pcd-to-map's navigation map on a simulated 4-room building and the
// default office, run as a user runs it. App-level, over 1 s: labelled slow.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/cloud_io/write.hpp"
#include "json_support.hpp"
#include "map_yaml.hpp"
#include "test_support.hpp"

using namespace indoormap;
using nlohmann::json;
using test::read_json;
using test::run_app;

namespace {

namespace fs = std::filesystem;

// The robot's configuration space of map.yaml: free cells whose centre lies at least radius_m
// from the centre of every cell that is not free (unknown counts as blocked), 4-connected
// components labelled.
struct CSpace {
  formats::RosMap map;
  cv::Mat labels;
  int label_at(const Eigen::Vector2d& p_m, double search_m) const {
    const CellIndex c = map.geometry.cell_of(p_m);
    const int r = static_cast<int>(std::ceil(search_m / map.geometry.cell_m()));
    for (int d = 0; d <= r; ++d)  // nearest labelled cell, ring by ring
      for (int dr = -d; dr <= d; ++dr)
        for (int dc = -d; dc <= d; ++dc) {
          const int col = c.col + dc, row = c.row + dr;
          if (col < 0 || row < 0 || col >= labels.cols || row >= labels.rows) continue;
          if (const int l = labels.at<int>(row, col); l > 0) return l;
        }
    return 0;
  }
};

CSpace cspace(const fs::path& yaml, double radius_m) {
  CSpace s{app::read_ros_map(yaml), {}};
  const auto& g = s.map.cells;
  cv::Mat free(g.height, g.width, CV_8U);
  for (int r = 0; r < g.height; ++r)
    for (int c = 0; c < g.width; ++c) free.at<std::uint8_t>(r, c) = g.at(c, r) == Cell::kFree;
  cv::Mat dist, ok;
  cv::distanceTransform(free, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  // At least radius_m between the robot's centre cell and the centre of any cell not free.
  cv::threshold(dist, ok, radius_m / s.map.geometry.cell_m() - 1e-3, 255, cv::THRESH_BINARY);
  ok.convertTo(ok, CV_8U);
  cv::connectedComponents(ok, s.labels, 4, CV_32S);
  return s;
}

struct Figures {
  int doors = 0, doors_open = 0;
  int positions = 0;
  bool all_reachable = true;
};

// Doors open for a 0.4 m robot (a configuration-space cell within 0.15 m of the door's centre)
// and every scanner position reachable from every other.
Figures figures(const fs::path& result, const json& truth) {
  const CSpace s = cspace(result / "map.yaml", 0.2);
  Figures f;
  for (const auto& room : truth["rooms"])
    for (const auto& d : room.value("doors", json::array())) {
      ++f.doors;
      f.doors_open +=
          s.label_at(Eigen::Vector2d(d["center"][0].get<double>(), d["center"][1].get<double>()),
                     0.15) > 0;
    }
  int first = -1;
  const json summary = read_json(result / "summary.json");
  for (const auto& p : summary["scanners_map_m"]) {
    ++f.positions;
    const int l = s.label_at(Eigen::Vector2d(p[0].get<double>(), p[1].get<double>()), 0.5);
    if (first < 0) first = l;
    f.all_reachable = f.all_reachable && l > 0 && l == first;
  }
  return f;
}

// map-eval's eval.json of a pcd-to-map result against a scene-sim truth directory.
json map_eval(const fs::path& sim, const fs::path& result) {
  const auto r =
      run_app("map-eval", "--truth " + (sim / "ground_truth.json").string() + " --result " +
                              result.string() + " -o " + (result / "eval").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_json(result / "eval" / "eval.json");
}

fs::path building4() {  // one scene for every test of this file: 4 rooms and a corridor
  static const fs::path dir = [] {
    // Not under scratch_dir (each call clears the test's directory): one per process.
    const fs::path d = fs::temp_directory_path() / "indoormap-tests" /
                       ("floors_building4_" + std::to_string(::getpid()));
    fs::remove_all(d);
    const auto r = run_app("scene-sim",
                           "--random --rooms 4 --seed 1 --step-deg 0.5 --3dtk -q -o " + d.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return d;
  }();
  return dir;
}

std::string scanner_options(const json& truth) {
  std::ostringstream s;
  for (const auto& sc : truth["scanners"])
    s << " --scanner " << sc["position_cloud_m"][0].get<double>() << ","
      << sc["position_cloud_m"][1].get<double>() << "," << sc["position_cloud_m"][2].get<double>();
  return s.str();
}

}  // namespace

TEST(FloorsApp, FourRoomsFrom3dtkAndFromTheMergedCloud) {
  const fs::path in = building4();
  const json truth = read_json(in / "ground_truth.json");
  const fs::path out = test::scratch_dir();
  const auto a =
      run_app("pcd-to-map", (in / "3dtk").string() + " -q -o " + (out / "3dtk").string());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const auto b = run_app("pcd-to-map", (in / "cloud.pcd").string() + scanner_options(truth) +
                                           " -q -o " + (out / "merged").string());
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_NE(b.err.find("ghost filter: 5 scanner positions and no record of which point came "
                       "from which: each point taken as seen from its nearest position"),
            std::string::npos)
      << b.err;
  for (const char* run : {"3dtk", "merged"}) {
    const Figures f = figures(out / run, truth);
    SCOPED_TRACE(run);
    EXPECT_EQ(f.positions, 5);
    EXPECT_GE(f.doors, 4);
    EXPECT_GE(f.doors_open, 0.95 * f.doors) << f.doors_open << " of " << f.doors;
    EXPECT_TRUE(f.all_reachable);
  }
  EXPECT_TRUE(read_json(out / "3dtk" / "summary.json")["ghosts"]["applied"].get<bool>())
      << "3DTK: the ghost filter runs per scan";
  EXPECT_TRUE(read_json(out / "merged" / "summary.json")["ghosts"]["applied"].get<bool>())
      << "merged: per nearest position";
  const json e = map_eval(in, out / "merged");
  EXPECT_GE(e["floor"]["map"]["seen_free_iou"]["iou"].get<double>(), 0.9);
}

// The mobile-scanner mode (a position every 0.5 m, 16 beams): with its trajectory every door
// open, every position reachable, seen-free IoU >= 0.9 (map-eval's figures); the same without
// any position (cloud.pcd's VIEWPOINT, the first position, is dropped): the observed floor and
// its holes alone (docs/evaluation-history.md "Floors").
TEST(FloorsApp, FourRoomsMobileWithAndWithoutTrajectory) {
  const fs::path dir = test::scratch_dir();
  const auto sim =
      run_app("scene-sim", "--random --rooms 4 --mobile --seed 1 -q -o " + (dir / "sim").string());
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const std::string cloud = (dir / "sim" / "cloud.pcd").string();
  const auto a =
      run_app("pcd-to-map", cloud + " --trajectory " + (dir / "sim" / "trajectory.txt").string() +
                                " -q -o " + (dir / "traj").string());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const auto b = run_app("pcd-to-map", cloud + " -q -o " + (dir / "none").string());
  ASSERT_EQ(b.exit_code, 0) << b.err;
  // "No positions" as a user gets it: cloud.pcd's VIEWPOINT (the first position) is the only
  // one; most of the cloud is hidden from it, so it is dropped and the observed floor decides.
  const json ns = read_json(dir / "none" / "summary.json");
  // The trajectory's rays show the free floor: M_r's flood keeps to them (it ran in through the
  // unseen ends of cabinets); without positions the observed floor is too patchy for that.
  EXPECT_TRUE(read_json(dir / "traj" / "summary.json")["free_from_evidence"].get<bool>());
  EXPECT_FALSE(ns["free_from_evidence"].get<bool>());
  EXPECT_TRUE(ns["viewpoint_check"]["position_dropped"].get<bool>()) << ns["viewpoint_check"];
  EXPECT_GT(ns["viewpoint_check"]["occluded_share"].get<double>(), 0.15);
  EXPECT_EQ(ns["nav_map"]["positions"].get<int>(), 0);
  EXPECT_FALSE(ns["ghosts"]["applied"].get<bool>());
  EXPECT_GT(ns["nav_map"]["cells"]["free_floor_holes"].get<int>(), 0);
  EXPECT_NE(ns["warnings"].dump().find("cannot be the origin"), std::string::npos)
      << ns["warnings"];
  const json t = map_eval(dir / "sim", dir / "traj"), n = map_eval(dir / "sim", dir / "none");
  EXPECT_EQ(t["floor"]["doors"]["doors"].get<int>(), 4);
  EXPECT_GE(t["floor"]["doors"]["open_share"].get<double>(), 0.95);
  EXPECT_TRUE(t["floor"]["reachability"]["all_reachable"].get<bool>());
  EXPECT_GT(t["floor"]["reachability"]["scanners"].get<int>(), 50) << "every trajectory position";
  EXPECT_GE(t["floor"]["map"]["seen_free_iou"]["iou"].get<double>(), 0.9);
  EXPECT_GE(n["floor"]["doors"]["open_share"].get<double>(), 0.95);
  EXPECT_TRUE(n["floor"]["reachability"]["all_reachable"].get<bool>());
  EXPECT_GE(n["floor"]["map"]["seen_free_iou"]["iou"].get<double>(), 0.9);
}

// Two storeys: the 4-room building and a copy of it one storey up (a slab 0.3 m thick between
// the lower ceiling and the upper floor), merged into one cloud, every position by --scanner.
TEST(FloorsApp, TwoStoreysEachMappedOnItsOwn) {
  const fs::path in = building4();
  const json truth = read_json(in / "ground_truth.json");
  double ceiling = 0.0;  // the highest ceiling of every room and the corridor
  for (const auto& room : truth["rooms"])
    ceiling = std::max(ceiling, room["ceiling"]["max_z_m"].get<double>());
  const double up = ceiling + 0.3;
  auto cloud = cloud_io::load_cloud((in / "cloud.pcd").string()).cloud;
  const std::size_t n = cloud.points.size();
  cloud.points.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i)
    cloud.points.push_back(cloud.points[i] + Eigen::Vector3f(0, 0, static_cast<float>(up)));
  const fs::path dir = test::scratch_dir();
  cloud_io::write_pcd_binary((dir / "two.pcd").string(), cloud.points);
  std::ostringstream sc;
  for (const auto& s : truth["scanners"])
    for (double dz : {0.0, up})
      sc << " --scanner " << s["position_cloud_m"][0].get<double>() << ","
         << s["position_cloud_m"][1].get<double>() << ","
         << s["position_cloud_m"][2].get<double>() + dz;
  const auto r = run_app(
      "pcd-to-map", (dir / "two.pcd").string() + sc.str() + " -q -o " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json top = read_json(dir / "out" / "summary.json");
  ASSERT_EQ(top["storeys"].size(), 2u) << top.dump(1);
  for (int k = 0; k < 2; ++k) {
    SCOPED_TRACE("storey " + std::to_string(k));
    const fs::path sub = dir / "out" / ("storey_" + std::to_string(k));
    const json s = read_json(sub / "summary.json");
    EXPECT_EQ(s["storey"].get<int>(), k);
    EXPECT_NEAR(s["floor_z_m"].get<double>(), k * up, 0.05) << "within one cell";
    // The top-level list gives the floor the storey's map was made with.
    EXPECT_DOUBLE_EQ(top["storeys"][k]["floor_z_m"].get<double>(), s["floor_z_m"].get<double>());
    EXPECT_TRUE(top["storeys"][k].contains("histogram_floor_z_m"));
    const Figures f = figures(sub, truth);
    EXPECT_EQ(f.positions, 5);
    EXPECT_GE(f.doors_open, 0.95 * f.doors) << f.doors_open << " of " << f.doors;
    EXPECT_TRUE(f.all_reachable);
  }
}

// The 12-room building of scripts/floor_eval.sh (seed 221, scene-sim's default step), from its
// 3DTK scans: a pillar 0.8 m in front of room 9's scanner hides the floor all the way to the
// room's door, and no other position sees it. The pillar's shadow (NavParams::shadow_max_width_m)
// opens it: every door open, every position reachable, seen-free IoU >= 0.9, as map-eval scores
// map.pgm; without the shadow rule that door stays closed. The storey is levelled by its floor
// (the ceilings of its rooms lie at several heights).
TEST(FloorsApp, TwelveRoomsPillarShadowedDoorOpens) {
  const fs::path dir = test::scratch_dir();
  const auto sim =
      run_app("scene-sim", "--random --rooms 12 --seed 221 --3dtk -q -o " + (dir / "sim").string());
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const std::string in = (dir / "sim" / "3dtk").string();
  const auto a = run_app("pcd-to-map", in + " -q -o " + (dir / "out").string());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const json e = map_eval(dir / "sim", dir / "out");
  EXPECT_EQ(e["floor"]["doors"]["doors"].get<int>(), 12);
  EXPECT_EQ(e["floor"]["doors"]["open_share"].get<double>(), 1.0) << e["floor"]["doors"];
  EXPECT_TRUE(e["floor"]["reachability"]["all_reachable"].get<bool>());
  EXPECT_GE(e["floor"]["map"]["seen_free_iou"]["iou"].get<double>(), 0.9);
  const json s = read_json(dir / "out" / "summary.json");
  EXPECT_GT(s["nav_map"]["cells"]["free_shadows"].get<int>(), 0);
  EXPECT_NE(s["levelling"]["note"].get<std::string>().find("floor plane only"), std::string::npos);

  const fs::path cfg = dir / "no_shadows.yaml";
  // Without the shadows, and without the floor holes (the wedge, cut off from the door wall's
  // inside by the wall band since 2026-12-07, is a hole of the floor as well), the door is shut.
  std::ofstream(cfg) << "nav:\n  shadow_max_width_m: 0\n  floor_hole_max_m2: 0\n";
  const auto b =
      run_app("pcd-to-map", in + " -c " + cfg.string() + " -q -o " + (dir / "off").string());
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const json off = map_eval(dir / "sim", dir / "off");
  EXPECT_LT(off["floor"]["doors"]["open_share"].get<double>(), 1.0) << "room 9's door";
}

// Issue 15's figures on the 8-room building and the 12-room two-storey one of
// scripts/floor_eval.sh (seeds 181 and 222, scene-sim's defaults), in every mode a user has: the
// 3DTK scans, the merged cloud with --scanner per position, and the mobile scan with its
// trajectory and without positions. Per storey, as map-eval scores map.pgm: at least 95 % of
// the doors open, every position reachable, seen-free IoU >= 0.9, the floor within one cell.
struct Building {
  int rooms, storeys, seed;
  /// Rooms within 0.15 m Hausdorff and 3 % area (map-eval's rooms block, summed over the
  /// storeys) per mode, a regression guard one below what was measured with the face lines kept
  /// to what their points fix (2026-12-07, session 29; docs/evaluation-history.md, "Rooms of a
  /// floor"); issue 16 wants 90 %.
  std::array<int, 4> min_rooms_within;
  /// Objects of at least 0.1 m2 (map-eval's objects block, pooled over the storeys): recall and
  /// precision over everything written, per mode, a guard 0.03 below what was measured on
  /// 2026-12-07 (precision, and without positions recall: with the stray returns left out,
  /// session 30; along a path and without positions: the tops carried over hidden cells, session
  /// 31; without positions: unseen bodies, session 32; docs/evaluation.md; issue 16 wants 0.9).
  std::array<double, 4> min_objects_recall, min_objects_precision;
};

class FloorsBuilding : public ::testing::TestWithParam<Building> {};

// Every truth position of every storey, as --scanner options (cloud frame).
std::string all_scanner_options(const json& truth) {
  std::ostringstream s;
  const auto add = [&](const json& list) {
    for (const auto& sc : list)
      s << " --scanner " << sc["position_cloud_m"][0].get<double>() << ","
        << sc["position_cloud_m"][1].get<double>() << ","
        << sc["position_cloud_m"][2].get<double>();
  };
  if (truth.contains("storeys"))
    for (const auto& st : truth["storeys"]) add(st["scanners"]);
  else
    add(truth["scanners"]);
  return s.str();
}

TEST_P(FloorsBuilding, EveryModeMeetsTheFigures) {
  const Building b = GetParam();
  const fs::path dir = test::scratch_dir();
  const std::string common = "--random --rooms " + std::to_string(b.rooms) + " --storeys " +
                             std::to_string(b.storeys) + " --seed " + std::to_string(b.seed) +
                             " -q -o ";
  ASSERT_EQ(run_app("scene-sim", common + (dir / "fixed").string() + " --3dtk").exit_code, 0);
  ASSERT_EQ(run_app("scene-sim", common + (dir / "mobile").string() + " --mobile").exit_code, 0);
  const json truth = read_json(dir / "fixed" / "ground_truth.json");
  const std::string mobile = (dir / "mobile" / "cloud.pcd").string();
  const std::vector<std::pair<std::string, std::string>> modes{
      {"3dtk", (dir / "fixed" / "3dtk").string()},
      {"merged", (dir / "fixed" / "cloud.pcd").string() + all_scanner_options(truth)},
      {"trajectory", mobile + " --trajectory " + (dir / "mobile" / "trajectory.txt").string()},
      {"none", mobile}};
  for (std::size_t mode = 0; mode < modes.size(); ++mode) {
    const auto& [name, args] = modes[mode];
    SCOPED_TRACE(name);
    const fs::path sim = dir / (name == "3dtk" || name == "merged" ? "fixed" : "mobile");
    const auto r = run_app("pcd-to-map", args + " -q -o " + (dir / name).string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json e = map_eval(sim, dir / name);
    std::vector<json> parts;
    if (b.storeys > 1) {
      ASSERT_EQ(e["storeys"].size(), static_cast<std::size_t>(b.storeys));
      for (const auto& st : e["storeys"]) {
        EXPECT_LE(std::abs(st["floor_error_m"].get<double>()), 0.05) << "storey " << st["k"];
        parts.push_back(st);
      }
    } else {
      parts.push_back(e);
    }
    int within = 0, matched = 0, truth_items = 0, matched_all = 0, written = 0;
    for (const json& part : parts) {
      const json& o = part["objects"];
      matched += o["matched"].get<int>(), truth_items += o["truth_count"].get<int>();
      matched_all += o["matched_all"].get<int>(), written += o["result_count"].get<int>();
      const json& f = part["floor"];
      EXPECT_GE(f["doors"]["open_share"].get<double>(), 0.95) << f["doors"];
      EXPECT_TRUE(f["reachability"]["all_reachable"].get<bool>()) << f["reachability"];
      EXPECT_GE(f["map"]["seen_free_iou"]["iou"].get<double>(), 0.9);
      within += part["rooms"]["within_tolerance"].get<int>();
    }
    EXPECT_GE(within, b.min_rooms_within[mode]);
    ASSERT_GT(truth_items, 0);
    ASSERT_GT(written, 0);
    EXPECT_GE(static_cast<double>(matched) / truth_items, b.min_objects_recall[mode]);
    EXPECT_GE(static_cast<double>(matched_all) / written, b.min_objects_precision[mode]);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Seeds, FloorsBuilding,
    ::testing::Values(
        Building{8, 1, 181, {6, 6, 8, 6}, {0.77, 0.80, 0.80, 0.77}, {0.85, 0.83, 0.83, 0.64}},
        Building{12, 2, 222, {22, 20, 21, 20}, {0.89, 0.86, 0.84, 0.81}, {0.90, 0.88, 0.89, 0.74}}),
    [](const ::testing::TestParamInfo<Building>& i) {
      return std::to_string(i.param.rooms) + "Rooms" + std::to_string(i.param.storeys) + "Storeys";
    });

TEST(FloorsApp, OfficeLampsAreNoObstaclesTablesAndChairsAre) {
  const fs::path office = fs::path(INDOORMAP_SOURCE_DIR) / "clouds" / "office";
  const fs::path out = test::scratch_dir() / "office";
  const auto r = run_app("pcd-to-map", (office / "cloud.pcd").string() + " -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto map = app::read_ros_map(out / "map.yaml");
  const json truth = read_json(office / "ground_truth.json");
  auto occupied_in = [&](double x0, double y0, double x1, double y1) {
    int n = 0;
    for (double y = y0; y <= y1; y += 0.05)
      for (double x = x0; x <= x1; x += 0.05) {
        const CellIndex c = map.geometry.cell_of({x, y});
        n += map.geometry.contains(c) && map.cells.at(c) == Cell::kWall;
      }
    return n;
  };
  for (const auto& o : truth["furniture"]) {
    const auto& fp = o["footprint"];
    double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
    for (const auto& p : fp) {
      x0 = std::min(x0, p[0].get<double>()), x1 = std::max(x1, p[0].get<double>());
      y0 = std::min(y0, p[1].get<double>()), y1 = std::max(y1, p[1].get<double>());
    }
    const std::string type = o["type"];
    SCOPED_TRACE(o["id"].get<std::string>());
    const std::string id = o["id"];
    if (id == "lamp_2" || id == "lamp_4") {  // hanging at 2.34 m over free floor: no obstacle
      EXPECT_EQ(occupied_in(x0, y0, x1, y1), 0);
    } else if (type == "table" || type == "chair" || type == "desk") {
      EXPECT_GT(occupied_in(x0 + 0.1, y0 + 0.1, x1 - 0.1, y1 - 0.1), 0);
    }
  }
}

// Bad positions and storeys: a clear error naming the file and line, exit 2, nothing written.
TEST(FloorsApp, BadTrajectoriesAndStoreysAreRefused) {
  const fs::path office = fs::path(INDOORMAP_SOURCE_DIR) / "clouds" / "office" / "cloud.pcd";
  const fs::path dir = test::scratch_dir() / "bad";
  fs::create_directories(dir);
  struct Case {
    std::string text, message;
  };
  const Case cases[] = {
      {"0 1 2 1.4 0 0 0 1\n0.5 1 two 1.4 0 0 0 1\n", "t.txt:2: column 3: 'two' is not a finite"},
      {"1 2 1.4\n1 2\n", "t.txt:2: expected 8 columns 't x y z qx qy qz qw' (TUM) or 3 'x y z'"},
      {"0 1 2 1.4 0 0 0.5 0.5\n", "t.txt:1: quaternion (qx qy qz qw) has norm 0.707107"},
      {"1 2 1.4\n40 2 1.4\n",
       "t.txt:2: position (40.000, 2.000, 1.400) lies more than 1 m outside"},
  };
  for (const auto& c : cases) {
    test::write_text(dir / "t.txt", c.text);
    const fs::path out = dir / "out";
    const auto r = run_app("pcd-to-map", office.string() + " --trajectory " +
                                             (dir / "t.txt").string() + " -q -o " + out.string());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out / "summary.json"));
  }
  const auto r =
      run_app("pcd-to-map", office.string() + " --storey 1 -q -o " + (dir / "s").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--storey 1: the cloud has 1 storey (0)"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "s" / "summary.json"));
}

// The Jacobs lab: one storey, and its door to the corridor open in map.pgm: the corridor 1.5 m
// beyond the door is reachable from the scanner for a 0.4 m robot (M_r and the room border are
// those of test_pcd_to_map / test_border_*, unchanged).
TEST(FloorsApp, JacobsOneStoreyDoorToTheCorridorOpen) {
  const auto data = test::shared_data_dir();
  if (!data || !fs::exists(*data / "jacobs-thermocolorlab"))
    GTEST_SKIP() << "shared data not found (../shared/data or $INDOORMAP_DATA)";
  const fs::path out = test::scratch_dir();
  const auto r =
      run_app("pcd-to-map", (*data / "jacobs-thermocolorlab").string() + " -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json s = read_json(out / "summary.json");
  ASSERT_EQ(s["storeys"].size(), 1u);
  EXPECT_FALSE(fs::exists(out / "storey_0"));
  const CSpace c = cspace(out / "map.yaml", 0.2);
  const auto& sc = s["scanners_map_m"][0];
  const int at_scanner = c.label_at(Eigen::Vector2d(sc[0].get<double>(), sc[1].get<double>()), 0.5);
  EXPECT_GT(at_scanner, 0);
  EXPECT_EQ(c.label_at(Eigen::Vector2d(4.2, -2.8), 0.1), at_scanner) << "the corridor";
}
