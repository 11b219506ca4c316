#include "fuzz_target.hpp"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <new>
#include <stdexcept>
#include <typeinfo>

#include "indoormap/core/errors.hpp"

namespace indoormap::fuzz {

namespace fs = std::filesystem;

namespace {
// Where fresh_dir() lives, for the clean-up at exit.
fs::path& fresh_dir_path() {
  static fs::path p;
  return p;
}

std::vector<Target>& registry() {
  static std::vector<Target> r;
  return r;
}
}  // namespace

bool register_target(const char* name, TargetFn fn) {
  registry().push_back({name, fn});
  return true;
}

const std::vector<Target>& targets() {
  return registry();
}

const Target* find_target(std::string_view name) {
  for (const auto& t : registry())
    if (name == t.name) return &t;
  return nullptr;
}

std::optional<std::string> run_one(const Target& target, std::string_view bytes) {
  try {
    target.fn(bytes);
  } catch (const InputError& e) {
    if (e.file().empty()) return std::string("InputError without a file name: ") + e.what();
    if (std::string_view(e.what()).empty()) return std::string("InputError with an empty message");
  } catch (const Error& e) {
    if (std::string_view(e.what()).empty())
      return std::string("indoormap::Error with an empty message");
  } catch (const std::bad_alloc&) {
    return std::string(
        "std::bad_alloc escaped (an allocation sized from the input was not checked)");
  } catch (const std::exception& e) {
    return std::string("untyped exception escaped (") + typeid(e).name() + "): " + e.what();
  } catch (...) {
    return std::string("unknown exception escaped");
  }
  return std::nullopt;
}

fs::path fresh_dir() {
  static const fs::path dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    fs::path d =
        fs::path(tmp && *tmp ? tmp : "/tmp") / ("indoormap-fuzz-" + std::to_string(::getpid()));
    fresh_dir_path() = d;  // constructed before the handler is registered, so still alive in it
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(fresh_dir_path(), ec);
    });
    return d;
  }();
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  return dir;
}

fs::path write_file(const fs::path& dir, const std::string& name, std::string_view bytes) {
  const fs::path p = dir / name;
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("fuzz harness: cannot write " + p.string());
  return p;
}

std::vector<std::string_view> split_parts(std::string_view bytes, std::size_t max_parts) {
  std::vector<std::string_view> parts;
  while (parts.size() + 1 < max_parts) {
    const auto at = bytes.find(kPartSeparator);
    if (at == std::string_view::npos) break;
    parts.push_back(bytes.substr(0, at));
    bytes.remove_prefix(at + kPartSeparator.size());
  }
  parts.push_back(bytes);
  return parts;
}

}  // namespace indoormap::fuzz
