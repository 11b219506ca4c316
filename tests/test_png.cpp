// PNG through libpng (formats/png.hpp) against OpenCV's codecs as the reference, and the PGM
// reader's plain and 16-bit files (map images).
#include <gtest/gtest.h>

#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "indoormap/core/errors.hpp"
#include "indoormap/formats/pgm.hpp"
#include "indoormap/formats/png.hpp"
#include "test_support.hpp"

using namespace indoormap;

namespace {

cv::Mat decode(const std::string& bytes, int flags) {
  return cv::imdecode(std::vector<unsigned char>(bytes.begin(), bytes.end()), flags);
}

// A 7 x 5 picture whose values differ from pixel to pixel and channel to channel.
cv::Mat pattern(int type) {
  cv::Mat m(5, 7, type);
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols * m.channels(); ++c) {
      const int v = 37 * r + 11 * c + 3;
      if (m.depth() == CV_16U)
        m.ptr<std::uint16_t>(r)[c] = static_cast<std::uint16_t>(v * 251);
      else
        m.ptr<std::uint8_t>(r)[c] = static_cast<std::uint8_t>(v);
    }
  return m;
}

formats::ImageView view(const cv::Mat& m) {
  return {m.data, m.cols, m.rows, m.channels(), m.depth() == CV_16U ? 16 : 8, m.step[0]};
}

}  // namespace

// What the pictures and the label PNGs write, OpenCV reads back exactly: grey, BGR, 16-bit.
TEST(Png, EncodedImagesDecodeExactlyInOpenCv) {
  for (const int type : {CV_8UC1, CV_8UC3, CV_16UC1}) {
    const cv::Mat m = pattern(type);
    for (const int level : {1, 9}) {
      const cv::Mat back =
          decode(formats::encode_png(view(m), level, "test"), cv::IMREAD_UNCHANGED);
      ASSERT_EQ(back.type(), type);
      EXPECT_EQ(cv::norm(back, m, cv::NORM_INF), 0.0) << "type " << type << " level " << level;
    }
  }
  EXPECT_THROW(formats::encode_png({nullptr, 3, 3, 1, 8, 3}, 1, "x"), OutputError);
  EXPECT_THROW(formats::encode_png(view(pattern(CV_8UC1)), 10, "x"), OutputError);
}

// Map images as OpenCV's IMREAD_GRAYSCALE reads them: colour to grey (0.299 R + 0.587 G + 0.114
// B, within one level of rounding), alpha dropped, 16-bit to its high byte; 16-bit kept for the
// label PNGs.
TEST(Png, DecodesToGreyAsOpenCvDoes) {
  const auto dir = test::scratch_dir();
  for (const int type : {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1}) {
    const auto file = dir / ("t" + std::to_string(type) + ".png");
    ASSERT_TRUE(cv::imwrite(file.string(), pattern(type)));
    const formats::GreyImage g = formats::read_png_grey(file, false, 1000);
    const cv::Mat ref = cv::imread(file.string(), cv::IMREAD_GRAYSCALE);
    ASSERT_EQ(g.width, ref.cols);
    ASSERT_EQ(g.height, ref.rows);
    for (int r = 0; r < ref.rows; ++r)
      for (int c = 0; c < ref.cols; ++c)
        EXPECT_NEAR(g.pixels[static_cast<std::size_t>(r) * g.width + c], ref.at<std::uint8_t>(r, c),
                    1)
            << "type " << type << " at " << c << ", " << r;
  }
  const auto f16 = dir / ("t" + std::to_string(CV_16UC1) + ".png");
  const formats::GreyImage wide = formats::read_png_grey(f16, true, 1000);
  EXPECT_EQ(wide.pixels[8], pattern(CV_16UC1).at<std::uint16_t>(1, 1));
}

TEST(Png, BadFilesAreInputErrorsNamingTheFile) {
  const auto dir = test::scratch_dir();
  test::write_text(dir / "text.png", "not a png at all");
  const std::string good = formats::encode_png(view(pattern(CV_8UC1)), 1, "x");
  test::write_text(dir / "cut.png", good.substr(0, good.size() / 2));
  for (const char* name : {"text.png", "cut.png", "missing.png"}) {
    try {
      formats::read_png_grey(dir / name, false, 1000);
      ADD_FAILURE() << name << " was read";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), (dir / name).string());
    }
  }
  test::write_text(dir / "big.png", good);  // 35 pixels, above a budget of 20
  EXPECT_THROW(formats::read_png_grey(dir / "big.png", false, 20), InputError);
}

// A 16-bit P5 map image and a plain P2 one (maxval 15) read as 0..255.
TEST(Pgm, SixteenBitAndPlainFilesScaleTo255) {
  const auto dir = test::scratch_dir();
  test::write_text(dir / "wide.pgm", std::string("P5\n2 1\n65535\n\xff\xff\x80\x00", 18));
  const Grid<std::uint8_t> wide = formats::read_pgm(dir / "wide.pgm", false);
  EXPECT_EQ(wide.at(0, 0), 255);
  EXPECT_EQ(wide.at(1, 0), 128);
  test::write_text(dir / "plain.pgm", "P2\n# a comment\n3 1\n15\n0 15 5\n");
  const Grid<std::uint8_t> plain = formats::read_pgm(dir / "plain.pgm", false);
  EXPECT_EQ(plain.at(0, 0), 0);
  EXPECT_EQ(plain.at(1, 0), 255);
  EXPECT_EQ(plain.at(2, 0), 85);
  test::write_text(dir / "short.pgm", "P2\n3 1\n15\n0 15\n");
  EXPECT_THROW(formats::read_pgm(dir / "short.pgm", false), InputError);
}
