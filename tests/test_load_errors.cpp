// Loaders: bad input (missing, empty, truncated and malformed files, budgets) with the
// message checked.
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/core/errors.hpp"
#include "load_fixtures.hpp"
#include "test_support.hpp"

using namespace load_fixtures;

// ---------------------------------------------------------------------------------- bad input

TEST(LoadErrors, MissingFileDirectoryAndUnknownExtension) {
  const auto dir = scratch_dir();
  auto msg = message_of<InputError>([&] { load_cloud((dir / "nope.pcd").string()); });
  EXPECT_CONTAINS(msg, "nope.pcd");
  EXPECT_CONTAINS(msg, "no such file");
  msg = message_of<InputError>([&] { load_cloud((dir / "nope.las").string()); });
  EXPECT_CONTAINS(msg, "no such file");

  fs::create_directories(dir / "d.pcd");
  msg = message_of<InputError>([&] { load_cloud((dir / "d.pcd").string()); });
  EXPECT_CONTAINS(msg, "d.pcd");
  EXPECT_CONTAINS(msg, "is a directory");

  write_text(dir / "x.las2", "whatever");
  msg = message_of<InputError>([&] { load_cloud((dir / "x.las2").string()); });
  EXPECT_CONTAINS(msg, "x.las2");
  EXPECT_CONTAINS(msg, "unknown file type '.las2'");
  EXPECT_CONTAINS(msg, ".pcd, .ply, .xyz, .txt, .csv, .las");

  fs::create_directories(dir / "empty_dir");
  msg = message_of<InputError>([&] { load_cloud((dir / "empty_dir").string()); });
  EXPECT_CONTAINS(msg, "empty_dir");
  EXPECT_CONTAINS(msg, "no 3DTK scan files (scanNNN.3d)");
}

TEST(LoadErrors, EmptyFiles) {
  const auto dir = scratch_dir();
  for (const char* name : {"e.pcd", "e.ply", "e.xyz", "e.3d"}) {
    write_text(dir / name, "");
    const auto msg = message_of<InputError>([&] { load_cloud((dir / name).string()); });
    EXPECT_CONTAINS(msg, name);
    EXPECT_CONTAINS(msg, "empty");
  }
  write_text(dir / "comments.xyz", "# nothing\n\n");
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "comments.xyz").string()); }),
                  "empty cloud: no points");
}

TEST(LoadErrors, PcdHeaderProblemsNameFileAndLine) {
  const auto dir = scratch_dir();
  struct Case {
    std::string text, needle;
  };
  const std::string tail = "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n";
  const std::string head = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  const std::vector<Case> cases = {
      {"VERSION 0.7\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n" + tail, ":8: PCD header: no FIELDS"},
      {"VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 65536\n"
       "HEIGHT 65536\nPOINTS 0\nDATA binary\n",
       ":8: PCD header: WIDTH 65536 x HEIGHT 65536 does not equal POINTS 0"},
      {head + "WIDTH 2\nHEIGHT 2\nPOINTS 3\nDATA ascii\n1 2 3\n", ":8: PCD header: WIDTH 2 x"},
      {head + "WIDTH 0\nHEIGHT 1\nPOINTS 0\nDATA ascii\n", ":8: PCD header: POINTS is 0: empty"},
      {"VERSION 0.7\nFIELDS x y\nSIZE 4 4\nTYPE F F\nCOUNT 1 1\n" + tail,
       ":2: PCD header: FIELDS has no 'z'"},
      {"VERSION 0.7\nFIELDS x y z\nSIZE 4 4\nTYPE F F F\nCOUNT 1 1 1\n" + tail,
       ":3: PCD header: SIZE has 2 values but FIELDS has 3"},
      {head + "WIDTH 1\nHEIGHT 1\nPOINTS 1\n", ":8: PCD header: ends without a DATA line"},
      {head + "WIDTH one\n", ":6: PCD header: WIDTH value 'one'"},
      {head + "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA zip\n", ":9: PCD header: DATA 'zip'"},
      // 4e9 points promised, a few bytes present: refused before anyone allocates.
      {head + "WIDTH 4000000000\nHEIGHT 1\nPOINTS 4000000000\nDATA binary\nabcdefghijkl",
       ":9: PCD data section too short for POINTS 4000000000"},
      {head + "WIDTH 4000000000\nHEIGHT 1\nPOINTS 4000000000\nDATA ascii\n1 2 3\n",
       ":9: PCD data section too short for POINTS 4000000000"},
      {head + "WIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA binary\n" + std::string(35, 'a'),
       ":9: PCD data section too short for POINTS 3"},
      // ASCII bodies are checked line by line (PCL would silently read zeros).
      {head + "WIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n1 2 3\n4 5 6\n7       8\n",
       ":12: PCD data line has 2 values, expected 3"},
      {head + "WIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n1 2 3\n4 five 6\n7 8 9\n",
       ":11: PCD value 'five' of field y is not a number"},
      {head + "WIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n1 2 3\n4 5 6\n\n\n\n\n\n\n",
       ": PCD data has 2 points but POINTS says 3"},
      {head + "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n4 5 6\n",
       ":11: more data lines than POINTS 1"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    // Appending (not "h" + to_string) avoids GCC 12's false -Wrestrict (GCC bug 105651).
    std::string name = "h";
    name += std::to_string(i);
    const auto f = dir / (name + ".pcd");
    write_text(f, cases[i].text);
    const auto msg = message_of<InputError>([&] { load_cloud(f.string()); });
    EXPECT_CONTAINS(msg, f.string() + cases[i].needle);
  }
}

TEST(LoadErrors, PcdCompressedSizesChecked) {
  const auto dir = scratch_dir();
  std::uint32_t wrong = 1000;
  write_text(dir / "u.pcd", compressed_pcd(&wrong));
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "u.pcd").string()); }),
                  "uncompressed size 1000 does not match");
  const std::string good = compressed_pcd();
  write_text(dir / "t.pcd", good.substr(0, good.size() - 4));
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "t.pcd").string()); }),
                  "too short");
}

// Every prefix of a valid file is either refused with InputError or (when only the final
// newline is missing) loaded in full: never a crash, never another exception, never a
// silently shortened or zero-filled cloud.
TEST(LoadErrors, TruncatedFilesNeverCrash) {
  const auto dir = scratch_dir();
  const std::vector<std::pair<std::string, std::string>> files = {{"a.pcd", kAsciiPcd},
                                                                  {"b.pcd", binary_pcd()},
                                                                  {"c.pcd", compressed_pcd()},
                                                                  {"b.ply", binary_ply()}};
  for (const auto& [name, bytes] : files) {
    for (std::size_t n = 0; n < bytes.size(); ++n) {
      const auto f = dir / name;
      write_text(f, bytes.substr(0, n));
      try {
        const auto r = load_cloud(f.string());
        const auto full = dir / ("full_" + name);
        write_text(full, bytes);
        EXPECT_EQ(r.cloud.points, load_cloud(full.string()).cloud.points)
            << name << " cut at " << n;
      } catch (const InputError& e) {
        EXPECT_CONTAINS(e.what(), f.string());
      } catch (const std::exception& e) {
        ADD_FAILURE() << name << " cut at " << n << ": " << e.what();
      }
    }
  }
}

TEST(LoadErrors, PlyProblems) {
  const auto dir = scratch_dir();
  write_text(dir / "t.ply", binary_ply(true));
  auto msg = message_of<InputError>([&] { load_cloud((dir / "t.ply").string()); });
  EXPECT_CONTAINS(msg, "t.ply");
  EXPECT_CONTAINS(msg, "truncated");

  write_text(dir / "h.ply",
             "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
             "property float x\nproperty float y\nproperty float z\nend_header\n0123456789ab");
  msg = message_of<InputError>([&] { load_cloud((dir / "h.ply").string()); });
  EXPECT_CONTAINS(msg, "h.ply:3: PLY data section too short for 4000000000 'vertex'");

  write_text(dir / "n.ply",
             "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
             "property float y\nend_header\n1 2\n");
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "n.ply").string()); }),
                  "n.ply:3: PLY header: vertex has no property 'z'");

  write_text(dir / "m.ply", "plx\n");
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "m.ply").string()); }),
                  "m.ply:1: PLY header: the file does not start with 'ply'");

  write_text(dir / "e.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n");
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "e.ply").string()); }),
                  "ends without end_header");

  write_text(dir / "v.ply",
             "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
             "property float y\nproperty float z\nend_header\n1 2 3\n4 five 6\n");
  EXPECT_CONTAINS(message_of<InputError>([&] { load_cloud((dir / "v.ply").string()); }),
                  "v.ply:9: PLY value 'five' is not a number");
}

TEST(LoadErrors, MalformedXyzLineNamesLine) {
  const auto dir = scratch_dir();
  write_text(dir / "m.xyz", "# header\n1 2 3\n4 5\n");
  auto msg = message_of<InputError>([&] { load_cloud((dir / "m.xyz").string()); });
  EXPECT_CONTAINS(msg, "m.xyz:3: malformed line");
  EXPECT_CONTAINS(msg, "'4 5'");
  write_text(dir / "n.txt", "1 2 3\r\n1 2 3x\r\n");
  msg = message_of<InputError>([&] { load_cloud((dir / "n.txt").string()); });
  EXPECT_CONTAINS(msg, "n.txt:2: malformed line");
  write_text(dir / "scan000.3d", "1 2 3\nabc\n");
  msg = message_of<InputError>([&] { load_cloud((dir / "scan000.3d").string()); });
  EXPECT_CONTAINS(msg, "scan000.3d:2: malformed line");
  fs::create_directories(dir / "s");
  write_text(dir / "s" / "scan000.3d", "1 2 3\n");
  write_text(dir / "s" / "scan000.pose", "1 2 3\n4 5\n");
  msg = message_of<InputError>([&] { load_cloud((dir / "s").string()); });
  EXPECT_CONTAINS(msg, "scan000.pose:2: pose line 2 must be the Euler angles");
}

TEST(LoadErrors, AllNaN) {
  const auto dir = scratch_dir();
  write_text(dir / "n.xyz", "nan nan nan\ninf 0 0\n");
  const auto msg = message_of<InputError>([&] { load_cloud((dir / "n.xyz").string()); });
  EXPECT_CONTAINS(msg, "n.xyz");
  EXPECT_CONTAINS(msg, "all 2 points are non-finite");
}

TEST(LoadErrors, BudgetExceeded) {
  const auto dir = scratch_dir();
  write_text(dir / "a.pcd", kAsciiPcd);
  write_text(dir / "b.xyz", "1 2 3\n4 5 6\n7 8 9\n");
  write_text(dir / "c.ply", binary_ply());
  LoadOptions o;
  o.max_points = 2;
  auto msg = message_of<BudgetError>([&] { load_cloud((dir / "a.pcd").string(), o); });
  EXPECT_CONTAINS(msg, "a.pcd: 3 points exceed the point budget (max_points 2)");
  msg = message_of<BudgetError>([&] { load_cloud((dir / "b.xyz").string(), o); });
  EXPECT_CONTAINS(msg, "b.xyz");
  EXPECT_CONTAINS(msg, "max_points 2");
  // The running total counts: 2 PLY points fit alone, not after the 3 PCD points.
  o.max_points = 4;
  EXPECT_EQ(load_cloud((dir / "c.ply").string(), o).cloud.points.size(), 2u);
  msg = message_of<BudgetError>([&] {
    load_clouds({(dir / "a.pcd").string(), (dir / "c.ply").string()}, o);
  });
  EXPECT_CONTAINS(msg, "c.ply: 2 points exceed the point budget (max_points 4, 3 already loaded)");
}
