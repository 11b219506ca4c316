#pragma once
// Shared helpers for the test suite: where the real data lives, scratch directories, running apps.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <string>

namespace indoormap::test {

/// ../shared/data next to the source tree, or $INDOORMAP_DATA when set; nullopt when absent.
inline std::optional<std::filesystem::path> shared_data_dir() {
  if (const char* env = std::getenv("INDOORMAP_DATA"); env && *env) {
    if (std::filesystem::is_directory(env)) return std::filesystem::path(env);
    return std::nullopt;
  }
  auto p = std::filesystem::path(INDOORMAP_SOURCE_DIR) / ".." / "shared" / "data";
  if (std::filesystem::is_directory(p)) return std::filesystem::canonical(p);
  return std::nullopt;
}

/// The Jacobs scan folder, or skips the current test with a clear message.
#define INDOORMAP_REQUIRE_DATA(var, sub)                                                    \
  auto var##_root = ::indoormap::test::shared_data_dir();                                   \
  if (!var##_root || !std::filesystem::exists(*var##_root / (sub)))                         \
    GTEST_SKIP() << "real data '" << (sub) << "' not found: set INDOORMAP_DATA or provide " \
                 << "../shared/data next to the source tree";                               \
  const std::filesystem::path var = *var##_root / (sub)

/// A fresh, empty scratch directory unique to the running test.
inline std::filesystem::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(info->test_suite_name()) + "_" + info->name();
  for (auto& ch : name)
    if (ch == '/') ch = '_';
  auto dir = std::filesystem::temp_directory_path() / "indoormap-tests" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

/// s with every occurrence of from replaced by to (left to right, not re-scanned).
inline std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size())
    s.replace(at, from.size(), to);
  return s;
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct RunResult {
  int exit_code = -1;
  std::string err;  ///< stderr
  std::string out;  ///< stdout
};

/// Runs an app from the build's bin directory with a shell-quoted argument string. env: shell
/// variable assignments put before the command ("A=1 B=2"); timeout_s > 0: the app is killed
/// after that many seconds (coreutils timeout; exit code 124), so a hang fails the test.
inline RunResult run_app(const std::string& app, const std::string& args,
                         const std::string& env = "", int timeout_s = 0) {
  static int counter = 0;
  auto dir = std::filesystem::temp_directory_path() / "indoormap-tests" / "runs";
  std::filesystem::create_directories(dir);
  auto tag = std::to_string(::getpid()) + "_" + std::to_string(counter++);
  auto out = dir / ("out_" + tag), err = dir / ("err_" + tag);
  std::string cmd = env + (env.empty() ? "" : " ") +
                    (timeout_s > 0 ? "timeout -k 5 " + std::to_string(timeout_s) + " " : "") +
                    std::string(INDOORMAP_BIN_DIR) + "/" + app + " " + args + " >" + out.string() +
                    " 2>" + err.string() + " </dev/null";
  int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

}  // namespace indoormap::test
