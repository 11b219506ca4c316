// Plain text points (.xyz / .txt / .csv) and the line parser shared with the 3DTK reader.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "indoormap/core/errors.hpp"
#include "load_internal.hpp"

namespace indoormap::cloud_io::detail {

namespace {

constexpr std::size_t kChunkBytes = std::size_t{4} << 20;  // progress granularity, too
constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// Parses one number at p (from_chars has no leading '+'), requiring it to end at a separator
// or the end of the line. Returns the position after it, or nullptr.
const char* parse_number(const char* p, const char* e, double& v) {
  if (p < e && *p == '+') ++p;
  const auto [end, ec] = std::from_chars(p, e, v, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) {
    // Beyond double's range: strtod gives the IEEE answer (+-HUGE_VAL, dropped later as
    // non-finite, or a denormal / zero).
    v = std::strtod(std::string(p, end).c_str(), nullptr);
  } else if (ec != std::errc()) {
    return nullptr;
  }
  if (end < e && !is_space(*end) && *end != ',') return nullptr;
  return end;
}

enum class LineKind { kSkip, kPoint, kBad };

LineKind parse_line(const char* p, const char* e, double xyz[3]) {
  while (e > p && is_space(e[-1])) --e;
  while (p < e && is_space(*p)) ++p;
  if (p == e || *p == '#' || (e - p >= 2 && p[0] == '/' && p[1] == '/')) return LineKind::kSkip;
  for (int k = 0; k < 3; ++k) {
    if (k > 0) {
      const char* start = p;
      while (p < e && is_space(*p)) ++p;
      if (p < e && *p == ',') ++p;
      while (p < e && is_space(*p)) ++p;
      if (p == start) return LineKind::kBad;
    }
    p = parse_number(p, e, xyz[k]);
    if (!p) return LineKind::kBad;
  }
  return LineKind::kPoint;
}

std::string snippet(const char* p, const char* e) {
  while (e > p && (e[-1] == '\r' || e[-1] == '\n')) --e;
  std::string s(p, static_cast<std::size_t>(std::min<std::ptrdiff_t>(e - p, 60)));
  if (e - p > 60) s += "...";
  return s;
}

}  // namespace

void for_each_line(const std::string& file, std::uint64_t offset, std::size_t first_line,
                   const LoadOptions& options, const LineFn& on_line,
                   const std::function<void(std::uint64_t)>& after_chunk) {
  const std::uint64_t size = checked_file_size(file);
  FilePtr f(std::fopen(file.c_str(), "rb"));
  if (!f) throw InputError(file, std::string("cannot open: ") + std::strerror(errno));
  if (offset > 0 && std::fseek(f.get(), static_cast<long>(offset), SEEK_SET) != 0)
    throw InputError(file, "cannot seek to byte " + std::to_string(offset));

  // A small file gets a small buffer (many small files stay cheap); the end of the file is
  // where a read comes back short.
  const std::size_t chunk = static_cast<std::size_t>(
      std::min<std::uint64_t>(kChunkBytes, (size > offset ? size - offset : 0) + 1));
  std::string buf;
  buf.reserve(chunk);
  std::size_t line = first_line - 1;
  std::uint64_t consumed = offset;
  bool eof = false;
  while (!eof) {
    const std::size_t carry = buf.size();
    buf.resize(carry + chunk);
    const std::size_t got = std::fread(buf.data() + carry, 1, chunk, f.get());
    if (got < chunk && std::ferror(f.get())) throw InputError(file, "read error", line + 1);
    eof = got < chunk;
    buf.resize(carry + got);

    const char* data = buf.data();
    const char* end = data + buf.size();
    const char* p = data;
    // Every line is held to the limit, not only one that crosses a chunk boundary.
    auto check_length = [&](const char* b, const char* e) {
      if (static_cast<std::size_t>(e - b) > kMaxLineBytes)
        throw InputError(file, "line longer than 1 MiB", line);
    };
    while (const char* nl = static_cast<const char*>(std::memchr(p, '\n', end - p))) {
      ++line;
      check_length(p, nl);
      on_line(p, nl, line);
      p = nl + 1;
    }
    if (eof && p < end) {
      ++line;
      check_length(p, end);
      on_line(p, end, line);
      p = end;
    }
    consumed += static_cast<std::uint64_t>(p - data);
    if (after_chunk) after_chunk(consumed);
    buf.erase(0, static_cast<std::size_t>(p - data));
    if (buf.size() > kMaxLineBytes) throw InputError(file, "line longer than 1 MiB", line + 1);
    if (options.progress && size > 0)
      options.progress(file,
                       std::min(1.0, static_cast<double>(consumed) / static_cast<double>(size)));
  }
}

std::uint64_t read_text_points(const std::string& file, const Budget& budget, bool allow_header,
                               const LoadOptions& options,
                               const std::function<void(std::uint64_t)>& reserve,
                               const std::function<void(double, double, double)>& sink) {
  const std::uint64_t size = checked_file_size(file);
  const std::uint64_t remaining = budget.remaining();
  std::uint64_t count = 0;
  bool header_possible = allow_header, reserved = false;

  auto handle = [&](const char* b, const char* e, std::size_t line) {
    double xyz[3];
    switch (parse_line(b, e, xyz)) {
      case LineKind::kSkip:
        return;
      case LineKind::kBad: {
        const char* q = b;
        while (q < e && is_space(*q)) ++q;
        if (header_possible && q < e &&
            (std::isalpha(static_cast<unsigned char>(*q)) || *q == '"')) {
          header_possible = false;  // a column header such as "x,y,z"
          return;
        }
        throw InputError(file,
                         "malformed line, expected 'x y z ...' (three numbers separated by "
                         "spaces or commas): '" +
                             snippet(b, e) + "'",
                         line);
      }
      case LineKind::kPoint:
        break;
    }
    header_possible = false;
    if (count >= remaining) check_budget(file, count + 1, budget);
    ++count;
    sink(xyz[0], xyz[1], xyz[2]);
  };
  auto after_chunk = [&](std::uint64_t consumed) {
    if (reserved || !reserve || count == 0) return;
    // Estimate the points from the first chunk's bytes per point, never beyond what the file
    // size or the budget allows.
    const double per_point = static_cast<double>(consumed) / static_cast<double>(count);
    const auto estimate = static_cast<std::uint64_t>(static_cast<double>(size) / per_point * 1.05);
    reserve(std::min({estimate + 16, text_points_upper_bound(size), remaining}));
    reserved = true;
  };
  for_each_line(file, 0, 1, options, handle, after_chunk);
  return count;
}

std::uint64_t text_points_upper_bound(std::uint64_t bytes) {
  return (bytes + 1) / 6;
}

ReadInfo read_xyz(const std::string& file, const Budget& budget, const LoadOptions& options,
                  std::vector<Eigen::Vector3f>& out) {
  const bool csv = file.size() >= 4 && (file.ends_with(".csv") || file.ends_with(".CSV"));
  ReadInfo info;
  info.points = read_text_points(
      file, budget, csv, options, [&](std::uint64_t n) { reserve_more(out, n); },
      [&](double x, double y, double z) {
        out.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
      });
  return info;
}

}  // namespace indoormap::cloud_io::detail
