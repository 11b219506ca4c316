#include "indoormap/core/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <iterator>
#include <system_error>

#include "indoormap/core/errors.hpp"

namespace indoormap {

namespace fs = std::filesystem;

std::uint64_t check_input_file(const fs::path& path, std::uint64_t max_bytes,
                               const std::string& role) {
  const std::string file = path.string();
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);  // follows symlinks: the target counts
  if (ec || !fs::exists(st)) {
    if (fs::is_symlink(fs::symlink_status(path, ec)))
      throw InputError(file, "is a dangling symlink (its target does not exist)");
    throw InputError(file,
                     role.empty() ? "no such file" : "cannot open " + role + ": no such file");
  }
  if (fs::is_directory(st))
    throw InputError(file, "is a directory, expected " + (role.empty() ? "a file" : role));
  if (!fs::is_regular_file(st))
    throw InputError(file, "is not a regular file (a FIFO, socket or device)" +
                               (role.empty() ? std::string() : ", expected " + role));
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) throw InputError(file, "cannot read the file size: " + ec.message());
  if (size > max_bytes)
    throw InputError(file, "is " + std::to_string(size) + " bytes, above the limit of " +
                               std::to_string(max_bytes) + " bytes" +
                               (role.empty() ? std::string() : " for " + role));
  return size;
}

std::ifstream open_input_file(const fs::path& path, std::uint64_t max_bytes,
                              const std::string& role) {
  check_input_file(path, max_bytes, role);
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path.string(),
                     (role.empty() ? std::string("cannot open: ") : "cannot open " + role + ": ") +
                         std::strerror(errno));
  return in;
}

std::string read_input_file(const fs::path& path, std::uint64_t max_bytes,
                            const std::string& role) {
  const std::uint64_t size = check_input_file(path, max_bytes, role);
  std::ifstream in = open_input_file(path, max_bytes, role);
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(size));
  bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path.string(), "read error");
  return bytes;
}

}  // namespace indoormap
