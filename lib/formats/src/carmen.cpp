#include "indoormap/formats/carmen.hpp"

#include <zlib.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "indoormap/core/errors.hpp"
#include "indoormap/core/input_file.hpp"

namespace indoormap::formats {

namespace {
constexpr std::size_t kChunk = 1 << 16;

// The FLASER fields after the ranges: x y theta odom_x odom_y odom_theta ipc_timestamp
// ipc_hostname logger_timestamp.
constexpr std::size_t kFieldsAfterRanges = 9;

bool parse_double(std::string_view s, double& out) {
  const char* end = s.data() + s.size();
  auto [p, ec] = std::from_chars(s.data(), end, out);
  return ec == std::errc() && p == end && std::isfinite(out);
}

std::string quoted(std::string_view s) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";
  for (char c : s.substr(0, kMax)) out += (c >= 32 && c < 127) ? c : '?';
  if (s.size() > kMax) out += "...";
  return out + "'";
}
}  // namespace

void CarmenReadOptions::validate() const {
  if (!(fov_rad > 0.0 && fov_rad <= 2.0 * 3.14159265358979323846 + 1e-9))
    throw UsageError("carmen: fov_rad must be in (0, 2 pi]");
  if (!(default_max_range_m > 0.0) || !std::isfinite(default_max_range_m))
    throw UsageError("carmen: default_max_range_m must be positive");
  if (max_line_bytes < 64 || max_line_bytes > (std::size_t{1} << 28))
    throw UsageError("carmen: max_line_bytes must be in [64, 2^28]");
  if (max_beams < 1 || max_beams > 1'000'000)
    throw UsageError("carmen: max_beams must be in [1, 1000000]");
}

struct CarmenReader::File {
  gzFile gz = nullptr;
  std::size_t begin = 0, end = 0;  ///< unread bytes of the buffer
  bool eof = false;
  ~File() {
    if (gz) gzclose(gz);
  }
};

CarmenReader::CarmenReader(const std::string& path, CarmenReadOptions options)
    : path_(path), options_(options), file_(std::make_unique<File>()) {
  options_.validate();
  max_range_m_ = options_.default_max_range_m;
  check_input_file(path, kNoSizeLimit, "a CARMEN log");  // a FIFO would block gzopen
  file_->gz = gzopen(path.c_str(), "rb");
  if (!file_->gz) throw InputError(path, std::string("cannot open: ") + std::strerror(errno));
  buffer_.resize(options_.max_line_bytes + kChunk);
}

CarmenReader::~CarmenReader() = default;

void CarmenReader::fail(const std::string& problem) const {
  throw InputError(path_, problem, stats_.lines + 1);
}

// Sets line_ to the next line (without its end of line); false at the end of the file.
bool CarmenReader::read_line() {
  File& f = *file_;
  while (true) {
    const char* b = buffer_.data() + f.begin;
    if (const void* nl = std::memchr(b, '\n', f.end - f.begin)) {
      const auto len = static_cast<std::size_t>(static_cast<const char*>(nl) - b);
      if (len > options_.max_line_bytes)
        fail("line longer than " + std::to_string(options_.max_line_bytes) + " bytes");
      line_ = std::string_view(b, len);
      f.begin += len + 1;
      return true;
    }
    if (f.end - f.begin > options_.max_line_bytes)
      fail("line longer than " + std::to_string(options_.max_line_bytes) + " bytes");
    if (f.eof) {
      if (f.begin == f.end) return false;
      line_ = std::string_view(b, f.end - f.begin);  // a last line without its newline
      f.begin = f.end;
      return true;
    }
    std::memmove(buffer_.data(), b, f.end - f.begin);
    f.end -= f.begin;
    f.begin = 0;
    const int n =
        gzread(f.gz, buffer_.data() + f.end, static_cast<unsigned>(buffer_.size() - f.end));
    int err = Z_OK;
    const char* msg = gzerror(f.gz, &err);
    if (n < 0 || (err != Z_OK && err != Z_BUF_ERROR))
      fail(std::string("cannot read: ") + (msg && *msg ? msg : "zlib error"));
    if (n == 0) {
      // zlib reports a gzip member cut short as Z_BUF_ERROR at the end of the input.
      if (err == Z_BUF_ERROR) fail("the gzip stream ends early (truncated file)");
      f.eof = true;
    }
    f.end += static_cast<std::size_t>(n);
  }
}

void CarmenReader::parse_param() {
  ++stats_.params;
  if (tokens_.size() < 3) fail("PARAM needs a name and a value");
  const std::string_view name = tokens_[1];
  double* target = nullptr;
  if (name == "robot_frontlaser_offset") target = &offset_.x_m;
  if (name == "robot_frontlaser_side_offset") target = &offset_.y_m;
  if (name == "robot_frontlaser_angular_offset") target = &offset_.theta_rad;
  if (name == "robot_front_laser_max") target = &max_range_m_;
  if (!target) return;
  double v = 0.0;
  if (!parse_double(tokens_[2], v))
    fail("PARAM " + std::string(name) + ": not a number " + quoted(tokens_[2]));
  if (target == &max_range_m_ && !(v > 0.0)) fail("PARAM robot_front_laser_max must be positive");
  *target = v;
}

void CarmenReader::parse_flaser(CarmenScan& out) {
  if (tokens_.size() < 2) fail("FLASER without a beam count");
  int n = 0;
  const std::string_view count = tokens_[1];
  auto [p, ec] = std::from_chars(count.data(), count.data() + count.size(), n);
  if (ec != std::errc() || p != count.data() + count.size())
    fail("FLASER beam count is not a whole number: " + quoted(count));
  if (n < 1 || n > options_.max_beams)
    fail("FLASER beam count " + std::to_string(n) + " outside [1, " +
         std::to_string(options_.max_beams) + "]");
  const std::size_t want = 2 + static_cast<std::size_t>(n) + kFieldsAfterRanges;
  if (tokens_.size() != want)
    fail("FLASER declares " + std::to_string(n) + " beams, so " + std::to_string(want) +
         " fields, but the line has " + std::to_string(tokens_.size()) +
         (tokens_.size() < want ? " (truncated line or wrong beam count)" : " (wrong beam count)"));
  out.ranges_m.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    double r = 0.0;
    const std::string_view t = tokens_[2 + static_cast<std::size_t>(i)];
    // Stored as float: a finite double beyond float's range would become infinite.
    if (!parse_double(t, r) || r < 0.0 || r > std::numeric_limits<float>::max())
      fail("FLASER range " + std::to_string(i + 1) +
           " is not a finite non-negative number (at most 3.4e38): " + quoted(t));
    out.ranges_m[static_cast<std::size_t>(i)] = static_cast<float>(r);
  }
  double v[kFieldsAfterRanges] = {};
  static const char* const kNames[kFieldsAfterRanges] = {
      "x", "y", "theta", "odom_x", "odom_y", "odom_theta", "ipc_timestamp", "", "logger_timestamp"};
  for (std::size_t k = 0; k < kFieldsAfterRanges; ++k) {
    if (k == 7) continue;  // ipc_hostname: any word
    const std::string_view t = tokens_[2 + static_cast<std::size_t>(n) + k];
    if (!parse_double(t, v[k]))
      fail(std::string("FLASER ") + kNames[k] + " is not a finite number: " + quoted(t));
  }
  out.x_m = v[0];
  out.y_m = v[1];
  out.theta_rad = v[2];
  out.odom_x_m = v[3];
  out.odom_y_m = v[4];
  out.odom_theta_rad = v[5];
  out.ipc_timestamp_s = v[6];
  out.logger_timestamp_s = v[8];
  const double fov = options_.fov_rad;
  out.angle_increment_rad = n == 1 ? 0.0 : (n % 2 == 1 ? fov / (n - 1) : fov / n);
  out.angle_min_rad = n == 1 ? 0.0 : -fov / 2.0;
  out.max_range_m = max_range_m_;
  out.laser_offset = offset_;
  out.line = stats_.lines + 1;
}

bool CarmenReader::next(CarmenScan& out) {
  while (read_line()) {
    if (!line_.empty() && line_.back() == '\r') line_.remove_suffix(1);
    if (std::memchr(line_.data(), '\0', line_.size()))
      fail("binary data (a NUL byte) in a text log");
    tokens_.clear();
    std::size_t i = 0;
    while (i < line_.size()) {
      while (i < line_.size() && (line_[i] == ' ' || line_[i] == '\t')) ++i;
      const std::size_t s = i;
      while (i < line_.size() && line_[i] != ' ' && line_[i] != '\t') ++i;
      if (i > s) tokens_.push_back(line_.substr(s, i - s));
      if (tokens_.size() > static_cast<std::size_t>(options_.max_beams) + 64)
        fail("too many fields on one line");
    }
    bool scan = false;
    if (tokens_.empty() || tokens_[0].front() == '#')
      ++stats_.skipped;
    else if (tokens_[0] == "FLASER") {
      parse_flaser(out);
      ++stats_.scans;
      scan = true;
    } else if (tokens_[0] == "PARAM")
      parse_param();
    else
      ++stats_.skipped;
    ++stats_.lines;
    if (scan) return true;
  }
  return false;
}

CarmenStats read_carmen(const std::string& path,
                        const std::function<void(const CarmenScan&)>& on_scan,
                        const CarmenReadOptions& options) {
  CarmenReader reader(path, options);
  CarmenScan scan;
  while (reader.next(scan)) on_scan(scan);
  return reader.stats();
}

}  // namespace indoormap::formats
