#pragma once
// Shared by the reliability tests (test_reliability.cpp, test_output_set.cpp): apps run with a
// time limit, a directory snapshot for byte-for-byte comparison, and tiny inputs.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "indoormap/core/grid.hpp"
#include "indoormap/formats/ros_map.hpp"
#include "test_support.hpp"

namespace indoormap::reliability {

namespace fs = std::filesystem;

/// run_app with a time limit (a hang is a failure, not a stuck suite) and an environment prefix.
inline test::RunResult run_limited(const std::string& app, const std::string& args,
                                   const std::string& env = "") {
  return test::run_app(app, args, env, 30);
}

/// Every file below dir (relative path -> bytes); directories as "<rel>/" -> "".
inline std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> s;
  if (!fs::exists(dir)) return s;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = fs::relative(e.path(), dir).generic_string();
    if (e.is_directory())
      s[rel + "/"] = "";
    else
      s[rel] = test::read_text(e.path());
  }
  return s;
}

/// A 3 x 2 m room of 0.05 m cells with walls around it (plan-route's and explore-sim's input).
inline fs::path small_map(const fs::path& dir) {
  Grid<Cell> room(60, 40, Cell::kFree);
  for (int c = 0; c < 60; ++c) room.at(c, 0) = room.at(c, 39) = Cell::kWall;
  for (int r = 0; r < 40; ++r) room.at(0, r) = room.at(59, r) = Cell::kWall;
  formats::write_ros_map(dir, "map", room, GridGeometry({0, 0}, 0.05, 60, 40));
  return dir / "map.yaml";
}

inline const std::string kTruth =
    R"({"format": "indoormap-ground-truth", "rooms": [], "furniture": [], "layout": )"
    R"({"image": "truth.pgm", "resolution": 0.05, "origin": [0, 0], "width": 2, "height": 2}})";

/// plan-route arguments on small_map before the output directory.
inline const std::string kPlanArgs = " --start 0.5,0.5 --goal 2.5,1.5 -q -o ";

// A 3DTK scan (cm, left-handed, y up) of a 4 x 3 m room, 2.5 m high: floor, ceiling, walls.
inline std::string tdtk_room() {
  std::string s;
  auto put = [&](double x, double y, double z) {  // output frame (m, z up) -> 3DTK
    s += std::to_string(-y * 100) + " " + std::to_string(z * 100) + " " + std::to_string(x * 100) +
         "\n";
  };
  for (double x = 0; x <= 4; x += 0.05)
    for (double y = 0; y <= 3; y += 0.05) {
      put(x, y, 0);
      put(x, y, 2.5);
    }
  for (double z = 0; z <= 2.5; z += 0.05) {
    for (double x = 0; x <= 4; x += 0.05) put(x, 0, z), put(x, 3, z);
    for (double y = 0; y <= 3; y += 0.05) put(0, y, z), put(4, y, z);
  }
  return s;
}

// A 4 x 3 x 2.5 m room of points 5 cm apart (floor, ceiling, four walls), with a 0.8 x 0.6 m desk
// 0.75 m high in the middle when `desk`.
inline std::string room_xyz(bool desk) {
  std::string s;
  auto put = [&](double x, double y, double z) {
    char line[64];
    std::snprintf(line, sizeof line, "%.3f %.3f %.3f\n", x, y, z);
    s += line;
  };
  auto steps = [](double a, double b) { return static_cast<int>(std::lround((b - a) / 0.05)); };
  auto at = [](double a, int i) { return a + 0.05 * i; };
  for (int i = 0; i <= steps(0, 4); ++i)
    for (int j = 0; j <= steps(0, 3); ++j) put(at(0, i), at(0, j), 0), put(at(0, i), at(0, j), 2.5);
  for (int k = 0; k <= steps(0, 2.5); ++k) {
    for (int i = 0; i <= steps(0, 4); ++i) put(at(0, i), 0, at(0, k)), put(at(0, i), 3, at(0, k));
    for (int j = 0; j <= steps(0, 3); ++j) put(0, at(0, j), at(0, k)), put(4, at(0, j), at(0, k));
  }
  if (!desk) return s;
  for (int i = 0; i <= steps(1.5, 2.3); ++i)
    for (int j = 0; j <= steps(1.2, 1.8); ++j) put(at(1.5, i), at(1.2, j), 0.75);
  for (int k = 0; k <= steps(0, 0.75); ++k) {
    for (int i = 0; i <= steps(1.5, 2.3); ++i)
      put(at(1.5, i), 1.2, at(0, k)), put(at(1.5, i), 1.8, at(0, k));
    for (int j = 0; j <= steps(1.2, 1.8); ++j)
      put(1.5, at(1.2, j), at(0, k)), put(2.3, at(1.2, j), at(0, k));
  }
  return s;
}

}  // namespace indoormap::reliability
