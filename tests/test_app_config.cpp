// Tests of the one config reader of the apps (apps/common/config_reader.hpp): a table of
// (section, key, field) read from YAML with the shared rules and messages, printed back.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "config_reader.hpp"
#include "indoormap/core/errors.hpp"
#include "progress.hpp"
#include "test_support.hpp"

using namespace indoormap;

namespace {

struct Params {
  double ratio = 0.5;
  double limit = 1.0;
  int count = 3;
  std::int64_t budget = 10;
  bool on = false;
  std::optional<double> floor_m;
};

template <class F>
void visit(Params& p, F&& f) {
  f("", "ratio", app::finite(p.ratio));
  f("a", "limit", p.limit);
  f("a", "count", p.count);
  f("a", "floor_m", p.floor_m);
  f("b", "budget", p.budget);
  f("b", "on", p.on);
}

Params read(const std::string& yaml) {
  const auto file = test::scratch_dir() / "c.yaml";
  test::write_text(file, yaml);
  Params p;
  app::read_config_file(file.string(), [&](auto&& f) { visit(p, f); });
  return p;
}

std::string error_of(const std::string& yaml) {
  try {
    read(yaml);
  } catch (const InputError& e) {
    return e.what();
  }
  return "<accepted>";
}

}  // namespace

TEST(ConfigReader, ReadsATableOverTheDefaultsAndPrintsItBack) {
  const Params p = read("ratio: 0.25\na:\n  count: 7\n  floor_m: 0.1\nb:\n  on: true\n");
  EXPECT_DOUBLE_EQ(p.ratio, 0.25);
  EXPECT_DOUBLE_EQ(p.limit, 1.0);
  EXPECT_EQ(p.count, 7);
  EXPECT_EQ(p.floor_m, 0.1);
  EXPECT_TRUE(p.on);
  Params q = p;
  const std::string yaml = app::config_to_yaml([&](auto&& f) { visit(q, f); });
  EXPECT_EQ(yaml,
            "ratio: 0.25\na:\n  limit: 1\n  count: 7\n  floor_m: 0.1\nb:\n  budget: 10\n  on: "
            "true\n");
  const Params back = read(yaml);
  EXPECT_EQ(back.count, 7);
  EXPECT_EQ(app::config_to_json([&](auto&& f) { visit(q, f); })["a"]["count"], 7);
  EXPECT_TRUE(read("a:\n  floor_m: null\n").floor_m == std::nullopt);
  EXPECT_EQ(read("").count, 3);  // empty file: all defaults
}

TEST(ConfigReader, OneMessageStyleFileLineKeyProblem) {
  EXPECT_NE(
      error_of("a:\n  count: 2.5\n").find("c.yaml:2: key 'a.count': expected an integer in range"),
      std::string::npos);
  EXPECT_NE(error_of("a:\n  count: .nan\n").find("key 'a.count': expected an integer in range"),
            std::string::npos);
  EXPECT_NE(error_of("b:\n  budget: 1e19\n").find("key 'b.budget': expected an integer in range"),
            std::string::npos);
  EXPECT_NE(error_of("a:\n  limit: x\n").find("c.yaml:2: key 'a.limit': expected a number"),
            std::string::npos);
  EXPECT_NE(error_of("ratio: .inf\n").find("c.yaml:1: key 'ratio': must be finite"),
            std::string::npos);
  EXPECT_NE(error_of("b:\n  on: maybe\n").find("key 'b.on': expected true or false"),
            std::string::npos);
  EXPECT_NE(error_of("a:\n  cuont: 1\n").find("c.yaml:2: unknown key 'a.cuont'"),
            std::string::npos);
  EXPECT_NE(error_of("c:\n  x: 1\n").find("c.yaml:1: unknown section 'c' (sections: a, b)"),
            std::string::npos);
  EXPECT_NE(error_of("- 1\n").find("the config must be a mapping of sections"), std::string::npos);
  EXPECT_NE(error_of("a: [1,\n").find("invalid YAML"), std::string::npos);
}

TEST(ConfigReader, StructureReaderRules) {
  const auto file = test::scratch_dir() / "s.yaml";
  test::write_text(file, "p: [1, 2]\nq: [1, x, 3]\nm: {a: 1, b: 2}\n");
  const YAML::Node root = app::load_yaml_file(file.string());
  const app::ConfigReader rd(file.string());
  EXPECT_EQ(rd.vec2(root["p"], "p"), Eigen::Vector2d(1, 2));
  try {
    rd.vec3(root["q"], "q");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.yaml:2: key 'q[1]': expected a number, got 'x'"),
              std::string::npos)
        << e.what();
  }
  try {
    rd.only_keys(root["m"], "m", {"a"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("key 'm.b': unknown key (expected one of: a)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(app::load_yaml_file((test::scratch_dir() / "none.yaml").string()), InputError);
}

TEST(Progress, BarAndLineTexts) {
  using indoormap::app::progress_text;
  using indoormap::app::ProgressMode;
  // 250 of 1000 in 2 s: 125/s, 6 s left.
  const std::string bar = progress_text("x: step", "rays", ProgressMode::kBar, 250, 1000, 2.0);
  EXPECT_EQ(bar, "x: step [======>                 ]  25%  125 rays/s  about 6 s left");
  const std::string line = progress_text("x: step", "rays", ProgressMode::kLines, 250, 1000, 2.0);
  EXPECT_EQ(line, "x: step: 25% (250 of 1000 rays, 125 rays/s, about 6 s left)");
  // Unknown total: the count and the rate only; large counts get a suffix.
  EXPECT_EQ(progress_text("p", "nodes", ProgressMode::kLines, 3'000'000, 0, 2.0),
            "p: 3.0 M nodes (1.5 M nodes/s)");
  EXPECT_EQ(progress_text("p", "nodes", ProgressMode::kBar, 3'000'000, 0, 2.0),
            "p 3.0 M nodes  1.5 M nodes/s");
  // Done: a full bar, no time left.
  EXPECT_EQ(progress_text("s", "", ProgressMode::kBar, 10, 10, 1.0),
            "s [========================] 100%");
}

TEST(Progress, TickerCallsEveryNAndAtTheEnd) {
  std::vector<std::pair<std::int64_t, std::int64_t>> calls;
  const indoormap::ProgressFn fn = [&](std::int64_t d, std::int64_t t) {
    calls.emplace_back(d, t);
  };
  {
    indoormap::ProgressTicker ticker(fn, 10, 4);
    for (int i = 0; i < 10; ++i) ticker.tick();
    ticker.finish();
  }
  ASSERT_EQ(calls.size(), 3u);
  EXPECT_EQ(calls[0], std::make_pair(std::int64_t{4}, std::int64_t{10}));
  EXPECT_EQ(calls[1], std::make_pair(std::int64_t{8}, std::int64_t{10}));
  EXPECT_EQ(calls[2], std::make_pair(std::int64_t{10}, std::int64_t{10}));
  const indoormap::ProgressFn none;
  indoormap::ProgressTicker idle(none, 0, 1);
  idle.tick(5);
  idle.finish();  // an empty function is never called
}
