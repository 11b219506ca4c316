// libFuzzer entry point: each fuzz binary links this file and exactly one target. A finding
// (see fuzz_target.hpp) aborts, so libFuzzer saves the input as crash-<sha1>; minimise it with
// -minimize_crash=1 and add it to tests/fuzz/regressions/<target>/.
#include <cstdio>
#include <cstdlib>

#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const indoormap::fuzz::Target& target = []() -> const indoormap::fuzz::Target& {
    if (indoormap::fuzz::targets().size() != 1) {
      std::fprintf(stderr, "fuzz binary must link exactly one target\n");
      std::abort();
    }
    return indoormap::fuzz::targets().front();
  }();
  const auto failure =
      indoormap::fuzz::run_one(target, std::string_view(reinterpret_cast<const char*>(data), size));
  if (failure) {
    std::fprintf(stderr, "indoormap fuzz target '%s': %s\n", target.name, failure->c_str());
    std::abort();
  }
  return 0;
}
