#include "indoormap/draw/labels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <utility>

namespace indoormap::draw {

namespace {

/// The box of size s centred on c (rounded to whole pixels).
cv::Rect label_box_at(const cv::Point2d& c, const cv::Size& s) {
  return {static_cast<int>(std::lround(c.x - s.width / 2.0)),
          static_cast<int>(std::lround(c.y - s.height / 2.0)), s.width, s.height};
}

/// The placed boxes and leader lines, and the test of a candidate against them.
class LabelBoard {
 public:
  LabelBoard(const cv::Rect& area, const std::vector<cv::Rect>& keep_clear,
             const std::vector<LabelRequest>& labels, int gap)
      : area_(area),
        taken_(keep_clear),
        labels_(labels),
        keep_clear_(keep_clear.size()),
        gap_(gap) {}

  /// b (the box of label self) inside the area, clear of every box and leader taken and of the
  /// other labels' anchors; with a leader (a to e), the leader clear of every label box as well
  /// (it may cross a keep-clear box: a line over a marker hides nothing).
  bool free(const cv::Rect& b, std::size_t self, const cv::Point2d* a = nullptr,
            const cv::Point2d* e = nullptr) const {
    if ((b & area_) != b) return false;
    const cv::Rect grown(b.x - gap_, b.y - gap_, b.width + 2 * gap_, b.height + 2 * gap_);
    for (std::size_t j = 0; j < labels_.size(); ++j)
      if (j != self && labels_[j].size_px.area() > 0 &&
          cv::Rect2d(grown).contains(labels_[j].anchor_px))
        return false;
    for (std::size_t t = 0; t < taken_.size(); ++t)
      if ((grown & taken_[t]).area() > 0 || (a && t >= keep_clear_ && crosses(taken_[t], *a, *e)))
        return false;
    for (const auto& [p, q] : leaders_)
      if (crosses(grown, p, q)) return false;
    return true;
  }
  void take(const cv::Rect& b) { taken_.push_back(b); }
  void take_leader(const cv::Point2d& a, const cv::Point2d& e) { leaders_.emplace_back(a, e); }

 private:
  static bool crosses(const cv::Rect& r, cv::Point2d a, cv::Point2d e) {
    cv::Point p(a), q(e);
    return cv::clipLine(r, p, q);
  }
  cv::Rect area_;
  std::vector<cv::Rect> taken_;
  const std::vector<LabelRequest>& labels_;
  std::size_t keep_clear_;  ///< taken_[0, keep_clear_) are the caller's keep-clear boxes
  std::vector<std::pair<cv::Point2d, cv::Point2d>> leaders_;
  int gap_;
};

// Right, left, up, down first (short leaders), then the diagonals.
constexpr std::array<std::array<int, 2>, 8> kLabelDirs = {
    {{1, 0}, {-1, 0}, {0, -1}, {0, 1}, {1, -1}, {-1, -1}, {1, 1}, {-1, 1}}};

}  // namespace

cv::Point2d nearest_on_box(const cv::Rect& b, const cv::Point2d& p) {
  return {std::clamp(p.x, static_cast<double>(b.x), static_cast<double>(b.x + b.width)),
          std::clamp(p.y, static_cast<double>(b.y), static_cast<double>(b.y + b.height))};
}

std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& labels,
                                      const cv::Rect& area_px,
                                      const std::vector<cv::Rect>& keep_clear_px,
                                      const LabelParams& params) {
  std::vector<PlacedLabel> out(labels.size());
  LabelBoard board(area_px, keep_clear_px, labels, std::max(0, params.gap_px));
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const cv::Rect b = label_box_at(labels[i].anchor_px, labels[i].size_px);
    if (labels[i].size_px.area() <= 0 || !board.free(b, i)) continue;
    out[i] = {true, b, false};
    board.take(b);
  }
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const LabelRequest& l = labels[i];
    if (out[i].placed || l.size_px.area() <= 0) continue;
    for (const int r : params.ring_px) {
      for (const auto& d : kLabelDirs) {
        const cv::Point2d c(l.anchor_px.x + d[0] * (l.size_px.width / 2.0 + r),
                            l.anchor_px.y + d[1] * (l.size_px.height / 2.0 + r));
        const cv::Rect b = label_box_at(c, l.size_px);
        const bool leader = r >= params.leader_min_px;
        const cv::Point2d e = nearest_on_box(b, l.anchor_px);
        if (!(leader ? board.free(b, i, &l.anchor_px, &e) : board.free(b, i))) continue;
        out[i] = {true, b, leader};
        board.take(b);
        if (leader) board.take_leader(l.anchor_px, e);
        break;
      }
      if (out[i].placed) break;
    }
  }
  return out;
}

}  // namespace indoormap::draw
