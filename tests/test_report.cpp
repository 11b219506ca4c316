// Tests of apps/common's provenance (SHA-256, input digests, command line) and report content
// (report.html's figures equal summary.json's; pictures embedded; output lines).
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "indoormap/core/errors.hpp"
#include "indoormap/formats/report_html.hpp"
#include "provenance.hpp"
#include "report.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace indoormap;
using nlohmann::json;

TEST(Provenance, Sha256MatchesFips180Vectors) {
  // FIPS 180-4 examples (NIST CSRC "SHA256.pdf", "SHA2_Additional.pdf").
  EXPECT_EQ(app::sha256_hex(""),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(app::sha256_hex("abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(app::sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(app::sha256_hex(std::string(1'000'000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Provenance, FileDigestStreamsAcrossChunksAndNamesUnreadableFiles) {
  const fs::path dir = test::scratch_dir();
  std::string bytes(3 * (1 << 20) + 17, '\0');  // three 1 MiB chunks and a bit
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 131 % 251);
  test::write_text(dir / "big.bin", bytes);
  EXPECT_EQ(app::sha256_file(dir / "big.bin"), app::sha256_hex(bytes));
  test::write_text(dir / "a.txt", std::string(1'000'000, 'a'));
  EXPECT_EQ(app::sha256_file(dir / "a.txt"),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  try {
    app::sha256_file(dir / "missing.pcd");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.pcd"), std::string::npos) << e.what();
  }
}

TEST(Provenance, DirectoriesAreEveryFileInThemSorted) {
  const fs::path dir = test::scratch_dir();
  fs::create_directories(dir / "scans" / "sub");
  test::write_text(dir / "scans" / "scan001.3d", "1 2 3\n");
  test::write_text(dir / "scans" / "scan000.3d", "abc");
  test::write_text(dir / "scans" / "sub" / "x.pose", "");
  test::write_text(dir / "cloud.xyz", "0 0 0\n");
  const auto d = app::digest_inputs({(dir / "cloud.xyz").string(), (dir / "scans").string()});
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(fs::path(d[0].path).filename(), "cloud.xyz");
  EXPECT_EQ(d[0].size_bytes, 6u);
  EXPECT_EQ(fs::path(d[1].path).filename(), "scan000.3d");
  EXPECT_EQ(d[1].sha256, app::sha256_hex("abc"));
  EXPECT_EQ(fs::path(d[2].path).filename(), "scan001.3d");
  EXPECT_EQ(fs::path(d[3].path).filename(), "x.pose");
  EXPECT_EQ(d[3].sha256, app::sha256_hex(""));
}

// Hashed ahead on the background thread (start_digests), the digests are the ones computed on
// the spot, and a second start hashes nothing twice.
TEST(Provenance, BackgroundDigestsAreTheOnesComputedOnTheSpot) {
  const fs::path dir = test::scratch_dir();
  std::string bytes(5 * (1 << 20) + 3, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 7 % 253);
  test::write_text(dir / "ahead.bin", bytes);
  test::write_text(dir / "small.xyz", "1 2 3\n");
  const std::vector<std::string> in = {(dir / "ahead.bin").string(), (dir / "small.xyz").string()};
  app::start_digests(in);
  app::start_digests(in);  // again: nothing started twice
  const auto d = app::digest_inputs(in);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].sha256, app::sha256_hex(bytes));
  EXPECT_EQ(d[0].size_bytes, bytes.size());
  EXPECT_EQ(d[1].sha256, app::sha256_hex("1 2 3\n"));
}

TEST(Provenance, JsonHoldsCommandLineStartVersionRevisionAndInputs) {
  const fs::path dir = test::scratch_dir();
  test::write_text(dir / "in.xyz", "1 1 1\n");
  const char* argv[] = {"pcd-to-map", "in.xyz", "-o", "out dir"};
  app::record_invocation(4, argv);
  const json p = app::provenance_json({(dir / "in.xyz").string()});
  EXPECT_EQ(p["command_line"], json({"pcd-to-map", "in.xyz", "-o", "out dir"}));
  const std::string t = p["started_utc"];
  ASSERT_EQ(t.size(), 20u) << t;  // 2026-12-02T08:00:37Z
  EXPECT_EQ(t[4], '-');
  EXPECT_EQ(t[10], 'T');
  EXPECT_EQ(t.back(), 'Z');
  EXPECT_FALSE(p["version"].get<std::string>().empty());
  EXPECT_FALSE(p["revision"].get<std::string>().empty());  // git describe, or "unknown"
  ASSERT_EQ(p["inputs"].size(), 1u);
  EXPECT_EQ(p["inputs"][0]["size_bytes"], 6);
  EXPECT_EQ(p["inputs"][0]["sha256"], app::sha256_hex("1 1 1\n"));
}

namespace {

/// The figure keyed by pointer (the first), or nullptr.
const formats::ReportFigure* figure(const formats::ReportContent& c, const std::string& pointer) {
  for (const auto& s : c.sections)
    for (const auto& f : s.figures)
      if (f.key == pointer) return &f;
  for (const auto& t : c.tables)
    for (const auto& row : t.rows)
      for (const auto& f : row)
        if (f.key == pointer) return &f;
  for (const auto& f : c.timings)
    if (f.key == pointer) return &f;
  return nullptr;
}

}  // namespace

TEST(Report, FiguresAreSummaryValuesKeyedByTheirPointer) {
  const fs::path dir = test::scratch_dir();
  const std::string png("\x89PNG\r\n\x1a\n", 8);
  test::write_text(dir / "map.png", png);
  test::write_text(dir / "areas_labels.png", png);  // a label image: data, not a picture
  const json summary = {
      {"program", "demo"},
      {"provenance",
       {{"command_line", {"demo", "a b"}},
        {"started_utc", "2026-01-01T00:00:00Z"},
        {"version", "0.1.0"},
        {"revision", "abc123"},
        {"inputs", {{{"path", "in.pcd"}, {"size_bytes", 42}, {"sha256", "ff"}}}}}},
      {"floor_z_m", 0.025},
      {"found", true},
      {"grid", {{"width", 207}, {"origin_m", {-0.05, -2.25}}, {"a/b", 1}}},
      {"storeys", {{{"floor_z_m", 0.1}}, {{"floor_z_m", 3.2}}}},
      {"warnings", {"no ceiling"}},
      {"timings_ms", {{"load", 12.345678}, {"total", 100}}},
      {"parameters", {{"cell_m", 0.05}}},
  };
  const auto c = app::report_content(summary, dir, {"map.png", "areas_labels.png", "x.weird"});
  EXPECT_EQ(c.title, "demo: in.pcd");
  ASSERT_NE(figure(c, "/floor_z_m"), nullptr);
  EXPECT_EQ(figure(c, "/floor_z_m")->value, "0.025");
  EXPECT_EQ(figure(c, "/found")->value, "true");
  EXPECT_EQ(figure(c, "/grid/width")->value, "207");
  EXPECT_EQ(figure(c, "/grid/a~1b")->value, "1");  // RFC 6901 escaping
  EXPECT_EQ(figure(c, "/storeys/1/floor_z_m")->value, "3.2");
  EXPECT_EQ(figure(c, "/timings_ms/load")->value, "12.3457");  // 6 significant digits
  EXPECT_EQ(figure(c, "/timings_ms/load")->label, "load (ms)");
  EXPECT_EQ(figure(c, "/provenance/inputs/0/size_bytes")->value, "42");
  EXPECT_EQ(figure(c, "/provenance/revision")->value, "abc123");
  EXPECT_EQ(figure(c, "/parameters/cell_m")->value, "0.05");
  EXPECT_EQ(c.sections.front().figures.front().value, "demo 'a b'");  // the command line
  // Every keyed figure's value is the summary's value at its pointer, as displayed.
  std::vector<formats::ReportFigure> keyed;
  for (const auto& s : c.sections) keyed.insert(keyed.end(), s.figures.begin(), s.figures.end());
  for (const auto& row : c.tables.at(0).rows) keyed.insert(keyed.end(), row.begin(), row.end());
  int checked = 0;
  for (const auto& f : keyed) {
    if (f.key.empty()) continue;
    const json& v = summary.at(json::json_pointer(f.key));
    if (v.is_number_integer()) {
      EXPECT_EQ(f.value, v.dump()) << f.key;
    } else if (v.is_string()) {
      EXPECT_EQ(f.value, v.get<std::string>()) << f.key;
    }
    ++checked;
  }
  EXPECT_GE(checked, 13);
  EXPECT_EQ(c.warnings, std::vector<std::string>{"no ceiling"});
  ASSERT_EQ(c.pictures.size(), 1u);
  EXPECT_EQ(c.pictures[0].file, "map.png");
  EXPECT_EQ(c.pictures[0].png_bytes, png);
  ASSERT_EQ(c.files.size(), 3u);
  EXPECT_NE(c.files[0].description.find("navigation map"), std::string::npos);
  EXPECT_EQ(c.files[2].description, "output file");
  app::ReportExtras extras;
  extras.descriptions["x.weird"] = "the app's own file";
  EXPECT_EQ(app::describe_output("sub/x.weird", extras), "the app's own file");
}

TEST(Report, InputsOfOneFolderAreListedRelativeToItAndNameTheTitle) {
  const json summary = {
      {"program", "pcd-to-map"},
      {"provenance",
       {{"inputs",
         {{{"path", "/data/jacobs/scan000.3d"}, {"size_bytes", 10}, {"sha256", "aa"}},
          {{"path", "/data/jacobs/sub/scan000.pose"}, {"size_bytes", 2}, {"sha256", "bb"}}}}}}};
  const auto c = app::report_content(summary, test::scratch_dir(), {});
  EXPECT_EQ(c.title, "pcd-to-map: jacobs");
  ASSERT_EQ(c.tables.size(), 1u);
  ASSERT_EQ(c.tables[0].rows.size(), 2u);
  EXPECT_EQ(c.tables[0].rows[1][0].value, "sub/scan000.pose");
  EXPECT_EQ(c.tables[0].rows[1][0].key, "");  // not the summary's path as written
  EXPECT_EQ(c.tables[0].rows[1][2].value, "bb");
  EXPECT_EQ(c.tables[0].rows[1][2].key, "/provenance/inputs/1/sha256");
  const auto folder = std::find_if(c.sections[0].figures.begin(), c.sections[0].figures.end(),
                                   [](const auto& f) { return f.label == "input folder"; });
  ASSERT_NE(folder, c.sections[0].figures.end());
  EXPECT_EQ(folder->value, "/data/jacobs");
  // One file: its full path, keyed; no inputs at all: the program alone.
  const json one = {{"program", "plan-route"},
                    {"provenance", {{"inputs", {{{"path", "m/map.yaml"}, {"size_bytes", 1}}}}}}};
  const auto c1 = app::report_content(one, test::scratch_dir(), {});
  EXPECT_EQ(c1.title, "plan-route: map.yaml");
  EXPECT_EQ(c1.tables[0].rows[0][0].value, "m/map.yaml");
  EXPECT_EQ(c1.tables[0].rows[0][0].key, "/provenance/inputs/0/path");
  EXPECT_EQ(app::report_content({{"program", "scene-sim"}}, test::scratch_dir(), {}).title,
            "scene-sim");
}
