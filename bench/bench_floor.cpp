// A whole floor end to end (issue 15, speed and memory): pcd-to-map on a simulated 12-room
// building of about 20 M points (scene-sim --rooms 12 --step-deg 0.15, the merged cloud.pcd with
// --scanner per position), load to every output, against pcl::io::loadPCDFile alone on the same
// file, in the same run. The building is simulated once, by the scene-sim binary beside this one
// (bin/, or $INDOORMAP_BIN_DIR), into a temporary directory. pcd-to-map runs as a child process, as
// a user runs it; its own peak memory (wait4's ru_maxrss) is reported as the counter peak_rss_mb.
// Results: docs/benchmarks.md ("A whole floor end to end").
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// The apps: $INDOORMAP_BIN_DIR when set (another build's bin/), else beside this binary.
fs::path bin_dir() {
  if (const char* env = std::getenv("INDOORMAP_BIN_DIR")) return env;
  return fs::read_symlink("/proc/self/exe").parent_path();
}

struct Floor {
  fs::path dir;
  std::vector<std::string> scanners;  // --scanner, X,Y,Z per position
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
    for (const auto& sc : j["scanners"]) {
      std::ostringstream s;
      s << sc["position_cloud_m"][0].get<double>() << "," << sc["position_cloud_m"][1].get<double>()
        << "," << sc["position_cloud_m"][2].get<double>();
      r.scanners.push_back("--scanner");
      r.scanners.push_back(s.str());
    }
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

// Runs argv as a child process (stdout and stderr to /dev/null) and returns its own peak
// resident memory in MB (wait4: this child alone, not scene-sim before it), or -1 on failure.
double run_child(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) ::dup2(null, 1), ::dup2(null, 2);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  rusage ru{};
  if (::wait4(pid, &status, 0, &ru) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return -1;
  return static_cast<double>(ru.ru_maxrss) / 1024.0;
}

void BM_PcdToMapEndToEnd(benchmark::State& state) {
  const Floor& f = floor12();
  std::vector<std::string> args = {(bin_dir() / "pcd-to-map").string(),
                                   (f.dir / "sim" / "cloud.pcd").string()};
  args.insert(args.end(), f.scanners.begin(), f.scanners.end());
  for (const char* a : {"-q", "-o"}) args.emplace_back(a);
  args.push_back((f.dir / "out").string());
  double peak_mb = 0;
  for (auto _ : state) {
    const double mb = run_child(args);
    if (mb < 0) state.SkipWithError("pcd-to-map failed");
    peak_mb = std::max(peak_mb, mb);
  }
  state.counters["peak_rss_mb"] = peak_mb;
}
BENCHMARK(BM_PcdToMapEndToEnd)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
