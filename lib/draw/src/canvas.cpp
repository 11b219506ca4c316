#include "indoormap/draw/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "font.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/formats/png.hpp"

namespace indoormap::draw {

int pixels_per_cell(int w, int h, int min_width_px, int max_side_px) {
  const int k = std::max(1, (min_width_px + w - 1) / w);
  return std::min(k, std::max(1, max_side_px / std::max(w, h)));
}

cv::Point PixelFrame::to_px(const Eigen::Vector2d& p_map) const {
  const Eigen::Vector2d e = exact(p_map);
  return cv::Point(static_cast<int>(std::lround(e.x())),
                   top_px + static_cast<int>(std::lround(e.y())));
}

void draw_cross(cv::Mat& img, cv::Point p, int arm, const cv::Scalar& col) {
  cv::line(img, p - cv::Point(arm, arm), p + cv::Point(arm, arm), col, 2, cv::LINE_AA);
  cv::line(img, p - cv::Point(arm, -arm), p + cv::Point(arm, -arm), col, 2, cv::LINE_AA);
}

Legend::Legend(cv::Mat& img, int y0_px, LegendStyle style) : img_(img), style_(style), y0_(y0_px) {}

void Legend::item(const std::string& label, const std::function<void(cv::Rect)>& symbol) {
  const int len = static_cast<int>(label.size());
  if (style_.wrap_reserve_px > 0 &&
      x_ + style_.wrap_reserve_px + len * style_.char_px > img_.cols) {
    x_ = 6;
    y0_ += style_.row_px;
  }
  symbol(cv::Rect(x_, y0_, 16, 16));
  cv::putText(img_, label, {x_ + 20, y0_ + 13}, kFont, style_.font_scale, {0, 0, 0}, 1,
              cv::LINE_AA);
  x_ += style_.gap_px + len * style_.char_px;
}

void Legend::swatch(const cv::Scalar& col, const std::string& label) {
  item(label, [&](cv::Rect rc) {
    cv::rectangle(img_, rc, col, cv::FILLED);
    cv::rectangle(img_, rc, {0, 0, 0}, 1);
  });
}

void Legend::stroke(const cv::Scalar& col, int t, const std::string& label) {
  item(label, [&](cv::Rect rc) {
    cv::line(img_, {rc.x, rc.y + 8}, {rc.x + 16, rc.y + 8}, col, t, cv::LINE_AA);
  });
}

void Legend::scale_bar(int bar) {
  const int w = img_.cols;
  if (style_.bar_must_fit) {
    if (style_.wrap_reserve_px > 0 && x_ + bar + 40 > w) {
      x_ = 6;
      y0_ += style_.row_px;
    }
    if (!(bar > 4 && x_ + bar + 40 < w)) return;
  } else {
    if (bar <= 4) return;
    if (style_.wrap_reserve_px > 0 && x_ + bar + 40 > w) {
      x_ = 6;
      y0_ += style_.row_px;
    }
  }
  const int x = x_, y0 = y0_;
  cv::line(img_, {x, y0 + 12}, {x + bar, y0 + 12}, {0, 0, 0}, 2);
  if (style_.bar_ticks) {
    cv::line(img_, {x, y0 + 6}, {x, y0 + 16}, {0, 0, 0}, 1);
    cv::line(img_, {x + bar, y0 + 6}, {x + bar, y0 + 16}, {0, 0, 0}, 1);
  }
  cv::putText(img_, "1 m", {x + bar + 6, y0 + 16}, kFont, style_.font_scale, {0, 0, 0}, 1,
              cv::LINE_AA);
}

int LegendTable::blocks(int width_px) const {
  int block_w = 16;
  for (const int w : col_px) block_w += w;
  return std::max(1, (width_px - 6) / block_w);
}

int LegendTable::height_px(int width_px) const {
  if (rows.empty()) return 0;
  const int n = static_cast<int>(rows.size()), b = blocks(width_px);
  return row_px * (2 + (n + b - 1) / b) + 6;
}

void LegendTable::draw(cv::Mat& img, int y0_px) const {
  if (rows.empty()) return;
  const int n = static_cast<int>(rows.size()), b = blocks(img.cols);
  const int per_block = (n + b - 1) / b;
  const auto text = [&](const std::string& t, int x, int y) {
    cv::putText(img, t, {x, y}, kFont, 0.42, {0, 0, 0}, 1, cv::LINE_AA);
  };
  text(title, 6, y0_px + row_px - 5);
  int block_w = 16;
  for (const int w : col_px) block_w += w;
  for (int k = 0; k < b && k * per_block < n; ++k) {
    const int x0 = 6 + k * block_w;
    for (int r = -1; r < per_block && k * per_block + r < n; ++r) {
      const auto& cells = r < 0 ? header : rows[static_cast<std::size_t>(k * per_block + r)];
      const int y = y0_px + row_px * (r + 3) - 5;
      int x = x0;
      for (std::size_t c = 0; c < cells.size() && c < col_px.size(); ++c) {
        text(cells[c], x, y);
        x += col_px[c];
      }
      if (r < 0) cv::line(img, {x0, y + 4}, {x - 8, y + 4}, {0, 0, 0}, 1);
    }
  }
}

void write_png(const std::filesystem::path& path, const cv::Mat& img, int level) {
  if (img.depth() != CV_8U || !(img.channels() == 1 || img.channels() == 3))
    throw OutputError(path.string(), "PNG encoding: not an 8-bit grey or colour picture");
  write_file_atomic(
      path, formats::encode_png({img.data, img.cols, img.rows, img.channels(), 8, img.step[0]},
                                level, path.string()));
}

}  // namespace indoormap::draw
