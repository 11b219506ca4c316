// A whole floor end to end (issue 15, speed and memory): pcd-to-map on a simulated 12-room
// building of about 20 M points (scene-sim --rooms 12 --step-deg 0.15, the merged cloud.pcd with
// --scanner per position), load to every output, against pcl::io::loadPCDFile alone on the same
// file, in the same run. The building is simulated once, by the scene-sim binary beside this one
// (bin/, or $INDOORMAP_BIN_DIR), into a temporary directory. pcd-to-map runs as a child process, as
// a user runs it; its peak memory (getrusage of the children, ru_maxrss) is reported as the counter
// peak_rss_mb. Results: docs/benchmarks.md ("A whole floor end to end").
#include <benchmark/benchmark.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

namespace fs = std::filesystem;

// The apps: $INDOORMAP_BIN_DIR when set (another build's bin/), else beside this binary.
fs::path bin_dir() {
  if (const char* env = std::getenv("INDOORMAP_BIN_DIR")) return env;
  return fs::read_symlink("/proc/self/exe").parent_path();
}

struct Floor {
  fs::path dir;
  std::string scanners;  // --scanner X,Y,Z per position
};

const Floor& floor12() {
  static const Floor f = [] {
    Floor r;
    r.dir = fs::temp_directory_path() / ("indoormap-bench-floor-" + std::to_string(::getpid()));
    fs::remove_all(r.dir);
    const std::string cmd = (bin_dir() / "scene-sim").string() +
                            " --random --rooms 12 --seed 221 --step-deg 0.15 -q -o " +
                            (r.dir / "sim").string();
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("scene-sim failed: " + cmd);
    std::ifstream in(r.dir / "sim" / "ground_truth.json");
    const auto j = nlohmann::json::parse(in);
    std::ostringstream s;
    for (const auto& sc : j["scanners"])
      s << " --scanner " << sc["position_cloud_m"][0].get<double>() << ","
        << sc["position_cloud_m"][1].get<double>() << ","
        << sc["position_cloud_m"][2].get<double>();
    r.scanners = s.str();
    return r;
  }();
  return f;
}

void BM_PclLoadPcd(benchmark::State& state) {
  const Floor& f = floor12();
  for (auto _ : state) {
    pcl::PointCloud<pcl::PointXYZ> cloud;
    if (pcl::io::loadPCDFile((f.dir / "sim" / "cloud.pcd").string(), cloud) != 0)
      state.SkipWithError("loadPCDFile failed");
    benchmark::DoNotOptimize(cloud.points.data());
    state.counters["points"] = static_cast<double>(cloud.size());
  }
}
BENCHMARK(BM_PclLoadPcd)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_PcdToMapEndToEnd(benchmark::State& state) {
  const Floor& f = floor12();
  const std::string cmd = (bin_dir() / "pcd-to-map").string() + " " +
                          (f.dir / "sim" / "cloud.pcd").string() + f.scanners + " -q -o " +
                          (f.dir / "out").string() + " 2>/dev/null";
  for (auto _ : state)
    if (std::system(cmd.c_str()) != 0) state.SkipWithError("pcd-to-map failed");
  rusage ru{};
  getrusage(RUSAGE_CHILDREN, &ru);  // the largest child so far: pcd-to-map (scene-sim is smaller)
  state.counters["peak_rss_mb"] = static_cast<double>(ru.ru_maxrss) / 1024.0;
}
BENCHMARK(BM_PcdToMapEndToEnd)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
