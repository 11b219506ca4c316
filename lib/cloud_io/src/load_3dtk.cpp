// 3DTK scan directories (scanNNN.3d + scanNNN.frames / scanNNN.pose) and single scan files.
// 3DTK works in centimetres in a left-handed, y-up frame; every point is first transformed by
// the scan's pose in that frame, then mapped to metres, right-handed, z up:
// X = z / 100, Y = -x / 100, Z = y / 100 (3DTK's own conversion).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/core/errors.hpp"
#include "load_internal.hpp"

namespace indoormap::cloud_io {

std::array<double, 16> tdtk_pose_to_matrix(const double translation_cm[3],
                                           const double euler_deg[3]) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  const double rx = euler_deg[0] * kDeg, ry = euler_deg[1] * kDeg, rz = euler_deg[2] * kDeg;
  const double sx = std::sin(rx), cx = std::cos(rx);
  const double sy = std::sin(ry), cy = std::cos(ry);
  const double sz = std::sin(rz), cz = std::cos(rz);
  return {cy * cz,
          sx * sy * cz + cx * sz,
          -cx * sy * cz + sx * sz,
          0.0,
          -cy * sz,
          -sx * sy * sz + cx * cz,
          cx * sy * sz + sx * cz,
          0.0,
          sy,
          -sx * cy,
          cx * cy,
          0.0,
          translation_cm[0],
          translation_cm[1],
          translation_cm[2],
          1.0};
}

namespace detail {

namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kMaxPoseFileBytes = std::uint64_t{16} << 20;

struct Scan {
  int number = 0;
  fs::path file;  // scanNNN.3d
};

// "scanNNN.3d" -> NNN; nullopt for anything else.
std::optional<int> scan_number(const std::string& name) {
  if (name.size() < 8 || !name.starts_with("scan") || !name.ends_with(".3d")) return std::nullopt;
  const std::string_view digits(name.data() + 4, name.size() - 7);
  int n = 0;
  const auto [p, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  if (ec != std::errc() || p != digits.data() + digits.size() || digits[0] == '-')
    return std::nullopt;
  return n;
}

// Parses all whitespace-separated numbers of a line; false if any token is not a number.
bool parse_numbers(std::string_view line, std::vector<double>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    std::size_t b = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i == b) break;
    if (line[b] == '+') ++b;
    double v = 0;
    const auto [p, ec] = std::from_chars(line.data() + b, line.data() + i, v);
    if (ec != std::errc() || p != line.data() + i || !std::isfinite(v)) return false;
    out.push_back(v);
  }
  return true;
}

std::vector<std::string_view> lines_of(const std::string& text) {
  std::vector<std::string_view> out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    out.emplace_back(text.data() + pos, nl - pos);
    pos = nl + 1;
  }
  return out;
}

// Poses beyond this distance from the origin are refused (1,000,000 km; 3DTK poses are in cm).
constexpr double kMaxTranslationCm = 1e11;

std::string shortest(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Refuses, naming the pose file and line, a pose that would move the scan's points beyond float
// range or onto one point or plane (an all-zero matrix): found later, on the points, it read as
// "all points are non-finite" or "all points lie at one height" without the file.
void check_pose(const std::string& file, std::size_t line, const std::array<double, 16>& m) {
  if (!std::all_of(m.begin(), m.end(), [](double v) { return std::isfinite(v); }))
    throw InputError(file, "the pose holds a value that is not finite", line);
  const double t = std::hypot(m[12], m[13], m[14]);
  if (t > kMaxTranslationCm)
    throw InputError(file,
                     "the pose's translation is " + shortest(t) +
                         " cm from the origin (the limit is 1e11 cm): not a scan position",
                     line);
  const double det = m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
                     m[8] * (m[1] * m[6] - m[5] * m[2]);
  if (!(std::abs(det) > 0.5 && std::abs(det) < 2))
    throw InputError(file,
                     "the matrix's rotation part has determinant " + shortest(det) +
                         ", expected 1 (a rotation; an all-zero matrix would put every point of "
                         "the scan at one point)",
                     line);
}

// The last non-empty line of a .frames file: 16 numbers (column-major 4x4) and a type code.
std::array<double, 16> read_frames(const std::string& file) {
  const std::string text = read_file_bytes(file, kMaxPoseFileBytes);
  const auto lines = lines_of(text);
  std::vector<double> v;
  for (std::size_t i = lines.size(); i-- > 0;) {
    if (lines[i].find_first_not_of(" \t\r") == std::string_view::npos) continue;
    if (!parse_numbers(lines[i], v) || (v.size() != 16 && v.size() != 17))
      throw InputError(file,
                       "frames line must hold 16 numbers (column-major 4x4 matrix) and a type "
                       "code",
                       i + 1);
    std::array<double, 16> m;
    std::copy_n(v.begin(), 16, m.begin());
    check_pose(file, i + 1, m);
    return m;
  }
  throw InputError(file, "frames file has no matrix line");
}

// A .pose file: line 1 translation x y z (cm), line 2 Euler angles (degrees).
std::array<double, 16> read_pose(const std::string& file) {
  const std::string text = read_file_bytes(file, kMaxPoseFileBytes);
  const auto lines = lines_of(text);
  std::vector<double> v;
  double t[3], r[3];
  for (std::size_t i = 0; i < 2; ++i) {
    if (i >= lines.size() || !parse_numbers(lines[i], v) || v.size() != 3)
      throw InputError(file,
                       i == 0 ? "pose line 1 must be the translation 'x y z' in cm"
                              : "pose line 2 must be the Euler angles 'rx ry rz' in degrees",
                       i + 1);
    std::copy_n(v.begin(), 3, i == 0 ? t : r);
  }
  const auto m = tdtk_pose_to_matrix(t, r);
  check_pose(file, std::isfinite(r[0] + r[1] + r[2]) ? 1 : 2, m);
  return m;
}

// The 3DTK frame (cm, left-handed, y up) to the output frame (m, right-handed, z up).
Eigen::Vector3d to_output(double x, double y, double z) {
  return {z / 100.0, -x / 100.0, y / 100.0};
}

void read_scan(const Scan& scan, Budget budget, const LoadOptions& options,
               std::vector<Eigen::Vector3f>& out, ReadInfo& info) {
  const std::string file = scan.file.string();
  fs::path frames = scan.file, pose = scan.file;
  frames.replace_extension(".frames");
  pose.replace_extension(".pose");
  std::optional<std::array<double, 16>> m;
  std::error_code ec;
  if (fs::exists(frames, ec))
    m = read_frames(frames.string());
  else if (fs::exists(pose, ec))
    m = read_pose(pose.string());
  else
    info.warnings.push_back(file + ": no " + pose.filename().string() + " or " +
                            frames.filename().string() +
                            " beside it: read with the identity pose (scanner at the origin)");

  budget.used += info.points;
  const std::array<double, 16> id = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const std::array<double, 16>& a = m ? *m : id;
  const std::uint64_t before = info.points;
  info.points += read_text_points(
      file, budget, false, options, [&](std::uint64_t n) { reserve_more(out, n); },
      [&](double x, double y, double z) {
        const double tx = a[0] * x + a[4] * y + a[8] * z + a[12];
        const double ty = a[1] * x + a[5] * y + a[9] * z + a[13];
        const double tz = a[2] * x + a[6] * y + a[10] * z + a[14];
        out.push_back(to_output(tx, ty, tz).cast<float>());
      });
  ++info.scans;
  if (m) {
    const Eigen::Vector3d s = to_output(a[12], a[13], a[14]);
    // Sectors of one scan position share the scanner: keep one entry per position.
    const bool dup = std::any_of(info.scanners.begin(), info.scanners.end(),
                                 [&](const Eigen::Vector3d& q) { return (q - s).norm() < 1e-3; });
    if (!dup) info.scanners.push_back(s);
    const auto it = std::find_if(info.scanners.begin(), info.scanners.end(),
                                 [&](const Eigen::Vector3d& q) { return (q - s).norm() < 1e-3; });
    info.runs.emplace_back(info.points - before,
                           static_cast<std::size_t>(it - info.scanners.begin()));
  } else {
    info.runs.emplace_back(info.points - before, ReadInfo::kNoScanner);
  }
}

}  // namespace

ReadInfo read_3dtk(const std::string& path, const Budget& budget, const LoadOptions& options,
                   std::vector<Eigen::Vector3f>& out) {
  std::vector<Scan> scans;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    for (fs::directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec)) {
      const auto n = scan_number(it->path().filename().string());
      if (!n) continue;
      if (options.scan_first >= 0 && *n < options.scan_first) continue;
      if (options.scan_last >= 0 && *n > options.scan_last) continue;
      scans.push_back({*n, it->path()});
    }
    if (ec) throw InputError(path, "cannot list the directory: " + ec.message());
    if (scans.empty()) {
      std::string msg = "no 3DTK scan files (scanNNN.3d) in this directory";
      if (options.scan_first >= 0 || options.scan_last >= 0)
        msg += " within scan numbers " + std::to_string(options.scan_first) + ".." +
               std::to_string(options.scan_last);
      throw InputError(path, msg);
    }
    std::sort(scans.begin(), scans.end(),
              [](const Scan& l, const Scan& r) { return l.number < r.number; });
  } else {
    checked_file_size(path);
    scans.push_back({0, fs::path(path)});
  }

  ReadInfo info;
  info.output_frame = true;
  for (const auto& s : scans) read_scan(s, budget, options, out, info);
  return info;
}

}  // namespace detail

}  // namespace indoormap::cloud_io
