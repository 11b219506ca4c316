// Skeletons: Zhang-Suen thinning (Zhang and Suen, CACM 1984), spur pruning, walks along it.
#include <cmath>
#include <functional>
#include <opencv2/core.hpp>
#include <queue>
#include <vector>

#include "corridors.hpp"

namespace indoormap::areas::detail {

Reach skeleton_reach(const cv::Mat& skel, cv::Point start, double k, cv::Mat& dist) {
  // dist: CV_32F scratch of skel's size, all negative (unvisited) on entry and on return.
  Reach out;
  using Item = std::pair<float, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  std::vector<cv::Point> touched{start};
  dist.at<float>(start) = 0.0f;
  queue.push({0.0f, start.y * skel.cols + start.x});
  while (!queue.empty()) {
    const auto [dp, idx] = queue.top();
    queue.pop();
    const cv::Point p(idx % skel.cols, idx / skel.cols);
    if (dp > dist.at<float>(p)) continue;
    if (dp >= k) {
      out.rim.push_back(p);
      continue;
    }
    out.within.push_back(p);
    for (const auto& d : kNb) {
      const cv::Point q(p.x + d[0], p.y + d[1]);
      if (q.x < 0 || q.y < 0 || q.x >= skel.cols || q.y >= skel.rows) continue;
      if (!skel.at<std::uint8_t>(q)) continue;
      const float nd = dp + ((d[0] && d[1]) ? 1.41421356f : 1.0f);
      float& dq = dist.at<float>(q);
      if (dq >= 0.0f && dq <= nd) continue;
      if (dq < 0.0f) touched.push_back(q);
      dq = nd;
      queue.push({nd, q.y * skel.cols + q.x});
    }
  }
  for (const auto& p : touched) dist.at<float>(p) = -1.0f;
  return out;
}

/// Groups rim cells into arms (8-adjacent cells belong to one arm); returns each arm's mean.
std::vector<cv::Point2d> arms(const std::vector<cv::Point>& rim) {
  std::vector<int> group(rim.size(), -1);
  std::vector<cv::Point2d> mean;
  std::vector<int> count;
  for (std::size_t i = 0; i < rim.size(); ++i) {
    if (group[i] >= 0) continue;
    const int g = static_cast<int>(mean.size());
    mean.emplace_back(0, 0);
    count.push_back(0);
    std::vector<std::size_t> stack{i};
    group[i] = g;
    while (!stack.empty()) {
      const std::size_t a = stack.back();
      stack.pop_back();
      mean[g] += cv::Point2d(rim[a]);
      ++count[g];
      for (std::size_t b = 0; b < rim.size(); ++b)
        if (group[b] < 0 && std::abs(rim[a].x - rim[b].x) <= 1 &&
            std::abs(rim[a].y - rim[b].y) <= 1) {
          group[b] = g;
          stack.push_back(b);
        }
    }
  }
  for (std::size_t g = 0; g < mean.size(); ++g) mean[g] *= 1.0 / count[g];
  return mean;
}

/// Removes end cells `times` times (spurs shorter than that vanish).
void prune(cv::Mat& skel, int times) {
  std::vector<cv::Point> ends;
  for (int t = 0; t < times; ++t) {
    ends.clear();
    for (int r = 1; r + 1 < skel.rows; ++r)
      for (int c = 1; c + 1 < skel.cols; ++c) {
        if (!skel.at<std::uint8_t>(r, c)) continue;
        int n = 0;
        for (const auto& d : kNb) n += skel.at<std::uint8_t>(r + d[1], c + d[0]);
        if (n <= 1) ends.emplace_back(c, r);
      }
    if (ends.empty()) return;
    for (const auto& p : ends) skel.at<std::uint8_t>(p) = 0;
  }
}

void thin(cv::Mat& img) {
  // img: CV_8U, 0/1, with a zero border (the callers pad their crops).
  std::vector<cv::Point> del;
  bool changed = true;
  while (changed) {
    changed = false;
    for (int pass = 0; pass < 2; ++pass) {
      del.clear();
      for (int r = 1; r + 1 < img.rows; ++r)
        for (int c = 1; c + 1 < img.cols; ++c) {
          if (!img.at<std::uint8_t>(r, c)) continue;
          const int p2 = img.at<std::uint8_t>(r - 1, c), p3 = img.at<std::uint8_t>(r - 1, c + 1),
                    p4 = img.at<std::uint8_t>(r, c + 1), p5 = img.at<std::uint8_t>(r + 1, c + 1),
                    p6 = img.at<std::uint8_t>(r + 1, c), p7 = img.at<std::uint8_t>(r + 1, c - 1),
                    p8 = img.at<std::uint8_t>(r, c - 1), p9 = img.at<std::uint8_t>(r - 1, c - 1);
          const int b = p2 + p3 + p4 + p5 + p6 + p7 + p8 + p9;
          if (b < 2 || b > 6) continue;
          const int a = (!p2 && p3) + (!p3 && p4) + (!p4 && p5) + (!p5 && p6) + (!p6 && p7) +
                        (!p7 && p8) + (!p8 && p9) + (!p9 && p2);
          if (a != 1) continue;
          if (pass == 0 && ((p2 && p4 && p6) || (p4 && p6 && p8))) continue;
          if (pass == 1 && ((p2 && p4 && p8) || (p2 && p6 && p8))) continue;
          del.emplace_back(c, r);
        }
      for (const auto& q : del) img.at<std::uint8_t>(q) = 0;
      changed = changed || !del.empty();
    }
  }
}

}  // namespace indoormap::areas::detail
