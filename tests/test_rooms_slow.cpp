// Rooms of a floor (issue 16): pcd-to-map's rooms.geojson / rooms.json / rooms.png and map-eval's
// "rooms" block on simulated buildings (4 rooms and a corridor, one and two storeys) and on the
// single-room office, run as a user runs them; map-eval must accept every result pcd-to-map
// wrote. App-level, over 1 s: labelled slow.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "test_support.hpp"

using indoormap::test::run_app;
using nlohmann::json;

namespace {

namespace fs = std::filesystem;

json rooms_read_json(const fs::path& p) {
  std::ifstream in(p);
  return json::parse(in);
}

/// scene-sim --random --rooms 4 (seed, storeys) once per process, 0.5 degree steps.
fs::path rooms_building(int seed, int storeys) {
  const fs::path d = fs::temp_directory_path() / "indoormap-tests" /
                     ("rooms_building_" + std::to_string(seed) + "_" + std::to_string(storeys) +
                      "_" + std::to_string(::getpid()));
  if (fs::exists(d / "ground_truth.json")) return d;
  fs::remove_all(d);
  const auto r = run_app("scene-sim", "--random --rooms 4 --seed " + std::to_string(seed) +
                                          " --storeys " + std::to_string(storeys) +
                                          " --step-deg 0.5 --3dtk -q -o " + d.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return d;
}

/// pcd-to-map on IN, map-eval on its outputs; returns eval.json.
json rooms_map_and_eval(const fs::path& in, const fs::path& truth, const fs::path& out) {
  const auto a = run_app("pcd-to-map", in.string() + " -q -o " + out.string());
  EXPECT_EQ(a.exit_code, 0) << a.err;
  const auto e = run_app("map-eval", "--truth " + truth.string() + " --result " + out.string() +
                                         " -o " + (out / "eval").string());
  EXPECT_EQ(e.exit_code, 0) << e.err;  // never fails on a result pcd-to-map wrote
  return rooms_read_json(out / "eval" / "eval.json");
}

}  // namespace

TEST(RoomsApp, FourRoomsAndACorridorEachItsOwnRoomWithItsDoor) {
  const fs::path in = rooms_building(141, 1);
  const fs::path out = indoormap::test::scratch_dir();
  const json e = rooms_map_and_eval(in / "3dtk", in / "ground_truth.json", out);
  for (const char* f : {"rooms.geojson", "rooms.json", "rooms.png", "objects.json"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const json& r = e["rooms"];
  ASSERT_EQ(r["status"], "ok");
  EXPECT_EQ(r["truth_rooms"], 5);  // 4 rooms and the corridor
  EXPECT_EQ(r["result_rooms"], 5);
  EXPECT_EQ(r["found"], 5);
  EXPECT_EQ(r["missed"], 0);
  EXPECT_EQ(r["split"], 0);
  EXPECT_EQ(r["merged"], 0);
  EXPECT_EQ(r["doors_found"], 4);
  // Every object of objects.json has its room; rooms.json lists the room graph: the corridor
  // joins the four rooms.
  const json objs = rooms_read_json(out / "objects.json");
  for (const auto& o : objs["objects"]) EXPECT_TRUE(o.contains("room_id")) << o["id"];
  const json graph = rooms_read_json(out / "rooms.json");
  ASSERT_EQ(graph["rooms"].size(), 5u);
  int hub = 0;
  for (const auto& room : graph["rooms"]) hub = std::max<int>(hub, room["neighbours"].size());
  EXPECT_EQ(hub, 4);
  EXPECT_EQ(graph["doors"].size(), 4u);
  const json summary = rooms_read_json(out / "summary.json");
  EXPECT_EQ(summary["rooms"]["count"], 5);
}

// The walls between rooms are wall, not furniture (issue 16): the 4-room building's rooms have
// ceilings from 2.48 to 3.18 m, so the storey's wall band (under the highest ceiling) misses the
// walls of the low rooms, and the unseen inside of every inner wall lay inside the passage area;
// both became furniture strips. With the low wall band (layers.low_wall_band_m) and the inside of
// the walls (layout.wall_max_thickness_m) at most one object's centre lies in no truth room (in a
// wall); with both off, 6 did. Measured at 0.5 degree steps (2026-12-03): on 16 objects,
// recall 0.91, precision 0.69, 1 outside; off 25 objects, 0.82 / 0.40, 6 outside. Since the
// levelling trusts the floor over a ceiling of rooms at several heights (2026-12-06: this
// building was levelled 0.3 degrees off before), on 15 objects: recall 0.82 (a shelf's footprint
// grew by three cells past the match), precision 0.67, 2 outside; off 3 outside (the 8- and 12-
// room buildings gained, docs/evaluation-history.md "Rooms of a floor"). Issue 16's target
// (precision 0.9) is not reached: docs/evaluation-history.md "Rooms of a floor" says what is left.
TEST(RoomsApp, InnerWallsAreNotFurniture) {
  const fs::path in = rooms_building(141, 1);
  const fs::path out = indoormap::test::scratch_dir();
  const json e = rooms_map_and_eval(in / "3dtk", in / "ground_truth.json", out);
  ASSERT_EQ(e["objects"]["status"], "ok");
  EXPECT_LE(e["rooms"]["objects_outside_rooms"].get<int>(), 2);
  EXPECT_GE(e["objects"]["recall"].get<double>(), 0.8);
  EXPECT_GE(e["objects"]["precision"].get<double>(), 0.65);
  const json summary = rooms_read_json(out / "summary.json");
  EXPECT_GE(summary["low_wall_band"]["lo_m"].get<double>(), 2.0);  // above the furniture band

  // The same scan with both rules off: the walls come back as objects.
  const fs::path cfg = out / "rules_off.yaml";
  std::ofstream(cfg) << "layers:\n  low_wall_band_m: 0\nlayout:\n  wall_max_thickness_m: 0\n";
  const fs::path off = out / "off";
  const auto a = run_app("pcd-to-map",
                         (in / "3dtk").string() + " -c " + cfg.string() + " -q -o " + off.string());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const auto m =
      run_app("map-eval", "--truth " + (in / "ground_truth.json").string() + " --result " +
                              off.string() + " -o " + (off / "eval").string());
  ASSERT_EQ(m.exit_code, 0) << m.err;
  const json eo = rooms_read_json(off / "eval" / "eval.json");
  // The objects step's own rule for a wall's face (thin strips along a wall, 2026-12-06) now
  // drops the strips whose centre lay in no room even with both rules off; the wider pieces of
  // the walls' insides stay and cost precision.
  EXPECT_GE(eo["rooms"]["objects_outside_rooms"].get<int>(),
            e["rooms"]["objects_outside_rooms"].get<int>());
  EXPECT_LT(eo["objects"]["precision"].get<double>(), e["objects"]["precision"].get<double>())
      << "rules off: " << eo["objects"].dump() << "\non: " << e["objects"].dump();
}

TEST(RoomsApp, TwoStoreysEachWithItsRooms) {
  const fs::path in = rooms_building(142, 2);
  const fs::path out = indoormap::test::scratch_dir();
  const json e = rooms_map_and_eval(in / "3dtk", in / "ground_truth.json", out);
  ASSERT_TRUE(e.contains("storeys"));
  ASSERT_EQ(e["storeys"].size(), 2u);
  for (const auto& s : e["storeys"]) {
    ASSERT_EQ(s["rooms"]["status"], "ok") << s.dump();
    EXPECT_EQ(s["rooms"]["truth_rooms"], 5);
    EXPECT_EQ(s["rooms"]["missed"], 0);
    EXPECT_EQ(s["rooms"]["merged"], 0);
    EXPECT_GE(s["rooms"]["found"].get<int>(), 4);
  }
  // Storey 0: every door. (Storey 1 at 0.5 degree steps: its navigation map keeps every door
  // closed - floor.doors.open_share 0 - so its rooms have no doors and one room is split; at
  // scene-sim's default steps both storeys open every door: docs/evaluation.md.)
  EXPECT_EQ(e["storeys"][0]["rooms"]["doors_found"], 4);
  EXPECT_EQ(e["storeys"][0]["rooms"]["found"], 5);
  for (int k = 0; k < 2; ++k)
    EXPECT_TRUE(fs::exists(out / ("storey_" + std::to_string(k)) / "rooms.geojson")) << k;
}

// The office (one room, 51 m2, scanned from inside): the office is one room of rooms.geojson
// (IoU >= 0.85 with the truth); a separate 3.4 m2 piece of free space with no door to it comes
// out as a second room (counted "split" by map-eval; docs/evaluation-history.md says so).
TEST(RoomsApp, SingleRoomOfficeIsOneRoomPlusAPiece) {
  const fs::path office = fs::path(INDOORMAP_SOURCE_DIR) / "clouds" / "office";
  const fs::path out = indoormap::test::scratch_dir();
  const json e = rooms_map_and_eval(office / "cloud.pcd", office / "ground_truth.json", out);
  EXPECT_TRUE(fs::exists(out / "room.geojson"));  // today's outputs stay
  const json& r = e["rooms"];
  ASSERT_EQ(r["status"], "ok");
  ASSERT_FALSE(r["rooms"].empty());
  EXPECT_EQ(r["rooms"][0]["truth_room"], "office");
  EXPECT_GE(r["rooms"][0]["iou"].get<double>(), 0.85);
  EXPECT_LE(r["result_rooms"].get<int>(), 2);
  EXPECT_TRUE(rooms_read_json(out / "rooms.json")["doors"].empty());
}

// The Jacobs lab (issue 16's target: one room of 28-40 m2 with its door to the corridor): the
// lab is the room holding the scanner; a door joins it to the room beyond (the corridor's piece).
TEST(RoomsApp, JacobsLabOneRoomWithItsDoorToTheCorridor) {
  INDOORMAP_REQUIRE_DATA(data, "jacobs-thermocolorlab");
  const fs::path out = indoormap::test::scratch_dir();
  const auto r = run_app("pcd-to-map", data.string() + " -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json g = rooms_read_json(out / "rooms.json");
  int labs = 0, lab = 0;
  for (const auto& room : g["rooms"])
    if (room["area_m2"].get<double>() >= 28.0 && room["area_m2"].get<double>() <= 40.0)
      ++labs, lab = room["id"].get<int>();
  ASSERT_EQ(labs, 1) << g.dump();
  int doors = 0;
  for (const auto& d : g["doors"])
    if (d["rooms"][0] == lab || d["rooms"][1] == lab) {
      ++doors;
      EXPECT_GT(d["width_m"].get<double>(), 0.6);
      EXPECT_LT(d["width_m"].get<double>(), 1.2);
    }
  EXPECT_EQ(doors, 1);
}
