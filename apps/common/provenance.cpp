#include "provenance.hpp"

#include <openssl/evp.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <future>
#include <map>
#include <memory>
#include <mutex>

#include "indoormap/core/errors.hpp"
#include "indoormap/version.hpp"
#include "revision.hpp"

namespace fs = std::filesystem;

namespace indoormap::app {
namespace {

struct Invocation {
  std::vector<std::string> argv;
  std::string started_utc;
};

std::string utc_now_iso8601() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

Invocation& invocation() {
  static Invocation inv{{}, utc_now_iso8601()};
  return inv;
}

/// Streams chunks into one SHA-256 digest (OpenSSL EVP; the context is freed on every path).
class Sha256 {
 public:
  Sha256() : ctx_(EVP_MD_CTX_new(), &EVP_MD_CTX_free) {
    if (!ctx_ || EVP_DigestInit_ex(ctx_.get(), EVP_sha256(), nullptr) != 1)
      throw Error("SHA-256: OpenSSL could not initialise a digest");
  }
  void update(const void* data, std::size_t n) {
    if (n > 0 && EVP_DigestUpdate(ctx_.get(), data, n) != 1)
      throw Error("SHA-256: OpenSSL digest update failed");
  }
  std::string hex() {
    std::array<unsigned char, EVP_MAX_MD_SIZE> md{};
    unsigned int len = 0;
    if (EVP_DigestFinal_ex(ctx_.get(), md.data(), &len) != 1)
      throw Error("SHA-256: OpenSSL digest final failed");
    std::string out;
    char two[3];
    for (unsigned int i = 0; i < len; ++i) {
      std::snprintf(two, sizeof two, "%02x", md[i]);
      out += two;
    }
    return out;
  }

 private:
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx_;
};

}  // namespace

void record_invocation(int argc, const char* const* argv) {
  Invocation& inv = invocation();
  inv.argv.assign(argv, argv + std::max(argc, 0));
  inv.started_utc = utc_now_iso8601();
}

const std::vector<std::string>& command_line() {
  return invocation().argv;
}
const std::string& started_utc() {
  return invocation().started_utc;
}

std::string sha256_hex(std::string_view bytes) {
  Sha256 h;
  h.update(bytes.data(), bytes.size());
  return h.hex();
}

namespace {

// Hashes file, in 1 MiB chunks; stops early (returning "") once *stop is set.
std::string sha256_file_until(const fs::path& file, const std::atomic<bool>* stop) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "cannot be opened to compute its SHA-256");
  Sha256 h;
  std::vector<char> chunk(1 << 20);
  while (in) {
    if (stop && stop->load(std::memory_order_relaxed)) return "";
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    h.update(chunk.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw InputError(file.string(), "read error while computing its SHA-256");
  return h.hex();
}

FileDigest digest_of(const fs::path& p, const std::atomic<bool>* stop) {
  return {p.string(), static_cast<std::uint64_t>(fs::file_size(p)), sha256_file_until(p, stop)};
}

// The files of the inputs: a file as itself, a directory as its regular files, sorted.
std::vector<fs::path> input_files(const std::vector<std::string>& inputs) {
  std::vector<fs::path> out;
  for (const auto& in : inputs) {
    std::error_code ec;
    if (fs::is_regular_file(in, ec)) {
      out.emplace_back(in);
    } else if (fs::is_directory(in, ec)) {
      std::vector<fs::path> files;
      for (const auto& e : fs::recursive_directory_iterator(in, ec))
        if (e.is_regular_file(ec)) files.push_back(e.path());
      std::sort(files.begin(), files.end());
      out.insert(out.end(), files.begin(), files.end());
    }
  }
  return out;
}

// Each file is hashed once per process (pcd-to-map writes a summary per storey and one on top),
// on the calling thread or ahead of time by start_digests' worker. At exit the worker is told to
// stop and joined: an app that fails early does not wait for the hash of a large cloud.
struct DigestCache {
  std::mutex mutex;
  std::map<std::string, std::shared_future<FileDigest>> files;
  std::atomic<bool> stop{false};
  std::vector<std::future<void>> workers;
  // OpenSSL frees its state at exit (atexit): initialised here, before this object is complete,
  // its clean-up is registered first and so runs after this destructor has joined the worker.
  DigestCache() { Sha256().hex(); }
  ~DigestCache() {
    stop = true;
    for (auto& w : workers) w.wait();
  }
};

DigestCache& digest_cache() {
  static DigestCache cache;
  return cache;
}

}  // namespace

std::string sha256_file(const fs::path& file) {
  return sha256_file_until(file, nullptr);
}

void start_digests(const std::vector<std::string>& inputs) {
  DigestCache& c = digest_cache();
  std::vector<std::pair<fs::path, std::promise<FileDigest>>> todo;
  {
    const std::lock_guard lock(c.mutex);
    for (const auto& f : input_files(inputs)) {
      if (c.files.count(f.string())) continue;
      std::promise<FileDigest> done;
      c.files.emplace(f.string(), done.get_future().share());
      todo.emplace_back(f, std::move(done));
    }
    if (todo.empty()) return;
    c.workers.push_back(std::async(std::launch::async, [&c, todo = std::move(todo)]() mutable {
      for (auto& [file, done] : todo) try {
          done.set_value(digest_of(file, &c.stop));
        } catch (...) {
          done.set_exception(std::current_exception());
        }
    }));
  }
}

std::vector<FileDigest> digest_inputs(const std::vector<std::string>& inputs) {
  DigestCache& c = digest_cache();
  std::vector<FileDigest> out;
  for (const auto& f : input_files(inputs)) {
    std::shared_future<FileDigest> known;
    {
      const std::lock_guard lock(c.mutex);
      if (auto it = c.files.find(f.string()); it != c.files.end()) known = it->second;
    }
    if (known.valid()) {
      out.push_back(known.get());  // rethrows the worker's InputError
      continue;
    }
    FileDigest d = digest_of(f, nullptr);
    std::promise<FileDigest> p;
    p.set_value(d);
    const std::lock_guard lock(c.mutex);
    c.files.emplace(f.string(), p.get_future().share());
    out.push_back(std::move(d));
  }
  return out;
}

nlohmann::json provenance_json(const std::vector<std::string>& inputs) {
  nlohmann::json files = nlohmann::json::array();
  for (const auto& d : digest_inputs(inputs))
    files.push_back({{"path", d.path}, {"size_bytes", d.size_bytes}, {"sha256", d.sha256}});
  return {{"command_line", command_line()},
          {"started_utc", started_utc()},
          {"version", kVersion},
          {"revision", source_revision()},
          {"inputs", files}};
}

}  // namespace indoormap::app
