#include "indoormap/areas/score.hpp"

#include <algorithm>
#include <map>

#include "indoormap/core/errors.hpp"

namespace indoormap::areas {

SegmentationScore score_segmentation(const Grid<int>& truth, const Grid<int>& found) {
  if (truth.width != found.width || truth.height != found.height)
    throw UsageError("score: ground truth is " + std::to_string(truth.width) + " x " +
                     std::to_string(truth.height) + ", the segmented map " +
                     std::to_string(found.width) + " x " + std::to_string(found.height));
  int nt = 0, nf = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    nt = std::max(nt, truth.data[i]);
    nf = std::max(nf, found.data[i]);
  }
  std::map<std::pair<int, int>, int> overlap;
  std::vector<int> size_t_(nt + 1, 0), size_f(nf + 1, 0);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const int t = truth.data[i], f = found.data[i];
    if (t <= 0 || f <= 0) continue;
    ++overlap[{t, f}];
    ++size_t_[t];
    ++size_f[f];
  }
  std::vector<int> best_t(nt + 1, 0), best_f(nf + 1, 0);
  for (const auto& [k, n] : overlap) {
    best_t[k.first] = std::max(best_t[k.first], n);
    best_f[k.second] = std::max(best_f[k.second], n);
  }
  SegmentationScore s;
  s.room_recall.assign(nt, 0.0);
  s.area_precision.assign(nf, 0.0);
  double sum_r = 0.0, sum_p = 0.0;
  for (int t = 1; t <= nt; ++t)
    if (size_t_[t] > 0) {
      s.room_recall[t - 1] = static_cast<double>(best_t[t]) / size_t_[t];
      sum_r += s.room_recall[t - 1];
      ++s.true_rooms;
    }
  for (int f = 1; f <= nf; ++f)
    if (size_f[f] > 0) {
      s.area_precision[f - 1] = static_cast<double>(best_f[f]) / size_f[f];
      sum_p += s.area_precision[f - 1];
      ++s.areas;
    }
  s.recall = s.true_rooms ? sum_r / s.true_rooms : 0.0;
  s.precision = s.areas ? sum_p / s.areas : 0.0;
  return s;
}

Grid<int> truth_rooms(const Grid<std::uint8_t>& grey, int free_min, int min_cells) {
  const int w = grey.width, h = grey.height;
  Grid<int> labels(w, h, 0);
  std::vector<int> stack, cells;
  int next = 0;
  for (int i = 0; i < static_cast<int>(grey.size()); ++i) {
    if (grey.data[i] < free_min || labels.data[i]) continue;
    ++next;
    cells.clear();
    stack.assign(1, i);
    labels.data[i] = next;
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      cells.push_back(k);
      const int c = k % w, r = k / w;
      const int nb[4][2] = {{c + 1, r}, {c - 1, r}, {c, r + 1}, {c, r - 1}};
      for (const auto& n : nb) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= w || n[1] >= h) continue;
        const int j = n[1] * w + n[0];
        if (grey.data[j] >= free_min && !labels.data[j]) {
          labels.data[j] = next;
          stack.push_back(j);
        }
      }
    }
    if (static_cast<int>(cells.size()) < min_cells) {
      for (int k : cells) labels.data[k] = -1;  // too small: marked, never a room
      --next;
    }
  }
  for (int& v : labels.data) v = std::max(v, 0);
  return labels;
}

}  // namespace indoormap::areas
