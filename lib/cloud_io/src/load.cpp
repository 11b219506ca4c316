// Dispatch by extension / directory, merging, unit and up-axis conversion, non-finite dropping,
// and the point budget shared by every reader.
#include "indoormap/cloud_io/load.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "indoormap/core/errors.hpp"
#include "indoormap/core/input_file.hpp"
#include "las_internal.hpp"
#include "load_internal.hpp"

namespace indoormap::cloud_io {

namespace fs = std::filesystem;

namespace detail {

void check_budget(const std::string& file, std::uint64_t points, const Budget& budget) {
  if (points <= budget.remaining()) return;
  std::string msg = file + ": " + std::to_string(points) + " points exceed the point budget (" +
                    "max_points " + std::to_string(budget.max_points);
  if (budget.used > 0) msg += ", " + std::to_string(budget.used) + " already loaded";
  throw BudgetError(msg + ")");
}

void reserve_more(std::vector<Eigen::Vector3f>& out, std::uint64_t n) {
  const std::size_t need = out.size() + static_cast<std::size_t>(n);
  if (need <= out.capacity()) return;
  out.reserve(std::max(need, std::min(2 * out.capacity(), need + need / 2)));
  // The untouched rest of a large buffer: transparent huge pages where the kernel offers them
  // on request (THP "madvise" mode, Debian's default). Faulting in a 20 M-point cloud 4 KiB at a
  // time cost more than reading it (bench_floor). Advice only: nothing changes if refused.
#ifdef MADV_HUGEPAGE
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  const auto lo = reinterpret_cast<std::uintptr_t>(out.data() + out.size());
  const auto hi = reinterpret_cast<std::uintptr_t>(out.data() + out.capacity());
  const std::uintptr_t b = (lo + kHuge - 1) & ~(kHuge - 1), e = hi & ~(kHuge - 1);
  if (e > b) ::madvise(reinterpret_cast<void*>(b), e - b, MADV_HUGEPAGE);
#endif
}

Eigen::Vector3d to_output(const Eigen::Vector3d& p, const LoadOptions& options) {
  const Eigen::Vector3d m = p * options.unit_m;
  if (options.up_axis == UpAxis::kY) return {m.x(), -m.z(), m.y()};
  return m;
}

std::uint64_t checked_file_size(const std::string& file) {
  return check_input_file(file, kNoSizeLimit);
}

namespace {
std::string read_up_to(const std::string& file, std::uint64_t bytes) {
  FilePtr f(std::fopen(file.c_str(), "rb"));
  if (!f) throw InputError(file, std::string("cannot open: ") + std::strerror(errno));
  std::string buf(static_cast<std::size_t>(bytes), '\0');
  const std::size_t got = std::fread(buf.data(), 1, buf.size(), f.get());
  if (got < buf.size() && std::ferror(f.get())) throw InputError(file, "read error");
  buf.resize(got);
  return buf;
}
}  // namespace

std::string read_file_bytes(const std::string& file, std::uint64_t limit_bytes) {
  const auto size = checked_file_size(file);
  if (size > limit_bytes)
    throw BudgetError(file + ": file of " + std::to_string(size) + " bytes exceeds the limit of " +
                      std::to_string(limit_bytes) + " bytes");
  return read_up_to(file, size);
}

std::string read_file_prefix(const std::string& file, std::uint64_t max_bytes) {
  return read_up_to(file, std::min(checked_file_size(file), max_bytes));
}

}  // namespace detail

namespace {

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

constexpr const char* kSupported =
    "supported: .pcd, .ply, .xyz, .txt, .csv, .las, .3d (3DTK scan), or a 3DTK scan directory";

// Loads one input, appending to result; budget.used counts the points already in result.
void load_one(const std::string& path, const LoadOptions& options, LoadResult& result) {
  detail::Budget budget{options.max_points, 0};
  for (const auto& in : result.inputs) budget.used += in.points_read;

  std::error_code ec;
  const bool is_dir = fs::is_directory(path, ec);
  const std::string ext = lower(fs::path(path).extension().string());
  const bool file_ext = ext == ".pcd" || ext == ".ply" || ext == ".xyz" || ext == ".txt" ||
                        ext == ".csv" || ext == ".3d" || ext == ".las";

  auto& points = result.cloud.points;
  const std::size_t first = points.size();
  InputReport report;
  report.path = path;
  detail::ReadInfo info;
  if (is_dir && !file_ext) {
    report.format = "3dtk";
    info = detail::read_3dtk(path, budget, options, points);
  } else if (is_dir) {
    throw InputError(path, "is a directory, expected a file");
  } else if (ext == ".pcd") {
    report.format = "pcd";
    info = detail::read_pcd(path, budget, options, points);
  } else if (ext == ".ply") {
    report.format = "ply";
    info = detail::read_ply(path, budget, points);
  } else if (ext == ".xyz" || ext == ".txt" || ext == ".csv") {
    report.format = "xyz";
    info = detail::read_xyz(path, budget, options, points);
  } else if (ext == ".las") {
    report.format = "las";
    info = detail::read_las(path, budget, result.source_offset, points);
  } else if (ext == ".laz" || ext == ".e57") {
    detail::checked_file_size(path);
    throw InputError(path, (ext == ".laz" ? std::string("compressed LAS (LAZ) is not read: ") +
                                                detail::las_laz_hint()
                                          : std::string("E57 is not read: convert it to LAS or "
                                                        "PLY first, e.g. 'pdal translate in.e57 "
                                                        "out.las' (PDAL with E57 support) or "
                                                        "CloudCompare (save as LAS or PLY)")));
  } else if (ext == ".3d") {
    report.format = "3dtk";
    info = detail::read_3dtk(path, budget, options, points);
  } else {
    detail::checked_file_size(path);  // a missing file says so, before the extension
    throw InputError(path, "unknown file type '" + ext + "' (" + kSupported + ")");
  }

  // Convert in place and compact away non-finite points (after conversion, so that a finite
  // input that overflows float is dropped too), and take the bounds of those kept.
  // Runs of points per scanner, in raw indices; with at most one scanner, the whole file.
  const std::size_t scanner_base = result.cloud.scanners.size();
  const std::size_t one_scanner =
      info.scanners.size() == 1 ? scanner_base : detail::ReadInfo::kNoScanner;
  std::vector<PointCloud::OriginSpan> spans;
  std::size_t kept = first;
  Eigen::Vector3f lo = info.lo, hi = info.hi;
  if (info.compacted) {
    kept = points.size();
    spans.push_back({first, kept - first, one_scanner});
  } else {
    if (info.runs.empty())
      info.runs.emplace_back(points.size() - first,
                             info.scanners.size() == 1 ? 0 : detail::ReadInfo::kNoScanner);
    auto keep = [&](std::size_t i) {
      Eigen::Vector3f p = points[i];
      if (!info.output_frame)
        p = detail::to_output(points[i].cast<double>(), options).cast<float>();
      if (!p.allFinite()) return;
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
      points[kept++] = p;
    };
    std::size_t i = first;
    for (const auto& [n, scanner] : info.runs) {
      const std::size_t span_first = kept;
      for (const std::size_t end = std::min(points.size(), i + static_cast<std::size_t>(n));
           i < end; ++i)
        keep(i);
      spans.push_back({span_first, kept - span_first,
                       scanner == detail::ReadInfo::kNoScanner ? scanner : scanner_base + scanner});
    }
    for (; i < points.size(); ++i) keep(i);  // not in a run (no reader leaves any): no origin
    if (const std::size_t end = spans.back().first + spans.back().count; kept > end)
      spans.push_back({end, kept - end, detail::ReadInfo::kNoScanner});
  }
  result.lo_m = result.lo_m.cwiseMin(lo);
  result.hi_m = result.hi_m.cwiseMax(hi);
  points.resize(kept);
  auto& origins = result.cloud.origins;
  origins.insert(origins.end(), spans.begin(), spans.end());

  report.points_read = info.points;
  report.points_dropped = info.points - (kept - first);
  report.scans = info.scans;
  report.warnings = info.warnings;
  report.scanner_known = !info.scanners.empty();
  report.source_offset = info.source_offset;
  if (info.source_offset && !result.source_offset) result.source_offset = info.source_offset;
  if (kept == first) {
    if (info.points == 0) throw InputError(path, "empty cloud: no points");
    throw InputError(path, "empty cloud: all " + std::to_string(info.points) +
                               " points are non-finite (NaN / Inf)");
  }
  for (const auto& s : info.scanners)
    result.cloud.scanners.push_back(info.output_frame ? s : detail::to_output(s, options));
  result.inputs.push_back(std::move(report));
}

}  // namespace

void validate(const LoadOptions& options) {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw UsageError(std::string("invalid parameter ") + what);
  };
  require(options.unit_m > 0 && std::isfinite(options.unit_m), "input.unit_m: must be > 0");
  require(options.max_points > 0, "input.max_points: must be > 0");
}

LoadResult load_clouds(const std::vector<std::string>& paths, const LoadOptions& options) {
  validate(options);
  if (paths.empty()) throw UsageError("no input cloud given");
  LoadResult result;
  for (const auto& p : paths) load_one(p, options, result);
  if (result.source_offset && !result.source_offset->isZero())
    for (auto& in : result.inputs)
      if (!in.source_offset)
        in.warnings.push_back(in.path +
                              ": not moved to the local frame of the LAS inputs (only "
                              "LAS coordinates are moved): check that the inputs share a frame");
  return result;
}

LoadResult load_cloud(const std::string& path, const LoadOptions& options) {
  return load_clouds({path}, options);
}

}  // namespace indoormap::cloud_io
