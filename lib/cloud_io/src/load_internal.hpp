#pragma once
// Private to im_cloud_io: the per-format readers behind load_clouds. No PCL here.
//
// Every reader appends raw points to `out` (input units and axes, except 3DTK which converts to
// the output frame itself), including non-finite ones; load.cpp converts, drops and counts. A
// reader may do that itself on the way (ReadInfo::compacted: the binary PCD reader).
// Readers check every size against the file size and the budget before allocating.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "indoormap/cloud_io/load.hpp"

namespace indoormap::cloud_io::detail {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
/// A C stream closed when it goes out of scope (null when fopen failed).
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

/// The point budget of the current file: how many points load_clouds may still accept.
struct Budget {
  std::uint64_t max_points = 0;  ///< LoadOptions::max_points
  std::uint64_t used = 0;        ///< points already loaded from earlier files
  std::uint64_t remaining() const { return used >= max_points ? 0 : max_points - used; }
};

/// Throws BudgetError naming the file when `points` more points would not fit.
void check_budget(const std::string& file, std::uint64_t points, const Budget& budget);

struct ReadInfo {
  std::uint64_t points = 0;  ///< points appended to out, including non-finite ones
  /// Scanner positions, in the same frame as the appended points.
  std::vector<Eigen::Vector3d> scanners;
  int scans = 0;              ///< 3DTK: scan files read
  bool output_frame = false;  ///< true: points and scanners are already metres, z up
  /// true: the points are already converted (metres, z up) and all finite, and lo / hi are their
  /// bounds; runs must be empty. Spares load.cpp its own pass over millions of points.
  bool compacted = false;
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(INFINITY), hi = -lo;
  std::vector<std::string> warnings;  ///< InputReport::warnings
  /// Which scanner saw which points (3DTK: one run per scan file): consecutive runs of appended
  /// points (raw, non-finite included) with the index of their scanner in `scanners`, or
  /// kNoScanner. Empty: a file with at most one scanner (all its points are that scanner's).
  static constexpr std::size_t kNoScanner = static_cast<std::size_t>(-1);
  std::vector<std::pair<std::uint64_t, std::size_t>> runs;
  /// LAS: the offset subtracted from every point (source units; InputReport::source_offset).
  std::optional<Eigen::Vector3d> source_offset;
};

/// Input units and axes to the output frame (metres, right-handed, z up).
Eigen::Vector3d to_output(const Eigen::Vector3d& p, const LoadOptions& options);

/// Makes room for `n` more points, growing geometrically so that merging many files stays
/// linear; `n` must already be checked against the budget.
void reserve_more(std::vector<Eigen::Vector3f>& out, std::uint64_t n);

/// The words of a line (PCD and PLY headers, ascii PCD data), split at spaces and tabs; empty
/// words are skipped. Inline: the ascii PCD reader calls it once per data line.
inline std::vector<std::string_view> split_ws(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    const std::size_t b = i;
    while (i < s.size() && s[i] != ' ' && s[i] != '\t') ++i;
    if (i > b) out.push_back(s.substr(b, i - b));
  }
  return out;
}

/// Size of a regular, readable file; throws InputError (missing, directory, unreadable).
std::uint64_t checked_file_size(const std::string& file);

/// Reads the whole file after checking its size against `limit_bytes`.
std::string read_file_bytes(const std::string& file, std::uint64_t limit_bytes);

/// Reads at most `max_bytes` from the start of the file.
std::string read_file_prefix(const std::string& file, std::uint64_t max_bytes);

ReadInfo read_pcd(const std::string& file, const Budget& budget, const LoadOptions& options,
                  std::vector<Eigen::Vector3f>& out);
ReadInfo read_ply(const std::string& file, const Budget& budget, std::vector<Eigen::Vector3f>& out);
ReadInfo read_xyz(const std::string& file, const Budget& budget, const LoadOptions& options,
                  std::vector<Eigen::Vector3f>& out);
/// A scan directory or a single scanNNN.3d file.
ReadInfo read_3dtk(const std::string& path, const Budget& budget, const LoadOptions& options,
                   std::vector<Eigen::Vector3f>& out);

/// A LAS file (.las): points in the local frame (source minus offset, source units). The offset
/// is shared_offset when given (an earlier LAS input chose it), else choose_las_offset's.
ReadInfo read_las(const std::string& file, const Budget& budget,
                  const std::optional<Eigen::Vector3d>& shared_offset,
                  std::vector<Eigen::Vector3f>& out);

/// Text point parser shared by XYZ and 3DTK: x y z first on each line, whitespace or comma
/// separated, further columns ignored; empty lines and lines starting with '#' or '//'
/// skipped; CRLF tolerated. `allow_header`: a first data line that does not start with a
/// number is taken as a column header (CSV). Reads the file in fixed-size chunks, so memory
/// stays bounded whatever the file size; calls options.progress per chunk. Calls `reserve`
/// once with an estimate of the point count (bounded by file size and budget), then `sink` per
/// point (NaN / Inf included) after checking the budget; returns the number of points.
std::uint64_t read_text_points(const std::string& file, const Budget& budget, bool allow_header,
                               const LoadOptions& options,
                               const std::function<void(std::uint64_t)>& reserve,
                               const std::function<void(double, double, double)>& sink);

/// Calls on_line(begin, end, line) for every line of the file from byte `offset` on (without
/// the '\n'; the last line may lack one), numbering lines from `first_line`. Reads in fixed-size
/// chunks (memory bounded whatever the file size; lines over 1 MiB are refused), calls
/// after_chunk(bytes consumed so far) and options.progress after each chunk.
using LineFn = std::function<void(const char* begin, const char* end, std::size_t line)>;
void for_each_line(const std::string& file, std::uint64_t offset, std::size_t first_line,
                   const LoadOptions& options, const LineFn& on_line,
                   const std::function<void(std::uint64_t)>& after_chunk = {});

/// An upper bound of the points a text file of `bytes` bytes can hold ("0 0 0\n" per point),
/// used to reserve memory without trusting the file.
std::uint64_t text_points_upper_bound(std::uint64_t bytes);

}  // namespace indoormap::cloud_io::detail
