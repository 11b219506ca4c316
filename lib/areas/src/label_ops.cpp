#include "label_ops.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <unordered_map>

namespace indoormap::areas::detail {

cv::Mat clearance(const Grid<std::uint8_t>& free) {
  // One obstacle cell of padding: the grid's edge is an obstacle.
  cv::Mat padded(free.height + 2, free.width + 2, CV_8U, cv::Scalar(0));
  for (int r = 0; r < free.height; ++r)
    for (int c = 0; c < free.width; ++c)
      padded.at<std::uint8_t>(r + 1, c + 1) = free.at(c, r) ? 255 : 0;
  cv::Mat d;
  cv::distanceTransform(padded, d, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  return d(cv::Rect(1, 1, free.width, free.height)).clone();
}

void fill_unlabelled(Grid<int>& labels, const Grid<std::uint8_t>& mask) {
  const int w = labels.width, h = labels.height;
  std::vector<int> queue;
  queue.reserve(labels.size() / 4);
  for (int i = 0; i < static_cast<int>(labels.size()); ++i)
    if (labels.data[i] > 0) queue.push_back(i);
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int i = queue[head], c = i % w, r = i / w;
    const int nb[4][2] = {{c + 1, r}, {c - 1, r}, {c, r + 1}, {c, r - 1}};
    for (const auto& n : nb) {
      if (n[0] < 0 || n[1] < 0 || n[0] >= w || n[1] >= h) continue;
      const int j = n[1] * w + n[0];
      if (labels.data[j] == 0 && mask.data[j]) {
        labels.data[j] = labels.data[i];
        queue.push_back(j);
      }
    }
  }
}

int compact(Grid<int>& labels) {
  std::unordered_map<int, int> map;
  for (int& v : labels.data) {
    if (v <= 0) {
      v = 0;
      continue;
    }
    auto [it, inserted] = map.try_emplace(v, static_cast<int>(map.size()) + 1);
    v = it->second;
  }
  return static_cast<int>(map.size());
}

std::vector<int> label_sizes(const Grid<int>& labels) {
  int top = 0;
  for (int v : labels.data) top = std::max(top, v);
  std::vector<int> n(static_cast<std::size_t>(top) + 1, 0);
  for (int v : labels.data)
    if (v > 0) ++n[v];
  return n;
}

void keep_largest_pieces(Grid<int>& labels, const Grid<std::uint8_t>& mask) {
  // Pieces: 4-connected components of equal label.
  const int w = labels.width, h = labels.height;
  Grid<int> piece(w, h, 0);
  std::vector<int> piece_label{0}, piece_size{0}, stack;
  for (int i = 0; i < static_cast<int>(labels.size()); ++i) {
    if (labels.data[i] == 0 || piece.data[i]) continue;
    const int id = static_cast<int>(piece_label.size()), lab = labels.data[i];
    piece_label.push_back(lab);
    piece_size.push_back(0);
    stack.assign(1, i);
    piece.data[i] = id;
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      ++piece_size[id];
      const int c = k % w, r = k / w;
      const int nb[4][2] = {{c + 1, r}, {c - 1, r}, {c, r + 1}, {c, r - 1}};
      for (const auto& n : nb) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= w || n[1] >= h) continue;
        const int j = n[1] * w + n[0];
        if (labels.data[j] == lab && !piece.data[j]) {
          piece.data[j] = id;
          stack.push_back(j);
        }
      }
    }
  }
  std::unordered_map<int, int> best;  // label -> piece
  for (int p = 1; p < static_cast<int>(piece_label.size()); ++p) {
    auto it = best.find(piece_label[p]);
    if (it == best.end() || piece_size[p] > piece_size[it->second]) best[piece_label[p]] = p;
  }
  Grid<int> before = labels;
  for (int i = 0; i < static_cast<int>(labels.size()); ++i)
    if (labels.data[i] && best[labels.data[i]] != piece.data[i]) labels.data[i] = 0;
  fill_unlabelled(labels, mask);
  // Pieces no neighbour reached keep their own (new) label.
  int next = 0;
  for (int v : before.data) next = std::max(next, v);
  std::unordered_map<int, int> fresh;
  for (int i = 0; i < static_cast<int>(labels.size()); ++i)
    if (before.data[i] && labels.data[i] == 0) {
      auto [it, ins] = fresh.try_emplace(piece.data[i], next + 1);
      if (ins) ++next;
      labels.data[i] = it->second;
    }
}

int merge_small(Grid<int>& labels, const Grid<std::uint8_t>& mask, int min_cells) {
  // Smallest first, a few rounds: a small piece between two small pieces ends in a big one.
  for (int round = 0; round < 4; ++round) {
    const std::vector<int> n = label_sizes(labels);
    Grid<int> before = labels;
    bool any = false;
    for (int& v : labels.data)
      if (v > 0 && n[v] < min_cells) {
        v = 0;
        any = true;
      }
    if (!any) break;
    fill_unlabelled(labels, mask);
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (before.data[i] && labels.data[i] == 0) labels.data[i] = before.data[i];
  }
  return compact(labels);
}

}  // namespace indoormap::areas::detail
