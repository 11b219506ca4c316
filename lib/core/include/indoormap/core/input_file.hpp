#pragma once
// The one input-opening check of every reader (configs, map YAMLs, scene files, JSON, images,
// clouds, CARMEN logs). Before a reader opens a path it calls check_input_file (or reads through
// read_input_file / open_input_file), so that every reader refuses the same things with the same
// messages, all InputError naming the file (exit code 2):
//   - a missing path:                     "F: no such file" (or "F: cannot open ROLE: no such
//   file")
//   - a directory:                        "F: is a directory, expected a file" (or "... ROLE")
//   - a FIFO, socket or device:           "F: is not a regular file (a FIFO, socket or device)"
//                                         (a FIFO would block open() until a writer comes)
//   - a file above max_bytes:             "F: is N bytes, above the limit of M bytes"
// A symlink to a regular file is fine (its target is checked). There is a window between the check
// and the open (the path may change in between); the readers accept it: the check is about
// honest mistakes, not an attacker racing the app.
//
// Adopting it in a new reader: call `check_input_file(path, limit, "the <role>")` before the
// open, or read the whole file with `read_input_file(path, limit, "the <role>")`.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace indoormap {

/// Size limit of a text input read whole (YAML, JSON): 256 MiB. Generous for configs, scenes and
/// truth files of 10^6 items; a larger one is a wrong file.
inline constexpr std::uint64_t kMaxTextInputBytes = std::uint64_t{256} << 20;
/// No size limit (the reader bounds its own allocations, e.g. clouds by their point budget).
inline constexpr std::uint64_t kNoSizeLimit = std::numeric_limits<std::uint64_t>::max();

/// Checks that path is an existing regular file (or a symlink to one) of at most max_bytes and
/// returns its size in bytes. role ("the config file", "the map YAML") is named in the messages.
/// Throws InputError(path, problem) as listed above.
std::uint64_t check_input_file(const std::filesystem::path& path,
                               std::uint64_t max_bytes = kMaxTextInputBytes,
                               const std::string& role = "");

/// check_input_file, then the whole file as bytes. Throws InputError on a read error.
std::string read_input_file(const std::filesystem::path& path,
                            std::uint64_t max_bytes = kMaxTextInputBytes,
                            const std::string& role = "");

/// check_input_file, then the file opened in binary mode. Throws InputError when it cannot open.
std::ifstream open_input_file(const std::filesystem::path& path,
                              std::uint64_t max_bytes = kMaxTextInputBytes,
                              const std::string& role = "");

}  // namespace indoormap
