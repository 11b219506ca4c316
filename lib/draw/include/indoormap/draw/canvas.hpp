#pragma once
// The drawing layer's common parts: the world-to-pixel transform of a north-up grid picture,
// cells, markers, the legend with its scale bar, and atomic PNG writing.
#include <Eigen/Core>
#include <filesystem>
#include <functional>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "indoormap/core/grid.hpp"

namespace indoormap::draw {

/// The integer number of pixels per cell that brings a w x h grid to at least min_width_px wide,
/// capped so that the longer side stays within about max_side_px (at least 1).
int pixels_per_cell(int w, int h, int min_width_px, int max_side_px = 4000);

/// A grid drawn north up, scale_px pixels per cell, its top row top_px below the image's top.
struct PixelFrame {
  GridGeometry geometry;
  int scale_px = 1;
  int top_px = 0;
  int rows = 0;  ///< grid rows drawn (the image row of map y is top_px + (rows - cell y) * scale)

  /// Continuous pixel coordinates of a map point (before adding top_px).
  Eigen::Vector2d exact(const Eigen::Vector2d& p_map) const {
    const Eigen::Vector2d c = geometry.to_cell_coords(p_map);
    return {c.x() * scale_px, (rows - c.y()) * scale_px};
  }
  /// The pixel of a map point, rounded to the nearest.
  cv::Point to_px(const Eigen::Vector2d& p_map) const;
  /// The pixel block of cell (col, row).
  cv::Rect cell_rect(int col, int row) const {
    return {col * scale_px, top_px + (rows - 1 - row) * scale_px, scale_px, scale_px};
  }
};

/// An x-shaped cross of half-width arm_px, 2 px thick (scanner positions).
void draw_cross(cv::Mat& img, cv::Point p, int arm_px, const cv::Scalar& colour);

/// Layout of a legend row: each entry is a 16 px symbol and its label, advancing by
/// gap_px + label length * char_px.
struct LegendStyle {
  double font_scale = 0.45;
  int char_px = 9;
  int gap_px = 26;
  /// 0: one row. Otherwise an entry starts a new row (row_px lower) when x + wrap_reserve_px +
  /// label length * char_px passes the image's width.
  int wrap_reserve_px = 0;
  int row_px = 24;
  bool bar_ticks = false;    ///< end ticks on the scale bar
  bool bar_must_fit = true;  ///< false: the bar is drawn even where it passes the image's edge
};

/// A legend row at (6, y0_px) on img.
class Legend {
 public:
  Legend(cv::Mat& img, int y0_px, LegendStyle style);
  /// A symbol drawn into the 16 x 16 box, and its label.
  void item(const std::string& label, const std::function<void(cv::Rect)>& symbol);
  /// A filled box with a black frame.
  void swatch(const cv::Scalar& colour, const std::string& label);
  /// A horizontal line across the box.
  void stroke(const cv::Scalar& colour, int thickness_px, const std::string& label);
  /// A 1 m scale bar of bar_px pixels with its label "1 m", when bar_px > 4.
  void scale_bar(int bar_px);
  /// The first pixel row below the entries drawn so far (their row's top + row_px).
  int bottom_px() const { return y0_ + style_.row_px; }

 private:
  cv::Mat& img_;
  LegendStyle style_;
  int x_ = 6, y0_;
};

/// A table below a legend (objects.png: the objects whose label found no place on the map): a
/// title line, a header and rows of text cells, the rows in blocks side by side when there are
/// many.
struct LegendTable {
  std::string title;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<int> col_px;  ///< width of each column
  int row_px = 18;

  /// The height the table takes in an image width_px wide; 0 without rows.
  int height_px(int width_px) const;
  /// Draws it with its top at y0_px (nothing without rows).
  void draw(cv::Mat& img, int y0_px) const;

 private:
  int blocks(int width_px) const;
};

/// Encodes img (8-bit grey or BGR) as PNG (formats::encode_png; level: zlib's 0-9, 1 fast) and
/// writes it atomically. Throws OutputError.
void write_png(const std::filesystem::path& path, const cv::Mat& img, int level = 1);

}  // namespace indoormap::draw
