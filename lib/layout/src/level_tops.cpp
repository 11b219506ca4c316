#include "level_tops.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace indoormap::layout::detail {

std::int64_t fill_level_tops(const std::vector<std::int32_t>& lo,
                             const std::vector<std::int32_t>& hi,
                             const std::vector<std::uint8_t>& floor_seen, int w, int h,
                             const LevelTopParams& p, std::vector<std::uint8_t>& occupied,
                             std::vector<std::uint8_t>& raised) {
  if (p.gap_cells <= 0 || w <= 0 || h <= 0) return 0;
  const auto n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  std::vector<std::int32_t> level(n, -1);
  std::int32_t top = -1;
  for (std::size_t i = 0; i < n; ++i)
    if (floor_seen[i] && lo[i] >= p.raised_lo && hi[i] - lo[i] < p.thin_layers) {
      level[i] = lo[i];
      top = std::max(top, lo[i]);
    }
  const cv::Mat disc =
      cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * p.gap_cells + 1, 2 * p.gap_cells + 1});
  std::int64_t added = 0;
  cv::Mat samples(h, w, CV_8U), joined, labels;
  for (std::int32_t l = p.raised_lo; l <= top; ++l) {
    int count = 0;
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) {
        const std::int32_t v = level[static_cast<std::size_t>(r) * w + c];
        const bool s = v == l || v == l + 1;
        samples.at<std::uint8_t>(r, c) = s;
        count += s;
      }
    if (count < p.min_cells) continue;
    cv::morphologyEx(samples, joined, cv::MORPH_CLOSE, disc);
    const int k = cv::connectedComponents(joined, labels, 8, CV_32S);
    std::vector<int> held(static_cast<std::size_t>(k), 0);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c)
        if (samples.at<std::uint8_t>(r, c)) ++held[static_cast<std::size_t>(labels.at<int>(r, c))];
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) {
        const int lab = labels.at<int>(r, c);
        if (lab == 0 || held[static_cast<std::size_t>(lab)] < p.min_cells) continue;
        const std::size_t i = static_cast<std::size_t>(r) * w + c;
        added += !occupied[i];
        occupied[i] = raised[i] = 1;
      }
  }
  return added;
}

}  // namespace indoormap::layout::detail
