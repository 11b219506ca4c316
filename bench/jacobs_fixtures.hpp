#pragma once
// The Jacobs room map shared by the benchmarks of the 2D stages (bench_border, bench_objects):
// the scan read from ../shared/data (or $INDOORMAP_DATA) and run through the whole pre-processing
// once. Without the data jacobs() is null and the Jacobs benchmarks report an error.
// (A *_fixtures.hpp header: bench/CMakeLists.txt links what it includes.)
#include <cstdlib>
#include <filesystem>
#include <optional>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/layout/pipeline.hpp"

namespace indoormap::bench {

inline const layout::MapResult* jacobs() {
  static const std::optional<layout::MapResult> m = []() -> std::optional<layout::MapResult> {
    std::filesystem::path dir =
        std::filesystem::path(INDOORMAP_SOURCE_DIR) / ".." / "shared" / "data";
    if (const char* env = std::getenv("INDOORMAP_DATA"); env && *env) dir = env;
    dir /= "jacobs-thermocolorlab";
    if (!std::filesystem::exists(dir)) return std::nullopt;
    auto loaded = cloud_io::load_cloud(dir.string());
    return layout::make_map(std::move(loaded.cloud), {});
  }();
  return m ? &*m : nullptr;
}

}  // namespace indoormap::bench
