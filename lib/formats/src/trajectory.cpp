#include "indoormap/formats/trajectory.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <string_view>

#include "indoormap/core/errors.hpp"
#include "indoormap/core/input_file.hpp"

namespace indoormap::formats {

namespace {

std::vector<std::string_view> words_of(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  auto sep = [](char c) { return c == ' ' || c == '\t' || c == ',' || c == '\r'; };
  while (i < s.size()) {
    while (i < s.size() && sep(s[i])) ++i;
    const std::size_t b = i;
    while (i < s.size() && !sep(s[i])) ++i;
    if (i > b) out.push_back(s.substr(b, i - b));
  }
  return out;
}

double number(std::string_view w, const std::string& file, std::size_t line, std::size_t col) {
  double v = 0.0;
  const char* end = w.data() + w.size();
  const auto [p, ec] = std::from_chars(w.data(), end, v);
  if (ec != std::errc() || p != end || !std::isfinite(v))
    throw InputError(file,
                     "column " + std::to_string(col + 1) + ": '" + std::string(w.substr(0, 40)) +
                         "' is not a finite number",
                     line);
  return v;
}

}  // namespace

Trajectory read_trajectory(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string text = read_input_file(path, kMaxTextInputBytes, "the trajectory");
  Trajectory t;
  std::size_t columns = 0, line = 0, pos = 0;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    const std::string_view l(text.data() + pos, (nl == std::string::npos ? text.size() : nl) - pos);
    pos = nl == std::string::npos ? text.size() : nl + 1;
    ++line;
    const auto w = words_of(l);
    if (w.empty() || w[0].starts_with("#")) continue;
    if (w.size() != 3 && w.size() != 8)
      throw InputError(file,
                       "expected 8 columns 't x y z qx qy qz qw' (TUM) or 3 'x y z', got " +
                           std::to_string(w.size()),
                       line);
    if (columns == 0) columns = w.size();
    if (w.size() != columns)
      throw InputError(file,
                       std::to_string(w.size()) + " columns where the file's first pose line has " +
                           std::to_string(columns),
                       line);
    std::vector<double> v;
    for (std::size_t k = 0; k < w.size(); ++k) v.push_back(number(w[k], file, line, k));
    const std::size_t o = columns == 8 ? 1 : 0;
    if (columns == 8) {
      const double n = std::sqrt(v[4] * v[4] + v[5] * v[5] + v[6] * v[6] + v[7] * v[7]);
      if (std::abs(n - 1.0) > kQuaternionNormTolerance) {
        char msg[160];
        std::snprintf(msg, sizeof msg,
                      "quaternion (qx qy qz qw) has norm %.6g, expected 1 within %g", n,
                      kQuaternionNormTolerance);
        throw InputError(file, msg, line);
      }
    }
    t.positions.emplace_back(v[o], v[o + 1], v[o + 2]);
    t.lines.push_back(line);
  }
  if (t.positions.empty()) throw InputError(file, "no pose line (empty trajectory)");
  t.format = columns == 8 ? TrajectoryFormat::kTum : TrajectoryFormat::kPlain;
  return t;
}

}  // namespace indoormap::formats
