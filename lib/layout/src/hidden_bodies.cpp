#include "hidden_bodies.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "indoormap/core/cell.hpp"

namespace indoormap::layout::detail {

Grid<std::uint8_t> hidden_bodies(const Grid<std::uint8_t>& seen, const Grid<std::uint8_t>& tall,
                                 const Grid<std::uint8_t>& walls, double cell_m,
                                 double max_depth_m) {
  const int w = seen.width, h = seen.height;
  Grid<std::uint8_t> out(w, h, 0);
  if (max_depth_m <= 0 || w == 0 || h == 0 || tall.width != w || tall.height != h) return out;
  // The nearest wall cell of every cell (labels of the distance transform to the walls).
  cv::Mat no_wall(h, w, CV_8U), dist, label;
  bool any_wall = false;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      no_wall.at<std::uint8_t>(r, c) = walls.at(c, r) ? 0 : 1;
      any_wall = any_wall || walls.at(c, r);
    }
  if (!any_wall) return out;
  cv::distanceTransform(no_wall, dist, label, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
  std::vector<CellIndex> wall_of(1, CellIndex{});
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (walls.at(c, r)) {
        const auto l = static_cast<std::size_t>(label.at<int>(r, c));
        if (l >= wall_of.size()) wall_of.resize(l + 1);
        wall_of[l] = {c, r};
      }
  // From each tall cell with a wall within max_depth_m, straight to that wall: the cells between
  // are the body when the scan saw the floor of none of them (a seen floor: a gap, no body).
  const double reach = max_depth_m / cell_m + 0.5;
  cv::Mat body(h, w, CV_8U, cv::Scalar(0));
  std::vector<CellIndex> run;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      if (!tall.at(c, r) || dist.at<float>(r, c) > reach) continue;
      const CellIndex to = wall_of[static_cast<std::size_t>(label.at<int>(r, c))];
      const int n = std::max(std::abs(to.col - c), std::abs(to.row - r));
      run.clear();
      bool gap = false;
      for (int k = 1; k < n && !gap; ++k) {
        const int cc = static_cast<int>(std::lround(c + (to.col - c) * static_cast<double>(k) / n));
        const int rr = static_cast<int>(std::lround(r + (to.row - r) * static_cast<double>(k) / n));
        if (walls.at(cc, rr)) break;
        gap = seen.at(cc, rr) != 0;
        if (!tall.at(cc, rr)) run.push_back({cc, rr});
      }
      if (gap || run.empty()) continue;
      for (const auto& q : run) out.at(q) = 1;
      cv::line(body, {c, r}, {run.back().col, run.back().row}, cv::Scalar(1), 3, cv::LINE_8);
    }
  // Lines from neighbouring face cells to their nearest wall cells diverge and leave unmarked
  // cells between them, through which the flood ran into the body: each line counts three
  // cells wide, over cells the scan did not see.
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (body.at<std::uint8_t>(r, c) && !seen.at(c, r) && !tall.at(c, r) && !walls.at(c, r))
        out.at(c, r) = 1;
  return out;
}

}  // namespace indoormap::layout::detail
