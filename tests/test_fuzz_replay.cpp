// The fuzz targets (tests/fuzz) replayed without fuzzing, in every build (no clang needed): each
// target over its seed corpus tests/fuzz/corpus/<target>/ and its crash regressions
// tests/fuzz/regressions/<target>/. Every file must be read or refused with indoormap::Error;
// under the ASan + UBSan build (test.sh --sanitize) this also proves them free of memory errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "fuzz_target.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using indoormap::fuzz::find_target;
using indoormap::fuzz::targets;

namespace {

const fs::path kFuzzDir = INDOORMAP_FUZZ_DIR;

std::vector<std::string> target_names() {
  std::vector<std::string> names;
  for (const auto& t : targets()) names.emplace_back(t.name);
  return names;
}

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename() != "README.md") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

class FuzzReplay : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzReplay, CorpusIsReadOrRefusedWithTypedError) {
  const auto* target = find_target(GetParam());
  ASSERT_NE(target, nullptr);
  const auto files = files_in(kFuzzDir / "corpus" / GetParam());
  EXPECT_GE(files.size(), 5u) << "seed corpus of '" << GetParam() << "' is missing or too small";
  for (const auto& f : files) {
    const std::string bytes = indoormap::test::read_text(f);
    EXPECT_LE(bytes.size(), 16u * 1024) << f << ": keep seeds small";
    const auto failure = indoormap::fuzz::run_one(*target, bytes);
    EXPECT_FALSE(failure) << f << ": " << *failure;
  }
}

TEST_P(FuzzReplay, RegressionsAreReadOrRefusedWithTypedError) {
  const auto* target = find_target(GetParam());
  ASSERT_NE(target, nullptr);
  for (const auto& f : files_in(kFuzzDir / "regressions" / GetParam())) {
    const auto failure = indoormap::fuzz::run_one(*target, indoormap::test::read_text(f));
    EXPECT_FALSE(failure) << f << ": " << *failure;
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzReplay, ::testing::ValuesIn(target_names()),
                         [](const auto& info) { return info.param; });

TEST(FuzzHarness, EveryCorpusDirectoryHasATarget) {
  EXPECT_GE(targets().size(), 6u);
  for (const char* kind : {"corpus", "regressions"}) {
    for (const auto& e : fs::directory_iterator(kFuzzDir / kind)) {
      if (e.is_directory()) {
        EXPECT_NE(find_target(e.path().filename().string()), nullptr)
            << e.path() << " has no fuzz target of that name";
      }
    }
  }
}

TEST(FuzzHarness, SplitParts) {
  using indoormap::fuzz::split_parts;
  const auto p = split_parts("a\n--part--\nb\n--part--\nc", 2);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0], "a");
  EXPECT_EQ(p[1], "b\n--part--\nc");
  EXPECT_EQ(split_parts("abc", 4).size(), 1u);
}
