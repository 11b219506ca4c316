#include "indoormap/formats/png.hpp"

#include <png.h>

#include <bit>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>

#include "indoormap/core/errors.hpp"

namespace indoormap::formats {

namespace {

// libpng reports errors through a longjmp back to the setjmp of the function that called it:
// the functions below hold no C++ object of their own between setjmp and the libpng calls (the
// buffers belong to their callers), and turn a failure into a message the caller throws.
struct PngError {
  char message[256] = {};
};

[[noreturn]] void on_error(png_structp png, png_const_charp msg) {
  if (auto* e = static_cast<PngError*>(png_get_error_ptr(png)))
    std::snprintf(e->message, sizeof e->message, "%s", msg ? msg : "libpng error");
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

void append(png_structp png, png_bytep data, std::size_t n) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}

void no_flush(png_structp) {}

bool encode(const ImageView& im, int level, std::string& out, PngError& e) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &e, on_error, on_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, &out, append, no_flush);
  png_set_compression_level(png, level);
  png_set_IHDR(png, info, static_cast<png_uint_32>(im.width), static_cast<png_uint_32>(im.height),
               im.bits, im.channels == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_GRAY,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  if (im.channels == 3) png_set_bgr(png);
  if (im.bits == 16 && std::endian::native == std::endian::little) png_set_swap(png);
  const auto* base = static_cast<const unsigned char*>(im.data);
  for (int r = 0; r < im.height; ++r)
    png_write_row(png, const_cast<png_bytep>(base + static_cast<std::size_t>(r) * im.stride));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

// What decode() found: 0 done, 1 a libpng error (in PngError), 2 above max_pixels.
int decode(std::FILE* f, bool keep_16, std::int64_t max_pixels, std::vector<png_byte>& buf,
           std::vector<png_bytep>& rows, int& width, int& height, int& bits, PngError& e) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &e, on_error, on_warning);
  if (!png) return 1;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return 1;
  }
  png_init_io(png, f);
  png_read_info(png, info);
  const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
  if (w == 0 || h == 0 ||
      static_cast<std::int64_t>(w) > max_pixels / static_cast<std::int64_t>(h)) {
    png_destroy_read_struct(&png, &info, nullptr);
    return 2;
  }
  const int type = png_get_color_type(png, info), depth = png_get_bit_depth(png, info);
  if (type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (type == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (type & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(png);
  if (type & PNG_COLOR_MASK_COLOR)
    png_set_rgb_to_gray_fixed(png, PNG_ERROR_ACTION_NONE, 29900, 58700);  // 1/100000
  if (depth == 16 && !keep_16) png_set_strip_16(png);
  if (depth == 16 && keep_16 && std::endian::native == std::endian::little) png_set_swap(png);
  png_read_update_info(png, info);
  bits = png_get_bit_depth(png, info);
  const std::size_t row_bytes = png_get_rowbytes(png, info);
  buf.resize(row_bytes * h);
  rows.resize(h);
  for (png_uint_32 r = 0; r < h; ++r) rows[r] = buf.data() + r * row_bytes;
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return 0;
}

}  // namespace

std::string encode_png(const ImageView& image, int level, const std::string& what) {
  if (!image.data || image.width <= 0 || image.height <= 0 ||
      !(image.channels == 1 || image.channels == 3) || !(image.bits == 8 || image.bits == 16) ||
      image.stride < static_cast<std::size_t>(image.width) * image.channels * (image.bits / 8) ||
      level < 0 || level > 9)
    throw OutputError(what, "PNG encoding: malformed image");
  std::string out;
  PngError e;
  if (!encode(image, level, out, e))
    throw OutputError(what, std::string("PNG encoding failed: ") + e.message);
  return out;
}

GreyImage read_png_grey(const std::filesystem::path& path, bool keep_16, std::int64_t max_pixels) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"),
                                                          &std::fclose);
  if (!f) throw InputError(path.string(), "cannot open the PNG file");
  unsigned char sig[8] = {};
  if (std::fread(sig, 1, 8, f.get()) != 8 || png_sig_cmp(sig, 0, 8) != 0)
    throw InputError(path.string(), "not a PNG file");
  std::rewind(f.get());
  std::vector<png_byte> buf;
  std::vector<png_bytep> rows;
  GreyImage g;
  int bits = 8;
  PngError e;
  switch (decode(f.get(), keep_16, max_pixels, buf, rows, g.width, g.height, bits, e)) {
    case 1:
      throw InputError(path.string(), std::string("cannot decode the PNG: ") + e.message);
    case 2:
      throw InputError(path.string(), "PNG of more than " + std::to_string(max_pixels) +
                                          " pixels is above the budget");
    default:
      break;
  }
  g.pixels.resize(static_cast<std::size_t>(g.width) * g.height);
  for (std::size_t i = 0; i < g.pixels.size(); ++i) {
    if (bits == 16) {
      std::uint16_t v;
      std::memcpy(&v, buf.data() + 2 * i, 2);
      g.pixels[i] = v;
    } else {
      g.pixels[i] = buf[i];
    }
  }
  return g;
}

}  // namespace indoormap::formats
