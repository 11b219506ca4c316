// Room segmentation: a watershed of the distance transform in decreasing clearance, basins kept
// apart at door-like necks (docs/grid-areas.md, "Rooms").
#include "indoormap/areas/rooms.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "label_ops.hpp"

namespace indoormap::areas {
namespace {

struct Basin {
  float peak = 0.0f;  ///< largest clearance (cells)
  int cells = 0;      ///< cells flooded so far (all above the current level)
};

int find(std::vector<int>& parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

/// free plus the clutter: obstacle blobs of at most max_cells not touching the edge.
Grid<std::uint8_t> without_clutter(const Grid<std::uint8_t>& free, double max_cells) {
  Grid<std::uint8_t> open = free, obstacle(free.width, free.height, 0);
  for (std::size_t i = 0; i < free.size(); ++i) obstacle.data[i] = free.data[i] ? 0 : 1;
  cv::Mat cc, stats, centroids;
  const int n =
      cv::connectedComponentsWithStats(detail::view(obstacle), cc, stats, centroids, 8, CV_32S);
  std::vector<bool> clutter(n, false);
  for (int i = 1; i < n; ++i) {
    const int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
    const int bw = stats.at<int>(i, cv::CC_STAT_WIDTH), bh = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    const bool edge = x == 0 || y == 0 || x + bw == free.width || y + bh == free.height;
    clutter[i] = !edge && stats.at<int>(i, cv::CC_STAT_AREA) <= max_cells;
  }
  for (int r = 0; r < free.height; ++r)
    for (int c = 0; c < free.width; ++c)
      if (clutter[cc.at<int>(r, c)]) open.at(c, r) = 1;
  return open;
}

}  // namespace

Grid<int> segment_rooms(const Grid<std::uint8_t>& free_in, double cell_m, const RoomParams& p,
                        int* count) {
  validate(p);
  const Grid<std::uint8_t> free =
      without_clutter(free_in, p.clutter_max_area_m2 / (cell_m * cell_m));
  const int w = free.width, h = free.height;
  const cv::Mat d = detail::clearance(free);
  std::vector<std::pair<float, int>> order;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (free.at(c, r)) order.emplace_back(d.at<float>(r, c), r * w + c);
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });

  // A neck of clearance n (cells) is n - 0.5 cells from the centre line to the obstacle's edge on
  // each side: clear width (2n - 1) cells.
  const double door_cells = p.door_max_width_m / cell_m;
  const double core_cells = p.min_core_area_m2 / (cell_m * cell_m);
  auto is_door = [&](float level, const Basin& a, const Basin& b) {
    const Basin& small = a.peak < b.peak ? a : b;
    return 2.0 * level - 1.0 <= door_cells && small.peak >= p.neck_ratio * level &&
           small.cells >= core_cells;
  };

  std::vector<int> parent(static_cast<std::size_t>(w) * h, -1);
  std::vector<Basin> basin(parent.size());
  std::vector<int> roots;
  for (const auto& [level, i] : order) {
    parent[i] = i;
    basin[i] = {level, 1};
    const int c = i % w, r = i / w;
    roots.clear();
    // The cell joins the basin of its highest neighbour (steepest ascent): joining the basin of
    // the highest peak instead lets a big basin leak along the low cells by a wall.
    int uphill = -1;
    float uphill_d = -1.0f;
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        const int cc = c + dc, rr = r + dr;
        if ((dr == 0 && dc == 0) || cc < 0 || rr < 0 || cc >= w || rr >= h) continue;
        const int j = rr * w + cc;
        if (parent[j] < 0) continue;
        const int root = find(parent, j);
        if (d.at<float>(rr, cc) > uphill_d) {
          uphill_d = d.at<float>(rr, cc);
          uphill = root;
        }
        if (std::find(roots.begin(), roots.end(), root) == roots.end()) roots.push_back(root);
      }
    if (roots.empty()) continue;
    std::iter_swap(roots.begin(), std::find(roots.begin(), roots.end(), uphill));
    const int top = roots[0];
    parent[i] = top;
    basin[top].cells += 1;
    for (std::size_t k = 1; k < roots.size(); ++k) {
      const int o = roots[k];
      if (is_door(level, basin[top], basin[o])) continue;
      parent[o] = top;
      basin[top].cells += basin[o].cells;
      basin[top].peak = std::max(basin[top].peak, basin[o].peak);
    }
  }
  Grid<int> labels(w, h, 0);
  for (int i = 0; i < static_cast<int>(parent.size()); ++i)
    if (parent[i] >= 0) labels.data[i] = find(parent, i) + 1;
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (!free_in.data[i]) labels.data[i] = 0;
  detail::keep_largest_pieces(labels, free_in);
  const int min_cells = static_cast<int>(std::ceil(p.min_room_area_m2 / (cell_m * cell_m)));
  const int n = detail::merge_small(labels, free_in, min_cells);
  if (count) *count = n;
  return labels;
}

}  // namespace indoormap::areas
