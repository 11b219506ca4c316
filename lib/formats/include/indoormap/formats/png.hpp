#pragma once
// PNG files through libpng: the encoder of every picture (im_draw) and of the areas' label PNG,
// and the decoder of map images and label PNGs. Images are held top row first. OpenCV's image
// codecs are not linked by the library: on Debian they load GDAL, GDCM, Poppler and a hundred
// more shared libraries, 60-100 ms at every start of every app (docs/benchmarks.md).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace indoormap::formats {

/// Pixels top row first, rows `stride` bytes apart: 1 channel (grey) or 3 (blue, green, red, as
/// OpenCV holds them), 8 bits or 16 (host-order std::uint16_t).
struct ImageView {
  const void* data = nullptr;
  int width = 0, height = 0;
  int channels = 1;
  int bits = 8;
  std::size_t stride = 0;
};

/// The PNG bytes of an image; level: zlib level 0-9 (1: fast, OpenCV's default). Throws
/// OutputError naming `what` when the image is malformed or libpng fails.
std::string encode_png(const ImageView& image, int level, const std::string& what);

/// A grey image, top row first.
struct GreyImage {
  int width = 0, height = 0;
  std::vector<std::uint16_t> pixels;  ///< width * height values
};

/// Decodes a PNG file to grey: a palette is expanded, alpha dropped, colour taken as 0.299 R +
/// 0.587 G + 0.114 B (OpenCV's weights); 16-bit samples kept (keep_16) or reduced to their high
/// byte, 8-bit samples kept as they are. The size is checked against max_pixels from the header
/// before any pixel is decoded. Throws InputError naming the file (not a PNG, corrupt, too large).
GreyImage read_png_grey(const std::filesystem::path& path, bool keep_16, std::int64_t max_pixels);

}  // namespace indoormap::formats
