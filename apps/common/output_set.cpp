#include "output_set.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <system_error>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::app {

namespace fs = std::filesystem;

namespace {

// file -> app, from out/.indoormap-outputs (missing or unreadable: empty, nothing to remove).
std::map<std::string, std::string> read_manifest(const fs::path& out) {
  std::map<std::string, std::string> owner;
  std::error_code ec;
  const fs::path p = out / kOutputManifest;
  if (!fs::is_regular_file(p, ec)) return owner;
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line)) {
    const auto sp = line.find(' ');
    if (sp == std::string::npos || sp == 0 || sp + 1 >= line.size()) continue;
    const std::string file = line.substr(sp + 1);
    // Only plain relative paths inside out (a hand-edited manifest cannot reach outside).
    const fs::path rel = fs::path(file).lexically_normal();
    if (rel.is_absolute() || rel.empty() || *rel.begin() == "..") continue;
    owner[rel.generic_string()] = line.substr(0, sp);
  }
  return owner;
}

std::vector<std::string> staged_files(const fs::path& staging) {
  std::vector<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(staging))
    if (e.is_regular_file()) files.push_back(e.path().lexically_relative(staging).generic_string());
  std::sort(files.begin(), files.end());
  return files;
}

// Throws OutputError, before anything is moved, when a staged file cannot take its place.
void check_places(const fs::path& out, const std::vector<std::string>& files) {
  for (const auto& f : files) {
    const fs::path target = out / f;
    std::error_code ec;
    for (fs::path p = fs::path(f).parent_path(); !p.empty(); p = p.parent_path()) {
      const auto st = fs::symlink_status(out / p, ec);
      if (fs::exists(st) && !fs::is_directory(fs::status(out / p, ec)))
        throw OutputError((out / p).string(), "exists and is not a directory (it should hold " + f +
                                                  "); nothing was written");
    }
    if (fs::is_directory(fs::symlink_status(target, ec)))
      throw OutputError(target.string(), "is a directory; nothing was written");
  }
}

// Removes file and then its parent folders inside out while they are empty.
void remove_with_empty_parents(const fs::path& out, const std::string& file) {
  std::error_code ec;
  fs::remove(out / file, ec);
  for (fs::path p = fs::path(file).parent_path(); !p.empty(); p = p.parent_path())
    if (!fs::remove(out / p, ec)) break;  // not empty (or not there): stop
}

}  // namespace

OutputSet::OutputSet(const fs::path& out_dir, std::string app)
    : out_(out_dir), app_(std::move(app)) {
  ensure_writable_dir(out_);
  static std::atomic<unsigned> counter{0};
  std::error_code ec;
  fs::path real = fs::weakly_canonical(fs::absolute(out_), ec);
  if (ec) real = fs::absolute(out_).lexically_normal();
  std::string name(1, '.');  // appended piecewise: "." + string trips gcc 12's -Wrestrict
  name += real.filename().string();
  name += ".indoormap-staging." + std::to_string(::getpid()) + "." + std::to_string(counter++);
  // Beside out_dir; inside it only for a root directory, which has no parent.
  staging_ = real.has_filename() && real.has_parent_path() && real.parent_path() != real
                 ? real.parent_path() / name
                 : real / name;
  fs::remove_all(staging_, ec);
  if (!fs::create_directory(staging_, ec) || ec)
    throw OutputError(staging_.string(), "cannot create the staging directory: " + ec.message());
}

OutputSet::~OutputSet() {
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

std::vector<std::string> OutputSet::commit() {
  if (committed_) throw Error("OutputSet::commit called twice");
  const std::vector<std::string> files = staged_files(staging_);
  check_places(out_, files);
  std::map<std::string, std::string> owner = read_manifest(out_);
  const std::set<std::string> now(files.begin(), files.end());
  for (auto it = owner.begin(); it != owner.end();) {
    if (it->second == app_ && !now.count(it->first)) {
      remove_with_empty_parents(out_, it->first);
      it = owner.erase(it);
    } else {
      ++it;
    }
  }
  for (const auto& f : files) {
    std::error_code ec;
    const fs::path target = out_ / f;
    if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
    fs::rename(staging_ / f, target, ec);
    if (ec) throw OutputError(target.string(), ec.message());
    owner[f] = app_;
  }
  std::ostringstream m;
  for (const auto& [file, app] : owner) m << app << ' ' << file << '\n';
  write_file_atomic(out_ / kOutputManifest, m.str());
  committed_ = true;
  return files;
}

}  // namespace indoormap::app
