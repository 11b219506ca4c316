#pragma once
// LAS 1.2-1.4 (ASPRS), reader and writer side by side, by hand: Debian packages no LAS library.
// load_cloud reads .las files through read_las_header and the point reader behind it (point data
// formats 0-10; x, y, z only; extra bytes per record skipped). LAZ (compressed) is refused with a
// conversion hint. Format, local frame and errors: docs/input-formats.md ("LAS").
//
// Local frame: georeferenced clouds sit at ~500,000 / 5,000,000 m, where a float keeps only
// ~0.5 m. The loader subtracts an offset from every coordinate in double precision before the
// conversion to float (choose_las_offset): points in the map's input frame are
// source - offset (LoadResult::source_offset).
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace indoormap::cloud_io {

/// Minimum record size of each point data format 0-10 (LAS 1.4 R15, table "Point Data Record
/// Format n"). Records may be longer (extra bytes), never shorter.
inline constexpr std::array<std::uint16_t, 11> kLasRecordBytes = {20, 28, 26, 34, 57, 63,
                                                                  30, 36, 38, 59, 67};

/// The fields of a LAS public header block that the reader uses, validated.
struct LasHeader {
  int version_minor = 2;            ///< 2, 3 or 4 (major is always 1)
  std::uint16_t header_bytes = 0;   ///< header size field (>= 227 / 235 / 375 by version)
  std::uint32_t point_offset = 0;   ///< offset to point data, bytes from the start
  std::uint32_t vlr_count = 0;      ///< variable length records, all inside the header area
  int point_format = 0;             ///< 0-10
  std::uint16_t record_bytes = 0;   ///< point record length (>= kLasRecordBytes[format])
  std::uint64_t points = 0;         ///< legacy count, or the 1.4 64-bit count
  Eigen::Vector3d scale{1, 1, 1};   ///< coordinate = integer * scale + offset
  Eigen::Vector3d offset{0, 0, 0};  ///< the header's offset fields (source frame)
  Eigen::Vector3d min{0, 0, 0};     ///< the header's bounding box (not trusted: may lie)
  Eigen::Vector3d max{0, 0, 0};
};

/// Parses and validates a LAS header from the file's first bytes (`head`: at least the header
/// block, up to 375 bytes) and the file's total size. Throws InputError naming the file and the
/// problem: not LASF, version outside 1.2-1.4, header size below the version's block, point
/// offset before the header's end or past the end of the file, compressed (LAZ) or unknown
/// point format, record length below the format's minimum, legacy and 64-bit counts that
/// disagree, point data running past the end of the file, scale zero or non-finite, offset
/// non-finite. The VLRs are checked by the loader (they need more bytes than the header).
LasHeader read_las_header(std::string_view head, std::uint64_t file_size, const std::string& file);

/// The local-frame offset for a LAS file (source units), chosen per axis:
///  - the header's offset field, when the header's bounding box lies within 10 km of it (a float
///    keeps better than 1 mm there; exact for the integers: local = integer * scale);
///  - else the bounding box minimum rounded down to a multiple of 100 m;
///  - `first` (the first point, source frame) rounded down to 100 m when the box is not finite
///    or inverted (the box is not trusted).
Eigen::Vector3d choose_las_offset(const LasHeader& header, const Eigen::Vector3d& first);

struct LasWriteOptions {
  int version_minor = 2;          ///< 2, 3 or 4
  int point_format = 0;           ///< 0-10 (6-10 need version 1.4)
  std::uint16_t extra_bytes = 0;  ///< zero bytes appended to every record (skipped by readers)
  /// Added to every point in double precision before quantising: source = point + origin_m.
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d scale{0.001, 0.001, 0.001};        ///< metres per integer unit, > 0
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  ///< the header's offset fields
  /// Version 1.4: also fill the legacy 32-bit count (formats 0-5 and < 2^32 points), as the
  /// standard asks; false leaves it 0 so that only the 64-bit count holds the number.
  bool legacy_count = true;
};

/// Writes points as an uncompressed LAS file (no VLRs; every point a single return), atomically.
/// Throws UsageError for options out of range, OutputError when a coordinate does not fit the
/// int32 of its format at this scale and offset, or on write failure.
void write_las(const std::string& path, const std::vector<Eigen::Vector3f>& points,
               const LasWriteOptions& options = {});

}  // namespace indoormap::cloud_io
