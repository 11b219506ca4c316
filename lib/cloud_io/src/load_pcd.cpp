// PCD: our own header validation, then PCL's reader for binary_compressed data sections. Debian's
// PCL 1.13 crashes (or throws std::bad_alloc) on an empty file, a header without FIELDS,
// WIDTH*HEIGHT overflowing, or POINTS far beyond the body, so PCL only ever sees a file whose
// header we have checked against the file size. ASCII and uncompressed binary bodies are read
// here (read_pcd_ascii, read_pcd_binary).
#include <pcl/PCLPointCloud2.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/core/errors.hpp"
#include "load_internal.hpp"

namespace indoormap::cloud_io {

namespace {

constexpr std::uint64_t kMaxHeaderBytes = std::uint64_t{1} << 20;

template <typename T>
bool parse_int(std::string_view s, T& v) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size();
}

bool parse_double(std::string_view s, double& v) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (end != s.data() + s.size()) return false;
  // Beyond double's range: strtod gives +-HUGE_VAL (dropped later as non-finite) or ~0.
  if (ec == std::errc::result_out_of_range) v = std::strtod(std::string(s).c_str(), nullptr);
  return ec == std::errc() || ec == std::errc::result_out_of_range;
}

std::uint32_t read_u32_le(std::string_view s, std::size_t at) {
  const auto* b = reinterpret_cast<const unsigned char*>(s.data() + at);
  return std::uint32_t{b[0]} | (std::uint32_t{b[1]} << 8) | (std::uint32_t{b[2]} << 16) |
         (std::uint32_t{b[3]} << 24);
}

// The header lines up to and including DATA: fills h, returns key -> header line; `line` ends on
// the DATA line.
std::map<std::string, std::size_t> parse_header_lines(std::string_view head,
                                                      std::uint64_t file_size,
                                                      const std::string& file, PcdHeader& h,
                                                      std::size_t& line) {
  std::map<std::string, std::size_t> seen;  // key -> header line
  std::size_t pos = 0;
  bool have_data = false;
  auto fail = [&](const std::string& problem, std::size_t at) {
    throw InputError(file, "PCD header: " + problem, at);
  };

  while (!have_data) {
    if (pos >= head.size()) {
      if (head.size() < file_size && head.size() >= kMaxHeaderBytes)
        fail("no DATA line within the first " + std::to_string(kMaxHeaderBytes) + " bytes", line);
      fail("ends without a DATA line", line);
    }
    const std::size_t nl = head.find('\n', pos);
    const std::size_t end = nl == std::string_view::npos ? head.size() : nl;
    std::string_view text = head.substr(pos, end - pos);
    pos = nl == std::string_view::npos ? head.size() : nl + 1;
    ++line;
    const bool empty_line = text.empty();
    while (!text.empty() && (text.back() == '\r' || text.back() == ' ' || text.back() == '\t'))
      text.remove_suffix(1);
    const auto tok = detail::split_ws(text);
    // PCL skips an empty line but ends its header at a blank one (spaces, tabs or a CR alone),
    // then reads the data from the wrong place and crashes (a fuzz finding): refuse it.
    if (tok.empty() && !empty_line)
      fail("blank line of spaces, tabs or a CR alone (only empty lines are allowed)", line);
    if (tok.empty() || tok[0][0] == '#') continue;
    if (text.find('\0') != std::string_view::npos) fail("binary bytes inside the header", line);

    std::string key(tok[0]);
    if (key == "COLUMNS") key = "FIELDS";  // PCD v0.5 name
    if (seen.count(key)) fail("duplicate " + key + " line", line);
    seen[key] = line;
    const std::size_t nv = tok.size() - 1;
    auto need_values = [&](std::size_t n) {
      if (nv != n)
        fail(key + " needs " + std::to_string(n) + " value(s), got " + std::to_string(nv), line);
    };
    auto need_some = [&] {
      if (nv == 0) fail(key + " has no values", line);
    };

    if (key == "VERSION") {
      need_values(1);
    } else if (key == "FIELDS") {
      need_some();
      for (std::size_t i = 1; i < tok.size(); ++i) h.fields.emplace_back(tok[i]);
    } else if (key == "SIZE" || key == "COUNT") {
      need_some();
      auto& dst = key == "SIZE" ? h.sizes : h.counts;
      for (std::size_t i = 1; i < tok.size(); ++i) {
        int v = 0;
        if (!parse_int(tok[i], v))
          fail(key + " value '" + std::string(tok[i]) + "' is not an integer", line);
        dst.push_back(v);
      }
    } else if (key == "TYPE") {
      need_some();
      for (std::size_t i = 1; i < tok.size(); ++i) {
        if (tok[i].size() != 1 || (tok[i][0] != 'F' && tok[i][0] != 'I' && tok[i][0] != 'U'))
          fail("TYPE value '" + std::string(tok[i]) + "' is not F, I or U", line);
        h.types.push_back(tok[i][0]);
      }
    } else if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS") {
      need_values(1);
      std::uint64_t v = 0;
      if (!parse_int(tok[1], v))
        fail(key + " value '" + std::string(tok[1]) + "' is not a non-negative integer", line);
      (key == "WIDTH" ? h.width : key == "HEIGHT" ? h.height : h.points) = v;
    } else if (key == "VIEWPOINT") {
      need_values(7);
      for (int i = 0; i < 7; ++i)
        if (!parse_double(tok[i + 1], h.viewpoint[i]) || !std::isfinite(h.viewpoint[i]))
          fail("VIEWPOINT value '" + std::string(tok[i + 1]) + "' is not a finite number", line);
      h.has_viewpoint = true;
    } else if (key == "DATA") {
      need_values(1);
      h.data = std::string(tok[1]);
      if (h.data != "ascii" && h.data != "binary" && h.data != "binary_compressed")
        fail("DATA '" + h.data + "' is not ascii, binary or binary_compressed", line);
      h.data_offset = pos;
      have_data = true;
    } else {
      fail("unknown header line '" + std::string(text.substr(0, 40)) + "'", line);
    }
  }
  return seen;
}

// Every required key, FIELDS / SIZE / TYPE / COUNT consistent, x y z floats, WIDTH x HEIGHT =
// POINTS > 0. Sets h.point_size; returns the values per point.
std::uint64_t check_fields(PcdHeader& h, const std::map<std::string, std::size_t>& seen,
                           const std::string& file, std::size_t data_line) {
  auto fail = [&](const std::string& problem, std::size_t at) {
    throw InputError(file, "PCD header: " + problem, at);
  };
  for (const char* key :
       {"VERSION", "FIELDS", "SIZE", "TYPE", "COUNT", "WIDTH", "HEIGHT", "POINTS"})
    if (!seen.count(key)) fail(std::string("no ") + key + " line before DATA", data_line);

  const std::size_t nf = h.fields.size();
  auto same_length = [&](const char* key, std::size_t n) {
    if (n != nf)
      fail(std::string(key) + " has " + std::to_string(n) + " values but FIELDS has " +
               std::to_string(nf),
           seen.at(key));
  };
  same_length("SIZE", h.sizes.size());
  same_length("TYPE", h.types.size());
  same_length("COUNT", h.counts.size());

  std::uint64_t values_per_point = 0;
  for (std::size_t i = 0; i < nf; ++i) {
    const int s = h.sizes[i];
    if (s != 1 && s != 2 && s != 4 && s != 8)
      fail("SIZE of field '" + h.fields[i] + "' is " + std::to_string(s) + ", not 1, 2, 4 or 8",
           seen.at("SIZE"));
    if (h.types[i] == 'F' && s != 4 && s != 8)
      fail("float field '" + h.fields[i] + "' has SIZE " + std::to_string(s), seen.at("SIZE"));
    // An upper limit only to keep point_size far from overflow; real files use 1..~300.
    if (h.counts[i] < 1 || h.counts[i] > (1 << 20))
      fail("COUNT of field '" + h.fields[i] + "' is " + std::to_string(h.counts[i]),
           seen.at("COUNT"));
    h.point_size += static_cast<std::uint64_t>(s) * static_cast<std::uint64_t>(h.counts[i]);
    values_per_point += static_cast<std::uint64_t>(h.counts[i]);
  }
  for (const char* axis : {"x", "y", "z"}) {
    const auto it = std::find(h.fields.begin(), h.fields.end(), axis);
    if (it == h.fields.end())
      fail(std::string("FIELDS has no '") + axis + "' (x y z are required)", seen.at("FIELDS"));
    const auto i = static_cast<std::size_t>(it - h.fields.begin());
    if (h.types[i] != 'F' || h.counts[i] != 1)
      fail(std::string("field '") + axis + "' must be a float (TYPE F, COUNT 1)", seen.at("TYPE"));
  }

  const std::size_t points_line = seen.at("POINTS");
  const bool product_overflows =
      h.height != 0 && h.width > std::numeric_limits<std::uint64_t>::max() / h.height;
  if (product_overflows || h.width * h.height != h.points)
    fail("WIDTH " + std::to_string(h.width) + " x HEIGHT " + std::to_string(h.height) +
             " does not equal POINTS " + std::to_string(h.points),
         points_line);
  if (h.points == 0) fail("POINTS is 0: empty cloud", points_line);
  return values_per_point;
}

// The data section must be able to hold POINTS points; checked before anyone allocates.
void check_data_section(const PcdHeader& h, std::string_view head, std::uint64_t file_size,
                        const std::string& file, std::size_t data_line,
                        std::uint64_t values_per_point) {
  auto fail = [&](const std::string& problem, std::size_t at) {
    throw InputError(file, "PCD header: " + problem, at);
  };
  const std::uint64_t body = file_size > h.data_offset ? file_size - h.data_offset : 0;
  const auto too_short = [&](const std::string& detail) {
    throw InputError(file,
                     "PCD data section too short for POINTS " + std::to_string(h.points) +
                         " (truncated file?): " + detail,
                     data_line);
  };
  // PCL keeps reading header lines after DATA: it skips empty and '#' lines and re-parses any
  // line starting with a header keyword (even inside binary data: a body starting "COUNT..."
  // crashed it, a fuzz finding); it stops at the first other line. Refuse what it would misread.
  if (h.data != "ascii") {
    std::size_t at = static_cast<std::size_t>(h.data_offset);
    while (at < head.size()) {
      const std::size_t nl = std::min(head.find('\n', at), head.size());
      std::string_view l = head.substr(at, nl - at);
      at = nl + 1;
      if (l.empty()) continue;
      while (!l.empty() && std::isspace(static_cast<unsigned char>(l.front()))) l.remove_prefix(1);
      if (l.empty()) break;  // PCL: an unknown (empty) keyword ends its header
      if (l[0] == '#') continue;
      for (const char* key : {"VERSION", "FIELDS", "COLUMNS", "SIZE", "TYPE", "COUNT", "WIDTH",
                              "HEIGHT", "VIEWPOINT", "POINTS", "DATA"})
        if (l.starts_with(key))
          fail(std::string("the data section starts with bytes that PCL would read as a ") + key +
                   " header line",
               data_line);
      break;
    }
  }
  if (h.data == "binary") {
    if (h.points > body / h.point_size)
      too_short(std::to_string(body) + " bytes, need " + std::to_string(h.point_size) +
                " per point");
  } else if (h.data == "binary_compressed") {
    if (body < 8 || head.size() < h.data_offset + 8)
      too_short("no compressed / uncompressed size words");
    const std::uint64_t compressed = read_u32_le(head, h.data_offset);
    const std::uint64_t uncompressed = read_u32_le(head, h.data_offset + 4);
    if (h.points > std::numeric_limits<std::uint32_t>::max() / h.point_size ||
        uncompressed != h.points * h.point_size)
      throw InputError(file,
                       "PCD binary_compressed: uncompressed size " + std::to_string(uncompressed) +
                           " does not match POINTS x point size " + std::to_string(h.points) +
                           " x " + std::to_string(h.point_size),
                       data_line);
    if (compressed == 0 || compressed > body - 8)
      too_short("compressed size " + std::to_string(compressed) + ", " + std::to_string(body - 8) +
                " bytes present");
  } else {
    // ASCII: every point needs at least one character per value plus a separator.
    const std::uint64_t min_bytes_per_point = 2 * values_per_point;
    if (h.points > (body + 1) / min_bytes_per_point)
      too_short(std::to_string(body) + " bytes cannot hold that many ascii points");
  }
}

}  // namespace

PcdHeader read_pcd_header(std::string_view head, std::uint64_t file_size, const std::string& file,
                          std::uint64_t max_points) {
  if (file_size == 0) throw InputError(file, "empty file (no PCD header)");
  PcdHeader h;
  std::size_t line = 0;
  const auto seen = parse_header_lines(head, file_size, file, h, line);
  const std::size_t data_line = line;
  const std::uint64_t values_per_point = check_fields(h, seen, file, data_line);
  check_data_section(h, head, file_size, file, data_line, values_per_point);

  if (h.points > max_points)
    throw BudgetError(file + ": POINTS " + std::to_string(h.points) +
                      " exceeds the point budget (max_points " + std::to_string(max_points) + ")");
  return h;
}

PcdHeader read_pcd_header(const std::string& bytes, const std::string& file,
                          std::uint64_t max_points) {
  return read_pcd_header(std::string_view(bytes), bytes.size(), file, max_points);
}

namespace detail {

namespace {

// PCL's ascii reader silently turns a short line or a bad token into zeros, so ascii bodies
// are read here, strictly: every line holds exactly one value per FIELDS x COUNT, x y z parse
// as numbers (nan / inf allowed, dropped later), and there are exactly POINTS lines.
void read_pcd_ascii(const std::string& file, const PcdHeader& h, std::size_t first_line,
                    const LoadOptions& options, std::vector<Eigen::Vector3f>& out) {
  std::size_t col[3] = {0, 0, 0};
  std::size_t values = 0;
  for (std::size_t i = 0; i < h.fields.size(); ++i) {
    for (int a = 0; a < 3; ++a)
      if (h.fields[i] == std::string(1, static_cast<char>('x' + a))) col[a] = values;
    values += static_cast<std::size_t>(h.counts[i]);
  }
  reserve_more(out, h.points);
  std::uint64_t count = 0;
  auto on_line = [&](const char* b, const char* e, std::size_t line) {
    while (e > b && e[-1] == '\r') --e;
    const auto tok = split_ws(std::string_view(b, static_cast<std::size_t>(e - b)));
    if (tok.empty()) return;
    if (count == h.points)
      throw InputError(file, "more data lines than POINTS " + std::to_string(h.points), line);
    if (tok.size() != values)
      throw InputError(file,
                       "PCD data line has " + std::to_string(tok.size()) + " values, expected " +
                           std::to_string(values) + " (FIELDS x COUNT)",
                       line);
    double v[3];
    for (int a = 0; a < 3; ++a) {
      const std::string_view t = tok[col[a]];
      if (!parse_double(t, v[a]))
        throw InputError(file,
                         "PCD value '" + std::string(t.substr(0, 40)) + "' of field " +
                             static_cast<char>('x' + a) + " is not a number",
                         line);
    }
    out.emplace_back(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
    ++count;
  };
  for_each_line(file, h.data_offset, first_line, options, on_line);
  if (count != h.points)
    throw InputError(file, "PCD data has " + std::to_string(count) + " points but POINTS says " +
                               std::to_string(h.points) + " (truncated file?)");
}

// Uncompressed binary bodies are read here: points of point_size bytes back to back, fields in
// FIELDS order (x y z are TYPE F, COUNT 1: check_fields). One pass from the file into the
// output, in chunks of whole points, where PCL's reader would copy the body into a blob first
// (twice the memory, and one more pass over it).
void read_pcd_binary(const std::string& file, const PcdHeader& h, const LoadOptions& options,
                     std::vector<Eigen::Vector3f>& out, ReadInfo& info) {
  std::size_t offset[3] = {0, 0, 0}, at = 0;
  bool is_double[3] = {false, false, false};
  for (std::size_t i = 0; i < h.fields.size(); ++i) {
    for (int a = 0; a < 3; ++a)
      if (h.fields[i] == std::string(1, static_cast<char>('x' + a))) {
        offset[a] = at;
        is_double[a] = h.sizes[i] == 8;
      }
    at += static_cast<std::size_t>(h.sizes[i]) * static_cast<std::size_t>(h.counts[i]);
  }
  const auto step = static_cast<std::size_t>(h.point_size);
  std::ifstream in(file, std::ios::binary);
  if (!in || !in.seekg(static_cast<std::streamoff>(h.data_offset)))
    throw InputError(file, "cannot be opened to read the PCD data section");
  reserve_more(out, h.points);
  // Converted, non-finite points dropped and bounds taken here, in the same pass (compacted).
  const bool convert = options.unit_m != 1.0 || options.up_axis != UpAxis::kZ;
  Eigen::Vector3f lo = info.lo, hi = info.hi;
  const std::size_t per_chunk = std::max<std::size_t>(1, (std::size_t{4} << 20) / step);
  std::vector<char> chunk(per_chunk * step);
  for (std::uint64_t done = 0; done < h.points;) {
    const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(per_chunk, h.points - done));
    if (!in.read(chunk.data(), static_cast<std::streamsize>(n * step)))
      throw InputError(file,
                       "PCD data section ends after " +
                           std::to_string(done + static_cast<std::uint64_t>(in.gcount()) / step) +
                           " of POINTS " + std::to_string(h.points) + " (truncated file?)");
    for (std::size_t k = 0; k < n; ++k) {
      const char* p = chunk.data() + k * step;
      Eigen::Vector3f v;
      for (int a = 0; a < 3; ++a) {
        if (is_double[a]) {
          double d;
          std::memcpy(&d, p + offset[a], sizeof d);
          v[a] = static_cast<float>(d);
        } else {
          std::memcpy(&v[a], p + offset[a], sizeof(float));
        }
      }
      if (convert) v = to_output(v.cast<double>(), options).cast<float>();
      if (!v.allFinite()) continue;
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
      out.push_back(v);
    }
    done += n;
    if (options.progress)
      options.progress(file, static_cast<double>(done) / static_cast<double>(h.points));
  }
  info.compacted = true;
  info.lo = lo;
  info.hi = hi;
}

}  // namespace

ReadInfo read_pcd(const std::string& file, const Budget& budget, const LoadOptions& options,
                  std::vector<Eigen::Vector3f>& out) {
  const std::uint64_t size = checked_file_size(file);
  const std::string head = read_file_prefix(file, kMaxHeaderBytes + 8);
  const PcdHeader h = read_pcd_header(head, size, file, std::numeric_limits<std::uint64_t>::max());
  check_budget(file, h.points, budget);

  ReadInfo info;
  info.points = h.points;
  if (h.has_viewpoint) info.scanners.emplace_back(h.viewpoint[0], h.viewpoint[1], h.viewpoint[2]);
  if (h.data == "ascii") {
    const auto header_lines =
        std::count(head.begin(), head.begin() + static_cast<std::ptrdiff_t>(h.data_offset), '\n');
    read_pcd_ascii(file, h, static_cast<std::size_t>(header_lines) + 1, options, out);
    return info;
  }
  if (h.data == "binary") {
    read_pcd_binary(file, h, options, out, info);
    return info;
  }

  pcl::PCLPointCloud2 blob;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0;
  int rc = -1;
  try {
    pcl::PCDReader reader;
    rc = reader.read(file, blob, origin, orientation, version, 0);
  } catch (const std::exception& e) {
    throw InputError(file, std::string("PCL could not read the PCD data: ") + e.what());
  } catch (...) {
    throw InputError(file, "PCL could not read the PCD data (unknown exception)");
  }
  if (rc < 0)
    throw InputError(file, "PCL could not read the PCD data section (error " + std::to_string(rc) +
                               "); the file is corrupt or truncated");
  const std::uint64_t n = std::uint64_t{blob.width} * blob.height;
  if (n != h.points || blob.data.size() < n * blob.point_step)
    throw InputError(file, "PCL read " + std::to_string(n) + " points, the header says " +
                               std::to_string(h.points));

  struct Axis {
    std::uint32_t offset = 0;
    bool is_double = false;
  } axes[3];
  const char* names[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    const auto it = std::find_if(blob.fields.begin(), blob.fields.end(),
                                 [&](const pcl::PCLPointField& f) { return f.name == names[a]; });
    if (it == blob.fields.end() || (it->datatype != pcl::PCLPointField::FLOAT32 &&
                                    it->datatype != pcl::PCLPointField::FLOAT64))
      throw InputError(file, std::string("PCL found no float field '") + names[a] + "'");
    axes[a] = {it->offset, it->datatype == pcl::PCLPointField::FLOAT64};
  }

  reserve_more(out, n);
  const std::uint8_t* data = blob.data.data();
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::uint8_t* p = data + i * blob.point_step;
    Eigen::Vector3f v;
    for (int a = 0; a < 3; ++a) {
      if (axes[a].is_double) {
        double d;
        std::memcpy(&d, p + axes[a].offset, sizeof d);
        v[a] = static_cast<float>(d);
      } else {
        std::memcpy(&v[a], p + axes[a].offset, sizeof(float));
      }
    }
    out.push_back(v);
  }

  return info;
}

}  // namespace detail

}  // namespace indoormap::cloud_io
