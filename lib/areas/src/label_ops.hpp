#pragma once
// Label-grid operations shared by the area steps (internal to im_areas).
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "indoormap/core/grid.hpp"

namespace indoormap::areas::detail {

/// OpenCV views of grid storage (row = grid row; no copy).
inline cv::Mat view(Grid<std::uint8_t>& g) {
  return {g.height, g.width, CV_8U, g.data.data()};
}
inline cv::Mat view(Grid<int>& g) {
  return {g.height, g.width, CV_32S, g.data.data()};
}

/// Distance (cells, L2) from each free cell to the nearest non-free cell or the grid's edge.
cv::Mat clearance(const Grid<std::uint8_t>& free);

/// Grows the labels (multi-source BFS, 4-connected) into the cells of mask that have label 0.
void fill_unlabelled(Grid<int>& labels, const Grid<std::uint8_t>& mask);

/// Relabels to 1..n in order of first appearance (0 stays 0); returns n.
int compact(Grid<int>& labels);

/// Cells per label (index = label, size max label + 1).
std::vector<int> label_sizes(const Grid<int>& labels);

/// Keeps each label's largest 4-connected piece; the other pieces are given to the neighbours
/// (fill_unlabelled within mask). Pieces with no labelled neighbour keep a label of their own.
void keep_largest_pieces(Grid<int>& labels, const Grid<std::uint8_t>& mask);

/// Labels under min_cells are given to their neighbours (fill_unlabelled within mask); a label
/// with no neighbour stays. Returns the number of labels after compact().
int merge_small(Grid<int>& labels, const Grid<std::uint8_t>& mask, int min_cells);

}  // namespace indoormap::areas::detail
