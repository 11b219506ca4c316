#include "indoormap/draw/explore_png.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "font.hpp"
#include "indoormap/draw/canvas.hpp"
#include "indoormap/draw/palette.hpp"

namespace indoormap::draw {

namespace {

const cv::Scalar kPath(200, 90, 20);  // BGR: blue
const cv::Scalar kStart(0, 0, 220);
const cv::Scalar kRobot(40, 160, 0);

/// The cells north up, one pixel per cell, in the palette's colours.
cv::Mat cells_image(const Grid<Cell>& cells) {
  cv::Mat img(std::max(cells.height, 1), std::max(cells.width, 1), CV_8UC3,
              cv::Scalar(255, 255, 255));
  for (int r = 0; r < cells.height; ++r)
    for (int c = 0; c < cells.width; ++c) {
      const cv::Scalar col = cell_colour(cells.at(c, r));
      img.at<cv::Vec3b>(cells.height - 1 - r, c) = cv::Vec3b(
          static_cast<uchar>(col[0]), static_cast<uchar>(col[1]), static_cast<uchar>(col[2]));
    }
  return img;
}

/// Pixel of a map point in a panel of s pixels per cell whose top-left corner is at origin.
cv::Point panel_px(const GridGeometry& g, int rows, double s, const Eigen::Vector2d& p,
                   cv::Point origin) {
  const Eigen::Vector2d c = g.to_cell_coords(p);
  return origin + cv::Point(static_cast<int>(std::lround(c.x() * s)),
                            static_cast<int>(std::lround((rows - c.y()) * s)));
}

/// Draws one panel (cells scaled to s pixels per cell, the path, the robot) at origin.
void draw_panel(cv::Mat& img, const ExplorePanel& p, const GridGeometry& g, double s,
                cv::Point origin, int thickness) {
  const cv::Mat cells = cells_image(p.cells);
  const cv::Size size(std::max(1, static_cast<int>(std::lround(cells.cols * s))),
                      std::max(1, static_cast<int>(std::lround(cells.rows * s))));
  cv::Mat scaled;
  cv::resize(cells, scaled, size, 0, 0, s >= 1.0 ? cv::INTER_NEAREST : cv::INTER_AREA);
  const cv::Rect roi(origin.x, origin.y, std::min(size.width, img.cols - origin.x),
                     std::min(size.height, img.rows - origin.y));
  scaled(cv::Rect(0, 0, roi.width, roi.height)).copyTo(img(roi));
  std::vector<cv::Point> px;
  px.reserve(p.path_m.size());
  for (const auto& q : p.path_m) px.push_back(panel_px(g, p.cells.height, s, q, origin));
  if (px.size() >= 2)
    cv::polylines(img, std::vector<std::vector<cv::Point>>{px}, false, kPath, thickness,
                  cv::LINE_AA);
  cv::circle(img, panel_px(g, p.cells.height, s, p.robot_m, origin), std::max(3, 2 * thickness),
             kRobot, cv::FILLED, cv::LINE_AA);
}

/// The class swatches, path, start, robot and scale bar below a picture.
void draw_legend(cv::Mat& img, int y0, int bar_px, bool with_start) {
  LegendStyle style;
  style.bar_ticks = true;
  Legend legend(img, y0, style);
  for (Cell c : {Cell::kWall, Cell::kFree, Cell::kUnknown})
    legend.swatch(cell_colour(c), std::string(to_string(c)));
  legend.stroke(kPath, 3, "path");
  if (with_start)
    legend.item("start", [&](cv::Rect rc) { draw_cross(img, {rc.x + 8, rc.y + 8}, 6, kStart); });
  legend.item("robot", [&](cv::Rect rc) {
    cv::circle(img, {rc.x + 8, rc.y + 8}, 5, kRobot, cv::FILLED, cv::LINE_AA);
  });
  legend.scale_bar(bar_px);
}

}  // namespace

void write_explore_png(const std::filesystem::path& path, const ExplorePanel& final_map,
                       const GridGeometry& g, const Eigen::Vector2d& start_m,
                       const std::string& title) {
  const int w = std::max(final_map.cells.width, 1), h = std::max(final_map.cells.height, 1);
  const int k = pixels_per_cell(w, h, 640, 1600);
  const int title_h = 28, legend_h = 44;
  cv::Mat img(title_h + h * k + legend_h, std::max(w * k, 600), CV_8UC3, cv::Scalar(255, 255, 255));
  draw_panel(img, final_map, g, k, {0, title_h}, 2);
  draw_cross(img, panel_px(g, h, k, start_m, {0, title_h}), std::max(6, 2 * k), kStart);
  cv::putText(img, title, {6, 20}, kFont, 0.55, {0, 0, 0}, 1, cv::LINE_AA);
  draw_legend(img, title_h + h * k + 10, static_cast<int>(std::lround(k / g.cell_m())), true);
  write_png(path, img);
}

void write_explore_strip_png(const std::filesystem::path& path,
                             const std::vector<ExplorePanel>& panels, const GridGeometry& g,
                             const std::string& title, int panel_width_px) {
  const int w = std::max(g.width(), 1), h = std::max(g.height(), 1);
  // Scale: panel_width_px wide, but no panel taller than 1.5 times that.
  const double s = std::min(static_cast<double>(panel_width_px) / w, 1.5 * panel_width_px / h);
  const int pw = static_cast<int>(std::lround(w * s)), ph = static_cast<int>(std::lround(h * s));
  const int gap = 10, title_h = 28, caption_h = 20, legend_h = 44;
  const int n = static_cast<int>(panels.size());
  const int img_w = std::max(n * pw + (n + 1) * gap, 600);
  cv::Mat img(title_h + caption_h + ph + legend_h, img_w, CV_8UC3, cv::Scalar(255, 255, 255));
  cv::putText(img, title, {6, 20}, kFont, 0.55, {0, 0, 0}, 1, cv::LINE_AA);
  for (int i = 0; i < n; ++i) {
    const int x = gap + i * (pw + gap);
    cv::putText(img, panels[i].caption, {x, title_h + 14}, kFont, 0.42, {0, 0, 0}, 1, cv::LINE_AA);
    draw_panel(img, panels[i], g, s, {x, title_h + caption_h}, 1);
    cv::rectangle(img, cv::Rect(x - 1, title_h + caption_h - 1, pw + 2, ph + 2), {120, 120, 120});
  }
  draw_legend(img, title_h + caption_h + ph + 10, static_cast<int>(std::lround(s / g.cell_m())),
              false);
  write_png(path, img);
}

}  // namespace indoormap::draw
