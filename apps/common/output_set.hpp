#pragma once
// All-or-nothing output sets: every app writes its outputs through one OutputSet.
//
// The rule (said in every app's page in docs/):
//   1. The app computes everything first. Then `OutputSet set(out_dir, "<app>")` creates a fresh
//      staging directory BESIDE out_dir (`.<name>.indoormap-staging.<pid>.<n>` in out_dir's
//      parent, out_dir's symlinks resolved, so it is on the same filesystem and the moves are
//      renames), and the app writes every output into `set.dir()` (sub-folders allowed).
//   2. `set.commit()` first checks that every staged file can take its place in out_dir (no
//      directory where a file goes, no file where a folder goes); then it removes the files that
//      the same app's earlier run wrote and this run does not (the manifest, below), moves the new
//      files in (each move a rename, so a reader never sees a half-written file) and writes the
//      manifest. Files the manifest does not list (the user's own, another tool's, or an app's
//      run from before manifests) are never touched.
//   3. If anything fails before commit (a computation, a full disk while staging, a conflict
//      found by the check), out_dir is left exactly as it was and the staging directory is
//      removed (the destructor). The moves themselves are the only window: a rename failing
//      half-way through them (not seen in practice: same directory tree, checked first) is
//      reported naming the file.
// The manifest `out_dir/.indoormap-outputs` has one line per file, `<app> <relative path>`: the
// app that wrote the file last. An app replacing another app's file takes it over (map-eval
// writing eval.json into pcd-to-map's directory owns eval.json only).
//
// Adopting it in an app (the lead's recipe for new apps):
//   ensure_writable_dir(out);                  // early, before the long work (unchanged)
//   ... compute result ...
//   app::OutputSet set(out, "my-app");
//   write_my_app_outputs(set.dir(), result);   // every file, summary.json included
//   set.commit();
//
// Tests: the environment variable INDOORMAP_TEST_FAIL_WRITE=<file name> makes
// indoormap::write_stream_atomic (lib/core/atomic_file.hpp) fail on that file as on a full disk;
// it lets the tests show that a failure part-way through leaves out_dir untouched.
#include <filesystem>
#include <string>
#include <vector>

namespace indoormap::app {

/// Name of the manifest file in an output directory.
inline constexpr const char* kOutputManifest = ".indoormap-outputs";

class OutputSet {
 public:
  /// Creates out_dir if needed and a fresh staging directory beside it. Throws OutputError.
  OutputSet(const std::filesystem::path& out_dir, std::string app);
  /// Removes the staging directory and whatever it still holds (nothing after commit()).
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  /// Where the app writes its outputs.
  const std::filesystem::path& dir() const { return staging_; }
  /// Moves the staged files into out_dir as one set (rule above) and returns their relative
  /// paths, sorted. Throws OutputError (out_dir untouched when the check fails). Call once.
  std::vector<std::string> commit();

 private:
  std::filesystem::path out_, staging_;
  std::string app_;
  bool committed_ = false;
};

}  // namespace indoormap::app
