// PLY (ascii, binary_little_endian, binary_big_endian): our own reader of the vertex x y z.
// PCL's PLYReader is not used: it allocates from the header's counts without checking them
// against the file, which is exactly what we must not do.
#include <algorithm>
#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>

#include "indoormap/core/errors.hpp"
#include "load_internal.hpp"

namespace indoormap::cloud_io::detail {

namespace {

static_assert(std::endian::native == std::endian::little,
              "PLY reader assumes a little-endian host");

constexpr std::uint64_t kMaxHeaderBytes = std::uint64_t{1} << 20;
constexpr std::size_t kBufferBytes = std::size_t{4} << 20;

enum class Scalar { kI8, kU8, kI16, kU16, kI32, kU32, kF32, kF64 };

bool scalar_from_name(std::string_view s, Scalar& t) {
  static constexpr std::pair<std::string_view, Scalar> kNames[] = {
      {"char", Scalar::kI8},    {"int8", Scalar::kI8},     {"uchar", Scalar::kU8},
      {"uint8", Scalar::kU8},   {"short", Scalar::kI16},   {"int16", Scalar::kI16},
      {"ushort", Scalar::kU16}, {"uint16", Scalar::kU16},  {"int", Scalar::kI32},
      {"int32", Scalar::kI32},  {"uint", Scalar::kU32},    {"uint32", Scalar::kU32},
      {"float", Scalar::kF32},  {"float32", Scalar::kF32}, {"double", Scalar::kF64},
      {"float64", Scalar::kF64}};
  for (const auto& [name, type] : kNames)
    if (s == name) {
      t = type;
      return true;
    }
  return false;
}

std::size_t scalar_size(Scalar t) {
  switch (t) {
    case Scalar::kI8:
    case Scalar::kU8:
      return 1;
    case Scalar::kI16:
    case Scalar::kU16:
      return 2;
    case Scalar::kI32:
    case Scalar::kU32:
    case Scalar::kF32:
      return 4;
    case Scalar::kF64:
      return 8;
  }
  return 0;
}

template <typename T>
T load(const unsigned char* p, bool swap) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (swap) std::reverse(b, b + sizeof(T));
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

double scalar_value(Scalar t, const unsigned char* p, bool swap) {
  switch (t) {
    case Scalar::kI8:
      return load<std::int8_t>(p, swap);
    case Scalar::kU8:
      return load<std::uint8_t>(p, swap);
    case Scalar::kI16:
      return load<std::int16_t>(p, swap);
    case Scalar::kU16:
      return load<std::uint16_t>(p, swap);
    case Scalar::kI32:
      return load<std::int32_t>(p, swap);
    case Scalar::kU32:
      return load<std::uint32_t>(p, swap);
    case Scalar::kF32:
      return load<float>(p, swap);
    case Scalar::kF64:
      return load<double>(p, swap);
  }
  return 0;
}

struct Property {
  std::string name;
  Scalar type = Scalar::kF32;
  bool is_list = false;
  Scalar count_type = Scalar::kU8;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> props;
  std::size_t line = 0;
  /// Smallest possible bytes per instance (lists empty); the exact stride when no lists.
  std::uint64_t min_bytes() const {
    std::uint64_t n = 0;
    for (const auto& p : props) n += scalar_size(p.is_list ? p.count_type : p.type);
    return n;
  }
  bool has_lists() const {
    return std::any_of(props.begin(), props.end(), [](const Property& p) { return p.is_list; });
  }
};

enum class Format { kAscii, kLittle, kBig };

struct Header {
  Format format = Format::kAscii;
  std::vector<Element> elements;
  std::uint64_t data_offset = 0;
  std::size_t lines = 0;  ///< header lines, so ascii body lines can be numbered
};

Header parse_header(std::string_view head, const std::string& file) {
  Header h;
  std::size_t pos = 0, line = 0;
  auto fail = [&](const std::string& problem) {
    throw InputError(file, "PLY header: " + problem, line);
  };
  bool have_format = false;
  for (;;) {
    if (pos >= head.size()) {
      if (line == 0) throw InputError(file, "empty file (no PLY header)");
      fail("ends without end_header");
    }
    const std::size_t nl = head.find('\n', pos);
    const std::size_t end = nl == std::string_view::npos ? head.size() : nl;
    std::string_view text = head.substr(pos, end - pos);
    pos = nl == std::string_view::npos ? head.size() : nl + 1;
    ++line;
    while (!text.empty() && (text.back() == '\r' || text.back() == ' ' || text.back() == '\t'))
      text.remove_suffix(1);
    if (line == 1) {
      if (text != "ply") fail("the file does not start with 'ply'");
      continue;
    }
    const auto tok = split_ws(text);
    if (tok.empty() || tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "format") {
      if (tok.size() != 3) fail("format line needs 'format <type> 1.0'");
      if (tok[1] == "ascii")
        h.format = Format::kAscii;
      else if (tok[1] == "binary_little_endian")
        h.format = Format::kLittle;
      else if (tok[1] == "binary_big_endian")
        h.format = Format::kBig;
      else
        fail("unknown format '" + std::string(tok[1]) + "'");
      have_format = true;
    } else if (tok[0] == "element") {
      Element e;
      if (tok.size() != 3) fail("element line needs 'element <name> <count>'");
      e.name = std::string(tok[1]);
      const auto [p, ec] = std::from_chars(tok[2].data(), tok[2].data() + tok[2].size(), e.count);
      if (ec != std::errc() || p != tok[2].data() + tok[2].size())
        fail("element count '" + std::string(tok[2]) + "' is not a non-negative integer");
      e.line = line;
      h.elements.push_back(std::move(e));
    } else if (tok[0] == "property") {
      if (h.elements.empty()) fail("property before any element");
      Property p;
      if (tok.size() == 5 && tok[1] == "list") {
        p.is_list = true;
        if (!scalar_from_name(tok[2], p.count_type) || !scalar_from_name(tok[3], p.type))
          fail("unknown list property types");
        if (p.count_type == Scalar::kF32 || p.count_type == Scalar::kF64)
          fail("list count type must be an integer");
        p.name = std::string(tok[4]);
      } else if (tok.size() == 3) {
        if (!scalar_from_name(tok[1], p.type))
          fail("unknown property type '" + std::string(tok[1]) + "'");
        p.name = std::string(tok[2]);
      } else {
        fail("malformed property line");
      }
      h.elements.back().props.push_back(std::move(p));
    } else if (tok[0] == "end_header") {
      break;
    } else {
      fail("unknown header line '" + std::string(text.substr(0, 40)) + "'");
    }
  }
  if (!have_format) fail("no format line");
  h.data_offset = pos;
  h.lines = line;
  return h;
}

// Buffered sequential reads with a hard end: never reads beyond the file, never trusts counts.
class ByteReader {
 public:
  ByteReader(std::FILE* f, const std::string& file, std::uint64_t bytes) : f_(f), file_(file) {
    buf_.resize(static_cast<std::size_t>(std::clamp<std::uint64_t>(bytes, 64, kBufferBytes)));
  }
  // Returns a pointer to n contiguous bytes (n <= kBufferBytes), or throws on end of file.
  const unsigned char* take(std::size_t n) {
    if (end_ - pos_ < n) refill(n);
    const unsigned char* p = buf_.data() + pos_;
    pos_ += n;
    return p;
  }

 private:
  void refill(std::size_t n) {
    std::memmove(buf_.data(), buf_.data() + pos_, end_ - pos_);
    end_ -= pos_;
    pos_ = 0;
    end_ += std::fread(buf_.data() + end_, 1, buf_.size() - end_, f_);
    if (end_ < n) throw InputError(file_, "PLY data section ends early (truncated file)");
  }
  std::FILE* f_;
  const std::string& file_;
  std::vector<unsigned char> buf_;
  std::size_t pos_ = 0, end_ = 0;
};

// Whitespace-separated tokens of an ascii body, read in chunks, with line numbers.
class TokenReader {
 public:
  TokenReader(std::FILE* f, const std::string& file, std::size_t first_line, std::uint64_t bytes)
      : f_(f),
        file_(file),
        line_(first_line),
        chunk_(static_cast<std::size_t>(std::clamp<std::uint64_t>(bytes + 1, 64, kBufferBytes))) {}
  std::string_view next() {
    for (;;) {
      while (pos_ < buf_.size() && std::isspace(static_cast<unsigned char>(buf_[pos_]))) {
        if (buf_[pos_] == '\n') ++line_;
        ++pos_;
      }
      std::size_t e = pos_;
      while (e < buf_.size() && !std::isspace(static_cast<unsigned char>(buf_[e]))) ++e;
      if (e < buf_.size() || (eof_ && e > pos_)) {
        std::string_view t(buf_.data() + pos_, e - pos_);
        pos_ = e;
        return t;
      }
      if (eof_) throw InputError(file_, "PLY data section ends early (truncated file)", line_);
      if (buf_.size() - pos_ > 4096) throw InputError(file_, "PLY token too long", line_);
      buf_.erase(0, pos_);
      pos_ = 0;
      const std::size_t old = buf_.size();
      buf_.resize(old + chunk_);
      const std::size_t got = std::fread(buf_.data() + old, 1, chunk_, f_);
      buf_.resize(old + got);
      eof_ = got < chunk_;
    }
  }
  double number() {
    const std::string_view t = next();
    std::string_view s = t;
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    double v = 0;
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec == std::errc::result_out_of_range)
      v = std::strtod(std::string(s).c_str(), nullptr);
    else if (ec != std::errc() || p != s.data() + s.size())
      throw InputError(file_, "PLY value '" + std::string(t.substr(0, 40)) + "' is not a number",
                       line_);
    return v;
  }
  std::size_t line() const { return line_; }
  /// True when only spaces, tabs or a CR are left on the current line (or the file ends).
  bool at_end_of_line() {
    for (;;) {
      while (pos_ < buf_.size() && (buf_[pos_] == ' ' || buf_[pos_] == '\t' || buf_[pos_] == '\r'))
        ++pos_;
      if (pos_ < buf_.size()) return buf_[pos_] == '\n';
      if (eof_) return true;
      buf_.clear();
      pos_ = 0;
      buf_.resize(chunk_);
      const std::size_t got = std::fread(buf_.data(), 1, chunk_, f_);
      buf_.resize(got);
      eof_ = got < chunk_;
    }
  }

 private:
  std::FILE* f_;
  const std::string& file_;
  std::size_t line_;
  std::size_t chunk_;  ///< bytes per read: the body size + 1 for small files, so one read sees eof
  std::string buf_;
  std::size_t pos_ = 0;
  bool eof_ = false;
};

// The ascii body up to and including the vertex element, one element per line: a line with a
// value too many or too few is refused at that line (it would shift every later value).
void read_ascii_elements(TokenReader& tr, const Header& h, std::vector<Element>::const_iterator vit,
                         const int (&xyz_index)[3], const std::string& file,
                         std::vector<Eigen::Vector3f>& out) {
  double v[3] = {0.0, 0.0, 0.0};
  for (auto it = h.elements.begin(); it <= vit; ++it) {
    if (it->props.empty()) continue;  // nothing to read, whatever its count (up to 2^64 - 1)
    const bool is_vertex = it == vit;
    for (std::uint64_t k = 0; k < it->count; ++k) {
      // One element per line: a short or long line would shift every later value silently.
      std::size_t line = 0;
      auto same_line = [&] {
        if (line == 0) line = tr.line();
        if (tr.line() != line)
          throw InputError(file,
                           "PLY data line has fewer values than the " +
                               std::to_string(it->props.size()) + " properties of '" + it->name +
                               "' (short line)",
                           line);
      };
      for (std::size_t pi = 0; pi < it->props.size(); ++pi) {
        const Property& p = it->props[pi];
        if (p.is_list) {
          const double c = tr.number();
          same_line();
          if (!(c >= 0) || c > 1e6 || c != std::floor(c))
            throw InputError(file, "PLY list count is not a small non-negative integer", tr.line());
          for (auto j = static_cast<std::uint64_t>(c); j > 0; --j) {
            tr.next();
            same_line();
          }
        } else if (is_vertex) {
          const double x = tr.number();
          same_line();
          for (int a = 0; a < 3; ++a)
            if (xyz_index[a] == static_cast<int>(pi)) v[a] = x;
        } else {
          tr.next();
          same_line();
        }
      }
      if (!tr.at_end_of_line())
        throw InputError(file,
                         "PLY data line has more values than the " +
                             std::to_string(it->props.size()) + " properties of '" + it->name + "'",
                         tr.line());
      if (is_vertex)
        out.emplace_back(static_cast<float>(v[0]), static_cast<float>(v[1]),
                         static_cast<float>(v[2]));
    }
  }
}

}  // namespace

ReadInfo read_ply(const std::string& file, const Budget& budget,
                  std::vector<Eigen::Vector3f>& out) {
  const std::uint64_t size = checked_file_size(file);
  const std::string head = read_file_prefix(file, kMaxHeaderBytes);
  const Header h = parse_header(head, file);

  // Locate the vertex element and x y z; check every count against the bytes present.
  const auto vit = std::find_if(h.elements.begin(), h.elements.end(),
                                [](const Element& e) { return e.name == "vertex"; });
  if (vit == h.elements.end()) throw InputError(file, "PLY header: no 'element vertex'");
  const Element& vertex = *vit;
  int xyz_index[3] = {-1, -1, -1};
  const char* names[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    for (std::size_t i = 0; i < vertex.props.size(); ++i)
      if (vertex.props[i].name == names[a]) xyz_index[a] = static_cast<int>(i);
    if (xyz_index[a] < 0)
      throw InputError(file, std::string("PLY header: vertex has no property '") + names[a] + "'",
                       vertex.line);
    const Property& p = vertex.props[static_cast<std::size_t>(xyz_index[a])];
    if (p.is_list || (p.type != Scalar::kF32 && p.type != Scalar::kF64))
      throw InputError(
          file,
          std::string("PLY header: vertex property '") + names[a] + "' must be float or double",
          vertex.line);
  }
  const std::uint64_t n = vertex.count;
  if (n == 0) throw InputError(file, "PLY header: element vertex 0: empty cloud", vertex.line);

  const std::uint64_t body = size > h.data_offset ? size - h.data_offset : 0;
  std::uint64_t need = 0;  // lower bound of the bytes up to and including the vertices
  for (auto it = h.elements.begin(); it <= vit; ++it) {
    // ascii: one character and one separator per value at least.
    const std::uint64_t per = h.format == Format::kAscii ? 2 * it->props.size() : it->min_bytes();
    if (per != 0 && it->count > (body - std::min(body, need)) / per)
      throw InputError(file,
                       "PLY data section too short for " + std::to_string(it->count) + " '" +
                           it->name + "' elements (truncated file?)",
                       it->line);
    need += it->count * per;
  }
  check_budget(file, n, budget);

  FilePtr f(std::fopen(file.c_str(), "rb"));
  if (!f) throw InputError(file, std::string("cannot open: ") + std::strerror(errno));
  if (std::fseek(f.get(), static_cast<long>(h.data_offset), SEEK_SET) != 0)
    throw InputError(file, "cannot seek to the PLY data section");
  reserve_more(out, n);

  double v[3] = {0.0, 0.0, 0.0};
  if (h.format == Format::kAscii) {
    TokenReader tr(f.get(), file, h.lines + 1, body);
    read_ascii_elements(tr, h, vit, xyz_index, file, out);
  } else {
    const bool swap = h.format == Format::kBig;
    ByteReader br(f.get(), file, body);
    for (auto it = h.elements.begin(); it <= vit; ++it) {
      if (it->props.empty()) continue;  // nothing to read, whatever its count (up to 2^64 - 1)
      const bool is_vertex = it == vit;
      for (std::uint64_t k = 0; k < it->count; ++k) {
        for (std::size_t pi = 0; pi < it->props.size(); ++pi) {
          const Property& p = it->props[pi];
          if (p.is_list) {
            const double c = scalar_value(p.count_type, br.take(scalar_size(p.count_type)), swap);
            if (!(c >= 0) || c > 1e6)
              throw InputError(file, "PLY list count is negative or too large");
            for (auto j = static_cast<std::uint64_t>(c); j > 0; --j) br.take(scalar_size(p.type));
          } else {
            const unsigned char* b = br.take(scalar_size(p.type));
            if (is_vertex)
              for (int a = 0; a < 3; ++a)
                if (xyz_index[a] == static_cast<int>(pi)) v[a] = scalar_value(p.type, b, swap);
          }
        }
        if (is_vertex)
          out.emplace_back(static_cast<float>(v[0]), static_cast<float>(v[1]),
                           static_cast<float>(v[2]));
      }
    }
  }
  ReadInfo info;
  info.points = n;
  return info;
}

}  // namespace indoormap::cloud_io::detail
