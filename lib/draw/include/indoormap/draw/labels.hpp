#pragma once
// Label placement without overlap (objects.png): a greedy placement of text boxes in pixel
// coordinates, free of OpenCV drawing, so that it can be tested on its own.
#include <opencv2/core.hpp>
#include <vector>

namespace indoormap::draw {

/// A label to place: its box's size and the point it names (inside its object).
struct LabelRequest {
  cv::Point2d anchor_px;
  cv::Size size_px;
};

struct LabelParams {
  int gap_px = 2;  ///< free pixels kept between two label boxes
  /// Distances tried between the box's edge and the anchor, nearest first (8 directions each).
  std::vector<int> ring_px = {3, 10, 20, 32, 48, 66, 88, 112};
  /// A box this far or farther from its anchor gets a leader line.
  int leader_min_px = 8;
};

struct PlacedLabel {
  bool placed = false;  ///< false: no free place; the caller lists the label elsewhere
  cv::Rect box_px;      ///< when placed: inside the area, clear of every other placed box
  bool leader = false;  ///< moved away from its anchor: draw a line from the box to the anchor
};

/// Places each label in the first free candidate box: centred on its anchor (first pass, in the
/// order given, so that as many labels as possible sit on their objects), then, for the labels
/// left, beside the anchor in 8 directions at each of params.ring_px (second pass, in the order
/// given). A box is free when it lies inside area_px, no placed box nor keep_clear_px box nor
/// other label's anchor comes within params.gap_px of it and no leader line placed crosses it
/// (so every anchor stays visible and a leader can reach it); a box with a leader needs its
/// leader (anchor to nearest_on_box) clear of every label box as well. One result per request, in
/// order. Deterministic.
std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& labels,
                                      const cv::Rect& area_px,
                                      const std::vector<cv::Rect>& keep_clear_px = {},
                                      const LabelParams& params = {});

/// The point of box nearest to p (p itself when inside): where a leader line meets the box.
cv::Point2d nearest_on_box(const cv::Rect& box, const cv::Point2d& p);

}  // namespace indoormap::draw
