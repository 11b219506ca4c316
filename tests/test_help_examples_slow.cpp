// Every app's --help examples run as written (issue 19): each example line of each app's --help,
// in order (later examples read earlier ones' outputs), run by /bin/sh from a scratch directory
// that mirrors the repository's shipped data (clouds/, scenes/, config/: directories copied,
// files symlinked), so that `scene-sim scenes/office.yaml -o clouds/office` replaces links in
// the mirror and never writes into the repository. Examples that need the shared data outside
// the repository (../shared/data), or the outputs of such an example, are skipped (listed),
// unless INDOORMAP_HELP_EXAMPLES_SHARED=1.
#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <vector>

#include "test_support.hpp"

namespace fs = std::filesystem;
namespace test = indoormap::test;

namespace {

// In this order: scene-sim writes the clouds pcd-to-map reads, whose maps the others read.
const std::vector<std::string> kApps = {"scene-sim",   "pcd-to-map",   "furniture-extract",
                                        "plan-route",  "grid-areas",   "map-eval",
                                        "explore-sim", "laser-to-map", "scan-features"};

struct Example {
  std::string app, command;
};

/// The example command lines of one --help text: the lines after "Examples" that start with
/// "  APP " (a trailing backslash joins the next line), each without its "# comment".
std::vector<std::string> examples_of(const std::string& app, const std::string& help) {
  std::vector<std::string> out;
  std::istringstream in(help);
  std::string line, pending;
  bool in_examples = false;
  while (std::getline(in, line)) {
    if (!pending.empty()) {
      pending += " " + line.substr(line.find_first_not_of(' '));
    } else if (line.rfind("Examples", 0) == 0) {
      in_examples = true;
      continue;
    } else if (in_examples && line.rfind("  " + app + " ", 0) == 0) {
      pending = line.substr(2);
    } else {
      if (in_examples && line.rfind("  ", 0) != 0) in_examples = false;
      continue;
    }
    if (!pending.empty() && pending.back() == '\\') {
      pending.pop_back();
      continue;
    }
    if (const auto hash = pending.find(" #"); hash != std::string::npos) pending.resize(hash);
    while (!pending.empty() && pending.back() == ' ') pending.pop_back();
    out.push_back(pending);
    pending.clear();
  }
  return out;
}

/// The -o / --out directories a command names.
std::vector<std::string> out_dirs(const std::string& command) {
  std::vector<std::string> dirs;
  std::istringstream in(command);
  std::string word, prev;
  while (in >> word) {
    if (prev == "-o" || prev == "--out") dirs.push_back(word);
    prev = word;
  }
  return dirs;
}

/// root/<sub> mirrors source/<sub>: directories made, files symlinked.
void mirror(const fs::path& source, const fs::path& root, const std::string& sub) {
  fs::create_directories(root / sub);
  for (const auto& e : fs::recursive_directory_iterator(source / sub)) {
    const fs::path rel = fs::relative(e.path(), source);
    if (e.is_directory())
      fs::create_directories(root / rel);
    else
      fs::create_symlink(e.path(), root / rel);
  }
}

/// Every regular file under dir with its modification time.
std::map<std::string, fs::file_time_type> stamps(const fs::path& dir) {
  std::map<std::string, fs::file_time_type> s;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) s[e.path().string()] = e.last_write_time();
  return s;
}

// Each app's page docs/<app>.md shows its --help examples, identical (a line continued with a
// backslash counts as one line).
TEST(HelpExamples, EveryAppPageShowsItsHelpExamples) {
  for (const auto& app : kApps) {
    const test::RunResult help = test::run_app(app, "--help");
    ASSERT_EQ(help.exit_code, 0) << app;
    std::string page = test::read_text(fs::path(INDOORMAP_SOURCE_DIR) / "docs" / (app + ".md"));
    ASSERT_FALSE(page.empty()) << "docs/" << app << ".md";
    for (std::size_t at; (at = page.find("\\\n")) != std::string::npos;)
      page.replace(at, page.find_first_not_of(' ', at + 2) - at, " ");
    for (const auto& c : examples_of(app, help.out))
      EXPECT_NE(page.find("\n" + c), std::string::npos)
          << "docs/" << app << ".md does not show the example: " << c;
  }
}

TEST(HelpExamples, EveryExampleRunsAsWrittenOnTheShippedData) {
  const fs::path source = INDOORMAP_SOURCE_DIR;
  const fs::path root = test::scratch_dir() / "repo";
  // INDOORMAP_HELP_EXAMPLES_SHARED=1 runs the shared-data examples too (minutes, not in CI):
  // ../shared/data of the mirror is a link to the data.
  const char* all_env = std::getenv("INDOORMAP_HELP_EXAMPLES_SHARED");
  const auto data = test::shared_data_dir();
  const bool with_shared = all_env && std::string(all_env) == "1" && data;
  fs::create_directories(root.parent_path() / "shared");
  if (with_shared) fs::create_directory_symlink(*data, root.parent_path() / "shared" / "data");
  for (const char* sub : {"clouds", "scenes", "config"}) mirror(source, root, sub);
  const auto before = stamps(source / "clouds");

  std::vector<Example> all;
  for (const auto& app : kApps) {
    const test::RunResult help = test::run_app(app, "--help");
    ASSERT_EQ(help.exit_code, 0) << app << " --help: " << help.err;
    const auto ex = examples_of(app, help.out);
    EXPECT_FALSE(ex.empty()) << app << " --help has no example";
    for (const auto& c : ex) all.push_back({app, c});
  }

  std::set<std::string> skipped_dirs;  // written by skipped examples: their readers skip too
  int ran = 0;
  std::string skipped;
  for (const auto& e : all) {
    bool skip = !with_shared && e.command.find("../shared/data") != std::string::npos;
    const auto own = out_dirs(e.command);
    const std::string padded = e.command + " ";
    for (const auto& d : skipped_dirs)  // reads what a skipped example wrote (not: writes there)
      if ((padded.find(" " + d + "/") != std::string::npos ||
           padded.find(" " + d + " ") != std::string::npos) &&
          std::find(own.begin(), own.end(), d) == own.end())
        skip = true;
    EXPECT_EQ(e.command.find("..."), std::string::npos) << "a placeholder: " << e.command;
    if (skip) {
      for (const auto& d : out_dirs(e.command)) skipped_dirs.insert(d);
      skipped += "\n  " + e.command;
      continue;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const std::string cmd = "cd '" + root.string() + "' && PATH='" + INDOORMAP_BIN_DIR +
                            "':\"$PATH\" timeout -k 5 120 sh -c '" + e.command + "' >run.out 2>&1";
    const int status = std::system(cmd.c_str());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
        << "exit " << (WIFEXITED(status) ? WEXITSTATUS(status) : -1) << ": " << e.command << "\n"
        << test::read_text(root / "run.out");
    std::printf("[%5.1f s] %s\n", s, e.command.c_str());
    ++ran;
  }
  std::printf("%d examples ran; skipped (shared data outside the repository):%s\n", ran,
              skipped.c_str());
  EXPECT_GE(ran, with_shared ? 30 : 15);
  // The mirror took every write: the repository's shipped clouds are untouched.
  EXPECT_EQ(stamps(source / "clouds"), before);
  EXPECT_TRUE(fs::is_symlink(root / "scenes" / "office.yaml"));
}

}  // namespace
