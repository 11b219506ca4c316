#pragma once
// Atomic output files: everything is written to a temporary name in the target directory and
// renamed over the target only when complete, so a failure never leaves a half-written or
// clobbered file. Throws OutputError naming the path.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace indoormap {

/// Writes bytes to path atomically.
void write_file_atomic(const std::filesystem::path& path, std::string_view bytes);

/// Calls write(stream) on a temporary file, then renames it to path. If write throws, the
/// temporary file is removed and the exception propagates.
/// Test hook: when the environment variable INDOORMAP_TEST_FAIL_WRITE equals path's file name
/// (e.g. "summary.json"), the write fails as on a full disk (OutputError, temporary removed).
/// Only the tests set it (the output-set tests: a failure part-way leaves OUTDIR untouched).
void write_stream_atomic(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& write);

/// Creates dir (and parents) if needed and checks that a file can be created in it.
/// Throws OutputError otherwise. Call before long computations so they do not run in vain.
void ensure_writable_dir(const std::filesystem::path& dir);

}  // namespace indoormap
