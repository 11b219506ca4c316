#pragma once
// Point-cloud loaders: PCD (ascii / binary / binary_compressed), PLY, plain text XYZ, LAS 1.2-1.4
// (indoormap/cloud_io/las.hpp) and 3DTK scan directories. PCL is used behind this header only;
// callers see indoormap::PointCloud. The writers of the same formats are in
// indoormap/cloud_io/write.hpp.
//
// Output frame: metres, right-handed, z up. 3DTK data (cm, left-handed, y up) is converted
// automatically (X = z/100, Y = -x/100, Z = y/100); other formats use LoadOptions::unit_m and
// LoadOptions::up_axis. LAS points are first moved to a local frame (source minus
// LoadResult::source_offset, in double precision). Non-finite points are dropped and counted.
// Formats, conventions and errors: docs/input-formats.md.
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "indoormap/core/cloud.hpp"

namespace indoormap::cloud_io {

/// Which input axis points up (for PCD / PLY / XYZ). kY means a right-handed y-up frame, mapped
/// to z-up as X = x, Y = -z, Z = y.
enum class UpAxis { kZ, kY };

struct LoadOptions {
  /// Metres per input unit for PCD / PLY / XYZ / LAS (0.01 for cm, 0.3048 for a LAS in feet);
  /// must be > 0. Not for 3DTK.
  double unit_m = 1.0;
  UpAxis up_axis = UpAxis::kZ;  ///< PCD / PLY / XYZ / LAS; 3DTK is converted automatically
  int scan_first = -1;          ///< 3DTK directory: first scan number to read (-1: from the first)
  int scan_last = -1;           ///< 3DTK directory: last scan number, inclusive (-1: to the last)
  /// Budget on the points read (NaN / Inf included) over all inputs; an input that would exceed
  /// it is refused with BudgetError before its points are allocated.
  std::uint64_t max_points = 200'000'000;
  /// Called after every few MB of a text file (XYZ, ascii PCD, 3DTK .3d) with the fraction
  /// [0, 1] of that file read; may be empty.
  std::function<void(const std::string& file, double fraction)> progress;
};

/// Throws UsageError naming the key (input.unit_m, input.max_points) for an option out of range.
void validate(const LoadOptions& options);

struct InputReport {
  std::string path;
  std::string format;                ///< "pcd", "ply", "xyz", "las", "3dtk"
  std::uint64_t points_read = 0;     ///< points in the file(s), including dropped ones
  std::uint64_t points_dropped = 0;  ///< NaN / Inf points dropped
  int scans = 0;                     ///< 3DTK: number of scan files read
  /// A scanner position came from the input (PCD VIEWPOINT line, 3DTK .frames / .pose).
  bool scanner_known = false;
  /// Doubts about the input that did not stop the load (e.g. a 3DTK scan without its pose file,
  /// read with the identity pose), each naming its file. The apps print them as warnings.
  std::vector<std::string> warnings;
  /// LAS: the offset subtracted from every coordinate (source units, before unit_m and
  /// up_axis): input frame = (source - offset) converted as for every input. Unset: not moved.
  std::optional<Eigen::Vector3d> source_offset;
};

struct LoadResult {
  /// Merged points, in input order, and scanner positions (one per PCD with a VIEWPOINT line,
  /// one per distinct 3DTK scan position: sectors within 1 mm of each other count once).
  PointCloud cloud;
  std::vector<InputReport> inputs;
  /// The local-frame offset of the LAS inputs (chosen by the first, shared by every later LAS
  /// input; other formats are not moved). Unset when no LAS input was read.
  std::optional<Eigen::Vector3d> source_offset;
  /// Bounds of the merged points (all finite, output frame), taken while loading; lo_m > hi_m
  /// only when there are no points.
  Eigen::Vector3f lo_m = Eigen::Vector3f::Constant(INFINITY), hi_m = -lo_m;
};

/// Loads and merges every input. Throws InputError (names file and line) on bad input (missing,
/// unreadable, unknown type, malformed, empty or all non-finite), BudgetError when the total
/// point count would exceed options.max_points, UsageError for bad options or no paths.
LoadResult load_clouds(const std::vector<std::string>& paths, const LoadOptions& options = {});

/// Loads one input: a file (by extension, case-insensitive: .pcd, .ply, .xyz / .txt / .csv, .las,
/// .3d) or a 3DTK scan directory. .laz and .e57 are refused with a conversion hint.
LoadResult load_cloud(const std::string& path, const LoadOptions& options = {});

/// The parsed header of a PCD file, validated by us before PCL sees the file (Debian's PCL 1.13
/// crashes on several malformed headers).
struct PcdHeader {
  std::vector<std::string> fields;
  std::vector<int> sizes;
  std::vector<char> types;
  std::vector<int> counts;
  std::uint64_t width = 0;
  std::uint64_t height = 0;
  std::uint64_t points = 0;
  bool has_viewpoint = false;                   ///< a VIEWPOINT line was present
  double viewpoint[7] = {0, 0, 0, 1, 0, 0, 0};  ///< tx ty tz qw qx qy qz
  std::string data;                             ///< "ascii", "binary", "binary_compressed"
  std::uint64_t data_offset = 0;                ///< byte offset of the data section
  std::uint64_t point_size = 0;                 ///< bytes per point in binary data
};

/// Parses and validates a PCD header from the file's bytes. Throws InputError naming the file
/// and the header line on any inconsistency (missing FIELDS, x/y/z absent, WIDTH*HEIGHT !=
/// POINTS, POINTS == 0, data section too short for POINTS, ...), and BudgetError naming the
/// file when POINTS exceeds max_points.
PcdHeader read_pcd_header(const std::string& bytes, const std::string& file,
                          std::uint64_t max_points);

/// The same, from the first bytes of a file (`head`, at least the header plus 8 bytes) and the
/// file's total size, so that large files need not be read twice.
PcdHeader read_pcd_header(std::string_view head, std::uint64_t file_size, const std::string& file,
                          std::uint64_t max_points);

/// The 3DTK pose convention (EulerToMatrix4): translation in cm and Euler angles in degrees to a
/// column-major 4x4 matrix in 3DTK's own (left-handed, y-up, cm) frame.
std::array<double, 16> tdtk_pose_to_matrix(const double translation_cm[3],
                                           const double euler_deg[3]);

}  // namespace indoormap::cloud_io
