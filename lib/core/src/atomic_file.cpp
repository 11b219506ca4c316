#include "indoormap/core/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

#include "indoormap/core/errors.hpp"

namespace indoormap {

namespace fs = std::filesystem;

namespace {

fs::path temp_name_for(const fs::path& path) {
  static std::atomic<unsigned> counter{0};
  // Appended piece by piece: gcc 12 warns falsely (-Wrestrict) on "." + std::string.
  std::string name = ".";
  name += path.filename().string();
  name += ".tmp.";
  name += std::to_string(::getpid());
  name += '.';
  name += std::to_string(counter++);
  return path.parent_path() / name;
}

}  // namespace

void write_stream_atomic(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  const fs::path tmp = temp_name_for(path);
  try {
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) throw OutputError(path.string(), std::strerror(errno));
      write(out);
      out.flush();
      if (!out) throw OutputError(path.string(), "write failed (disk full?)");
      // Test hook (documented in atomic_file.hpp): a full disk on the named file.
      if (const char* fail = std::getenv("INDOORMAP_TEST_FAIL_WRITE");
          fail && *fail && path.filename() == fail)
        throw OutputError(path.string(),
                          "write failed: No space left on device (INDOORMAP_TEST_FAIL_WRITE)");
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) throw OutputError(path.string(), ec.message());
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
}

void write_file_atomic(const fs::path& path, std::string_view bytes) {
  write_stream_atomic(path, [&](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

void ensure_writable_dir(const fs::path& dir) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw OutputError(dir.string(), "exists and is not a directory");
  // fs::exists follows links: a dangling link would reach create_directories, whose error is a
  // bare "File exists".
  if (fs::is_symlink(fs::symlink_status(dir, ec)) && !fs::exists(dir, ec))
    throw OutputError(dir.string(), "is a symbolic link to '" + fs::read_symlink(dir, ec).string() +
                                        "', which does not exist (a dangling link): create its "
                                        "target or give another output directory");
  fs::create_directories(dir, ec);
  if (ec) throw OutputError(dir.string(), ec.message());
  const fs::path probe = temp_name_for(dir / "probe");
  {
    std::ofstream out(probe, std::ios::binary);
    if (!out)
      throw OutputError(dir.string(),
                        std::string("directory is not writable: ") + std::strerror(errno));
  }
  fs::remove(probe, ec);
}

}  // namespace indoormap
