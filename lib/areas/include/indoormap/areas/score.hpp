#pragma once
// The room segmentation score of Bormann et al. (ICRA 2016): for each true room the
// best-overlapping area, recall = overlap / room size; for each area the best-overlapping true
// room, precision = overlap / area size; both averaged (unweighted) over rooms / areas. Cells are
// counted only where both grids are labelled (> 0): the true rooms are restricted to the free
// space of the map that was segmented (furniture is not room floor a segmentation could cover).
#include <cstdint>
#include <vector>

#include "indoormap/core/grid.hpp"

namespace indoormap::areas {

struct SegmentationScore {
  double recall = 0.0;
  double precision = 0.0;
  int true_rooms = 0;
  int areas = 0;
  std::vector<double> room_recall;     ///< per true room label 1..n (index label-1)
  std::vector<double> area_precision;  ///< per area label 1..m
};

/// truth, found: labels >= 1, 0 = none; same size (throws UsageError otherwise). Labels with no
/// counted cell are left out of the averages.
SegmentationScore score_segmentation(const Grid<int>& truth, const Grid<int>& found);

/// The true rooms of a ground-truth image (grey levels, >= free_min free): each 4-connected free
/// region of at least min_cells cells is a room, labelled 1..n.
Grid<int> truth_rooms(const Grid<std::uint8_t>& grey, int free_min = 250, int min_cells = 20);

}  // namespace indoormap::areas
