#pragma once
// Fuzz targets: one function per reader that pushes arbitrary bytes through the WHOLE reading
// path (bytes -> temporary file(s) -> public loader), shared by the libFuzzer binaries
// (fuzz_main.cpp, clang only, INDOORMAP_FUZZ=ON) and the GoogleTest replay of the seed corpora
// and crash regressions (tests/test_fuzz_replay.cpp, every build). Contract of a target: it
// returns normally or throws indoormap::Error; anything else (std::bad_alloc, another
// exception, a crash, a hang, a leak, a sanitizer report) is a finding.
//
// Adding a reader: write tests/fuzz/targets/<name>.cpp with INDOORMAP_FUZZ_TARGET(<name>), add
// <name> to the list in tests/fuzz/CMakeLists.txt, and put seeds in tests/fuzz/corpus/<name>/.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace indoormap::fuzz {

using TargetFn = void (*)(std::string_view bytes);

struct Target {
  const char* name;
  TargetFn fn;
};

/// Adds a target to the registry (called by INDOORMAP_FUZZ_TARGET at static initialisation).
bool register_target(const char* name, TargetFn fn);
/// Every target linked into this binary, in registration order.
const std::vector<Target>& targets();
/// The target called `name`, or nullptr.
const Target* find_target(std::string_view name);

/// Runs one input through a target. nullopt when it returned or threw indoormap::Error (with a
/// non-empty message; an InputError must name its file); otherwise what went wrong.
std::optional<std::string> run_one(const Target& target, std::string_view bytes);

/// A directory private to this process, emptied on every call: the home of one input's files.
std::filesystem::path fresh_dir();
/// Writes bytes to dir / name and returns the path.
std::filesystem::path write_file(const std::filesystem::path& dir, const std::string& name,
                                 std::string_view bytes);

/// Multi-file inputs (map YAML + image, 3DTK scan + pose files) are one byte string whose
/// parts are separated by this line. Missing parts are empty / absent.
inline constexpr std::string_view kPartSeparator = "\n--part--\n";
/// Splits bytes into at most max_parts parts at kPartSeparator (the last part keeps the rest).
std::vector<std::string_view> split_parts(std::string_view bytes, std::size_t max_parts);

/// Point budget of the cloud targets (LoadOptions::max_points): the inputs are small, so
/// anything allocating beyond this is refused rather than allowed to exhaust -rss_limit_mb.
inline constexpr std::uint64_t kMaxPoints = 1'000'000;
/// Cell budget of the map target (read_ros_map's max_cells).
inline constexpr std::int64_t kMaxCells = 4'000'000;

}  // namespace indoormap::fuzz

#define INDOORMAP_FUZZ_TARGET(name)                                      \
  static void indoormap_fuzz_##name(std::string_view bytes);             \
  [[maybe_unused]] static const bool indoormap_fuzz_registered_##name =  \
      ::indoormap::fuzz::register_target(#name, &indoormap_fuzz_##name); \
  static void indoormap_fuzz_##name(std::string_view bytes)
