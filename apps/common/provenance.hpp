#pragma once
// Provenance of a run, for summary.json's "provenance" block (docs/pipeline.md, "summary.json"):
// the command line, the UTC start time, the version with the source revision and each input
// file's size and SHA-256, so that a result can be traced back to how it was made.
//
// record_invocation() is called once per process by run_guarded (main_guard.hpp), before the
// app parses its arguments; provenance_json() reads what it recorded.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace indoormap::app {

/// Remembers argv (as given) and the current UTC time as the run's command line and start.
void record_invocation(int argc, const char* const* argv);

/// The recorded command line (empty before record_invocation) and UTC start time
/// ("2026-12-02T08:00:37Z"; the time of the first call when nothing was recorded).
const std::vector<std::string>& command_line();
const std::string& started_utc();

/// SHA-256 of bytes, as 64 lower-case hex digits (OpenSSL EVP).
std::string sha256_hex(std::string_view bytes);

/// SHA-256 of a file's contents, read in 1 MiB chunks (a cloud of many GB is never held in
/// memory). Throws InputError naming the file when it cannot be read.
std::string sha256_file(const std::filesystem::path& file);

/// One input file: its path as given, size in bytes and SHA-256.
struct FileDigest {
  std::string path;
  std::uint64_t size_bytes = 0;
  std::string sha256;
};

/// Starts hashing the inputs' files on a background thread, so that digest_inputs later takes
/// the digests instead of reading gigabytes after the run's work. Optional; safe to call again.
void start_digests(const std::vector<std::string>& inputs);

/// Digests of the inputs: a file as itself, a directory (a 3DTK scan folder) as every regular
/// file in it and its sub-folders, sorted by path. Inputs that do not exist are skipped (the app
/// has refused them before). Throws InputError when a file cannot be read.
std::vector<FileDigest> digest_inputs(const std::vector<std::string>& inputs);

/// {"command_line": [...], "started_utc": ..., "version": ..., "revision": ...,
///  "inputs": [{"path", "size_bytes", "sha256"}]}.
nlohmann::json provenance_json(const std::vector<std::string>& inputs);

}  // namespace indoormap::app
