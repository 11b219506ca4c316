#include "indoormap/formats/ros_map.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <opencv2/core.hpp>
#include <sstream>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/core/input_file.hpp"
#include "indoormap/formats/pgm.hpp"
#include "indoormap/formats/png.hpp"

namespace indoormap::formats {

namespace fs = std::filesystem;

namespace {

/// Shortest text that reads back as the same double.
std::string shortest(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, r.ptr);
  if (s.find_first_of(".eE") == std::string::npos && s.find("inf") == std::string::npos) s += ".0";
  return s;
}

}  // namespace

RosMapMeta map_meta(const std::string& image, const GridGeometry& geometry) {
  RosMapMeta meta;
  meta.image = image;
  meta.resolution_m = geometry.cell_m();
  meta.origin = {geometry.origin_m().x(), geometry.origin_m().y(), 0.0};
  return meta;
}

void write_map_yaml(const fs::path& path, const RosMapMeta& meta, MapYamlStyle style) {
  std::ostringstream y;
  if (style == MapYamlStyle::kRosMap) {
    y.precision(10);
    y << "image: " << meta.image << "\n"
      << "mode: trinary\n"
      << "resolution: " << meta.resolution_m << "\n"
      << "origin: [" << meta.origin.x() << ", " << meta.origin.y() << ", 0.0]\n"
      << "negate: " << meta.negate << "\n"
      << "occupied_thresh: " << meta.occupied_thresh << "\n"
      << "free_thresh: " << meta.free_thresh << "\n";
  } else {
    y << "image: " << meta.image << "\n"
      << "resolution: " << shortest(meta.resolution_m) << "\n"
      << "origin: [" << shortest(meta.origin.x()) << ", " << shortest(meta.origin.y()) << ", 0.0]\n"
      << "negate: " << meta.negate << "\n"
      << "occupied_thresh: " << shortest(meta.occupied_thresh) << "\n"
      << "free_thresh: " << shortest(meta.free_thresh) << "\n";
  }
  for (std::string line : meta.comments) {  // one line each: a newline would end the comment
    for (auto& ch : line)
      if (ch == '\n' || ch == '\r') ch = ' ';
    y << "# " << line << "\n";
  }
  write_file_atomic(path, y.str());
}

void write_ros_map(const fs::path& dir, const std::string& stem, const Grid<Cell>& layout,
                   const GridGeometry& geo, const std::vector<std::string>& comments) {
  Grid<std::uint8_t> img(layout.width, layout.height);
  for (std::size_t i = 0; i < img.size(); ++i) {
    switch (layout.data[i]) {
      case Cell::kWall:
      case Cell::kFurniture:
        img.data[i] = kRosOccupied;
        break;
      case Cell::kFree:
        img.data[i] = kRosFree;
        break;
      case Cell::kUnknown:
        img.data[i] = kRosUnknown;
        break;
    }
  }
  write_pgm(dir / (stem + ".pgm"), img);
  RosMapMeta meta = map_meta(stem + ".pgm", geo);
  meta.comments = comments;
  write_map_yaml(dir / (stem + ".yaml"), meta, MapYamlStyle::kRosMap);
}

namespace {

// Image dimensions from the header, read before decoding so that a huge image is refused
// before anything is allocated for it.
std::pair<std::int64_t, std::int64_t> image_size(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open the map image");
  char head[32] = {};
  in.read(head, sizeof head);
  const auto got = in.gcount();
  if (got >= 24 && static_cast<unsigned char>(head[0]) == 0x89 && head[1] == 'P' &&
      head[2] == 'N' && head[3] == 'G') {
    auto be32 = [&](int o) {
      return (std::int64_t{static_cast<unsigned char>(head[o])} << 24) |
             (std::int64_t{static_cast<unsigned char>(head[o + 1])} << 16) |
             (std::int64_t{static_cast<unsigned char>(head[o + 2])} << 8) |
             std::int64_t{static_cast<unsigned char>(head[o + 3])};
    };
    return {be32(16), be32(20)};
  }
  if (got >= 2 && head[0] == 'P' && (head[1] == '5' || head[1] == '2')) {
    in.clear();
    in.seekg(2);
    std::int64_t w = -1, h = -1;
    auto next_int = [&](std::int64_t& v) {
      for (;;) {
        int ch = in.peek();
        if (ch == '#') {
          std::string skip;
          std::getline(in, skip);
        } else if (std::isspace(ch)) {
          in.get();
        } else {
          break;
        }
      }
      in >> v;
    };
    std::int64_t maxval = -1;
    next_int(w);
    next_int(h);
    next_int(maxval);
    if (!in || w <= 0 || h <= 0 || maxval <= 0 || maxval > 65535)
      throw InputError(path.string(), "malformed PGM header");
    // The pixels must be there before the decoder allocates for them: P5 has 1 or 2 bytes per
    // pixel after one whitespace byte, P2 at least one digit and a separator per pixel.
    const auto header_end = static_cast<std::uint64_t>(in.tellg()) + 1;
    std::error_code ec;
    const std::uint64_t size = fs::file_size(path, ec);
    const std::uint64_t per_pixel = head[1] == '5' ? (maxval > 255 ? 2 : 1) : 2;
    const std::uint64_t body = !ec && size > header_end ? size - header_end + (head[1] == '2') : 0;
    if (static_cast<std::uint64_t>(w) > body / per_pixel / static_cast<std::uint64_t>(h))
      throw InputError(path.string(), "PGM of " + std::to_string(w) + " x " + std::to_string(h) +
                                          " pixels is truncated (" + std::to_string(body) +
                                          " bytes of pixel data)");
    return {w, h};
  }
  throw InputError(path.string(), "map image is neither PGM (P5/P2) nor PNG");
}

// The map image decoded as 8-bit grey, its size checked against max_cells from the header before
// decoding. PNG sizes are 32-bit: each is checked before any product (w * h can overflow int64).
cv::Mat decode_gray(const fs::path& image, std::int64_t max_cells) {
  const auto [w, h] = image_size(image);
  if (w <= 0 || h <= 0) throw InputError(image.string(), "map image has no pixels");
  if (w > std::numeric_limits<int>::max() || h > std::numeric_limits<int>::max() ||
      w > max_cells / h)
    throw BudgetError(image.string() + ": map of " + std::to_string(w) + " x " + std::to_string(h) +
                      " cells is above the budget of " + std::to_string(max_cells) + " cells");
  cv::Mat img(static_cast<int>(h), static_cast<int>(w), CV_8U);
  std::ifstream in(image, std::ios::binary);
  const bool png = in.get() == 0x89;
  in.close();
  if (png) {
    GreyImage g;
    try {
      g = read_png_grey(image, false, max_cells);
    } catch (const InputError& e) {
      throw InputError(image.string(), "cannot decode the map image (" + e.problem() + ")");
    }
    if (g.width != w || g.height != h)
      throw InputError(image.string(), "cannot decode the map image");
    for (std::size_t i = 0; i < g.pixels.size(); ++i)
      img.data[i] = static_cast<std::uint8_t>(g.pixels[i]);
  } else {
    const Grid<std::uint8_t> g = read_pgm(image, false);
    if (g.width != w || g.height != h)
      throw InputError(image.string(), "cannot decode the map image");
    std::copy(g.data.begin(), g.data.end(), img.data);
  }
  return img;
}

}  // namespace

RosMap decode_ros_map(const RosMapMeta& meta, const fs::path& yaml_path, std::int64_t max_cells) {
  RosMap m;
  m.meta = meta;
  fs::path image = m.meta.image;
  if (image.is_relative()) image = yaml_path.parent_path() / image;
  std::error_code ec;
  if (!fs::is_regular_file(image, ec)) {
    if (!fs::exists(image, ec))
      throw InputError(image.string(),
                       "map image not found (named by 'image' in " + yaml_path.string() + ")");
    check_input_file(image, kNoSizeLimit,
                     "the map image named by 'image' in " + yaml_path.string());
  }
  const cv::Mat img = decode_gray(image, max_cells);
  const int w = img.cols, h = img.rows;

  m.geometry = GridGeometry({m.meta.origin.x(), m.meta.origin.y()}, m.meta.resolution_m,
                            static_cast<int>(w), static_cast<int>(h));
  m.cells = Grid<Cell>(static_cast<int>(w), static_cast<int>(h), Cell::kUnknown);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const double v = img.at<std::uint8_t>(static_cast<int>(h - 1 - r), c);
      const double p = m.meta.negate ? v / 255.0 : (255.0 - v) / 255.0;
      m.cells.at(c, r) = p > m.meta.occupied_thresh ? Cell::kWall
                         : p < m.meta.free_thresh   ? Cell::kFree
                                                    : Cell::kUnknown;
    }
  return m;
}

RosMap read_plain_map(const fs::path& image, double resolution_m, int free_min,
                      std::int64_t max_cells) {
  if (!(resolution_m > 0) || !std::isfinite(resolution_m))
    throw UsageError("map resolution must be a positive number of metres per pixel");
  if (free_min < 0 || free_min > 255) throw UsageError("free_min must be in [0, 255]");
  // A directory would reach the decoder as an unreadable file, a FIFO would block in open().
  std::error_code ec;
  if (!fs::exists(image, ec)) throw InputError(image.string(), "map image not found");
  if (!fs::is_regular_file(image, ec))
    throw InputError(image.string(), "map image is not a regular file");
  check_input_file(image, kNoSizeLimit, "a map image");
  const cv::Mat img = decode_gray(image, max_cells);
  const int w = img.cols, h = img.rows;
  RosMap m;
  m.meta.image = image.filename().string();
  m.meta.resolution_m = resolution_m;
  m.geometry = GridGeometry({0.0, 0.0}, resolution_m, static_cast<int>(w), static_cast<int>(h));
  m.cells = Grid<Cell>(static_cast<int>(w), static_cast<int>(h), Cell::kWall);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (img.at<std::uint8_t>(static_cast<int>(h - 1 - r), c) >= free_min)
        m.cells.at(c, r) = Cell::kFree;
  return m;
}

}  // namespace indoormap::formats
