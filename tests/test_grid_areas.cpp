// grid-areas end to end: a generated floor (lib/sim area_maps) to every output, the speed mask
// decoded through map_server's scale formula and the filter info's base / multiplier to the
// configured limits, the label image against areas.json, --print-config, bad input (exit 2, no
// output), a footprint that fits nowhere (exit 3, no output), and --score on a shared map.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "indoormap/formats/areas_geojson.hpp"
#include "indoormap/formats/costmap_masks.hpp"
#include "indoormap/formats/pgm.hpp"
#include "indoormap/sim/area_maps.hpp"
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using namespace indoormap;
using indoormap::test::read_text;
using indoormap::test::run_app;
using nlohmann::json;

bool empty_or_missing(const fs::path& dir) {
  return !fs::exists(dir) || fs::is_empty(dir);
}

/// A generated floor as a plain PGM (255 free, 0 wall) in dir.
fs::path floor_pgm(const fs::path& dir) {
  sim::AreaMapParams p;
  p.arm_length_m = 5.0;
  p.rotation_deg = 10.0;
  p.clutter_per_room = 3;
  const sim::AreaMap m = sim::make_area_map(sim::AreaMapShape::kFloor, p);
  Grid<std::uint8_t> grey(m.cells.width, m.cells.height, 0);
  for (std::size_t i = 0; i < grey.size(); ++i)
    grey.data[i] = m.cells.data[i] == Cell::kFree ? 255 : 0;
  formats::write_pgm(dir / "floor.pgm", grey);
  return dir / "floor.pgm";
}

/// The value of "key: value" in a YAML text written by grid-areas (flat lines only).
double yaml_number(const std::string& text, const std::string& key) {
  const auto at = text.find(key + ":");
  EXPECT_NE(at, std::string::npos) << key;
  return at == std::string::npos ? NAN : std::stod(text.substr(at + key.size() + 1));
}

TEST(GridAreas, FloorToEveryOutputAndTheSpeedMaskDecodesToTheLimits) {
  const fs::path dir = test::scratch_dir();
  const fs::path map = floor_pgm(dir);
  test::write_text(dir / "cfg.yaml",
                   "speed:\n  room_percent: 100\n  corridor_percent: 70\n  crossing_percent: 30\n");
  const fs::path out = dir / "out";
  auto r = run_app("grid-areas", map.string() + " --resolution 0.05 -c " +
                                     (dir / "cfg.yaml").string() + " -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f :
       {"areas.geojson", "areas.json", "areas_labels.png", "areas.png", "summary.json",
        "speed_mask.pgm", "speed_mask.yaml", "speed_filter_info.yaml", "keepout_mask.pgm",
        "keepout_mask.yaml", "keepout_filter_info.yaml"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const json areas = json::parse(read_text(out / "areas.json"));
  std::map<int, std::string> type;
  for (const auto& a : areas["areas"]) type[a["id"].get<int>()] = a["type"].get<std::string>();
  std::map<std::string, int> count;
  for (const auto& [id, t] : type) ++count[t];
  EXPECT_EQ(count["crossing"], 3);  // the floor's X, T and corner
  EXPECT_EQ(count["room"], 2);
  EXPECT_GE(count["corridor"], 3);
  EXPECT_EQ(areas["graph"]["components"].get<int>(), 1);
  const json geo = json::parse(read_text(out / "areas.geojson"));
  int polygons = 0, doors = 0;
  for (const auto& f : geo["features"]) {
    if (f["geometry"]["type"] == "Polygon") {
      ++polygons;
      const auto& ring = f["geometry"]["coordinates"][0];
      EXPECT_EQ(ring.front(), ring.back());
    } else {
      ++doors;
      EXPECT_EQ(f["properties"]["type"], "door");
    }
  }
  EXPECT_EQ(polygons, static_cast<int>(type.size()));
  EXPECT_EQ(doors, static_cast<int>(areas["graph"]["edges"].size()));

  // The speed mask through map_server (scale, thresholds from its YAML) and the filter info.
  const std::string mask_yaml = read_text(out / "speed_mask.yaml");
  EXPECT_NE(mask_yaml.find("mode: scale"), std::string::npos);
  const double occ_th = yaml_number(mask_yaml, "occupied_thresh");
  const double free_th = yaml_number(mask_yaml, "free_thresh");
  const std::string info = read_text(out / "speed_filter_info.yaml");
  EXPECT_EQ(yaml_number(info, "type"), 1.0);
  const double base = yaml_number(info, "base"), mult = yaml_number(info, "multiplier");
  const Grid<std::uint8_t> mask = formats::read_pgm(out / "speed_mask.pgm");
  const Grid<std::uint16_t> labels = formats::read_labels_png(out / "areas_labels.png");
  ASSERT_EQ(mask.width, labels.width);
  const std::map<std::string, double> want = {{"room", 100}, {"corridor", 70}, {"crossing", 30}};
  int checked = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!labels.data[i]) continue;
    ASSERT_TRUE(type.count(labels.data[i])) << labels.data[i];
    const double occ = (255.0 - mask.data[i]) / 255.0;
    const int value =
        occ >= occ_th ? 100
        : occ <= free_th
            ? 0
            : static_cast<int>(std::lround(100.0 * (occ - free_th) / (occ_th - free_th)));
    const double limit = value == 0 ? 100.0 : base + mult * value;  // 0: Nav2's "no limit"
    ASSERT_DOUBLE_EQ(limit, want.at(type[labels.data[i]])) << "cell " << i;
    ++checked;
  }
  EXPECT_GT(checked, 1000);
  const json summary = json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["program"], "grid-areas");
  EXPECT_TRUE(summary["timings_ms"].contains("split"));
}

TEST(GridAreas, PrintConfigReadsBack) {
  const fs::path dir = test::scratch_dir();
  auto r = run_app("grid-areas", "--print-config");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("door_max_width_m"), std::string::npos);
  test::write_text(dir / "all.yaml", r.out);
  auto again = run_app("grid-areas", "-c " + (dir / "all.yaml").string() + " --print-config");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.out, r.out);
  // The documented defaults are the built-in ones.
  auto cfg = run_app("grid-areas", std::string("-c ") + INDOORMAP_SOURCE_DIR +
                                       "/config/grid-areas.yaml --print-config");
  ASSERT_EQ(cfg.exit_code, 0) << cfg.err;
  EXPECT_EQ(cfg.out, r.out);
}

TEST(GridAreas, BadInputExits2AndFootprintThatFitsNowhereExits3WithoutOutput) {
  const fs::path dir = test::scratch_dir();
  test::write_text(dir / "text.png", "this is not an image\n");
  auto r = run_app("grid-areas",
                   (dir / "text.png").string() + " --resolution 0.05 -o " + (dir / "o1").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("text.png"), std::string::npos) << r.err;
  EXPECT_TRUE(empty_or_missing(dir / "o1"));

  formats::write_pgm(dir / "black.pgm", Grid<std::uint8_t>(40, 30, 0));
  r = run_app("grid-areas",
              (dir / "black.pgm").string() + " --resolution 0.05 -o " + (dir / "o2").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("no free cell"), std::string::npos) << r.err;
  EXPECT_TRUE(empty_or_missing(dir / "o2"));

  const fs::path map = floor_pgm(dir);
  test::write_text(dir / "big.yaml", "footprint:\n  robot_width_m: 3.0\n  robot_length_m: 3.0\n");
  r = run_app("grid-areas", map.string() + " --resolution 0.05 -c " + (dir / "big.yaml").string() +
                                " -o " + (dir / "o3").string());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("fits nowhere"), std::string::npos) << r.err;
  EXPECT_TRUE(empty_or_missing(dir / "o3"));

  test::write_text(dir / "typo.yaml", "rooms:\n  door_width: 1.0\n");
  r = run_app("grid-areas", map.string() + " --resolution 0.05 -c " + (dir / "typo.yaml").string() +
                                " -o " + (dir / "o4").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(empty_or_missing(dir / "o4"));

  r = run_app("grid-areas", map.string() + " -o " + (dir / "o5").string());  // no --resolution
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(empty_or_missing(dir / "o5"));
}

TEST(GridAreas, ScoreOnASharedMap) {
  INDOORMAP_REQUIRE_DATA(data, "room-segmentation-maps");
  const fs::path out = test::scratch_dir() / "out";
  auto r = run_app("grid-areas",
                   (data / "office_d_furnitures.png").string() + " --resolution 0.05 --score " +
                       (data / "office_d_gt_segmentation.png").string() + " -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json s = json::parse(read_text(out / "score.json"));
  EXPECT_GE(s["recall"].get<double>(), 0.98);
  EXPECT_GE(s["precision"].get<double>(), 0.98);
}

}  // namespace
