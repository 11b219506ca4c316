// The area split's steps in order (docs/grid-areas.md).
#include "indoormap/areas/areas.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "corridors.hpp"
#include "indoormap/areas/rooms.hpp"
#include "indoormap/core/errors.hpp"
#include "label_ops.hpp"
#include "outline.hpp"

namespace indoormap::areas {

std::string_view to_string(AreaKind k) {
  switch (k) {
    case AreaKind::kRoom:
      return "room";
    case AreaKind::kCorridor:
      return "corridor";
    case AreaKind::kCrossing:
      return "crossing";
  }
  return "invalid";
}

namespace {

/// Free cells the footprint reaches: within half its width of a cell where its inscribed circle
/// fits, in components of at least the footprint's area. Sets the component count.
Grid<std::uint8_t> reachable(const Grid<std::uint8_t>& free, double cell_m,
                             const FootprintParams& fp, int& components) {
  const cv::Mat d = detail::clearance(free);
  const double half = 0.5 * fp.robot_width_m / cell_m;
  cv::Mat centre(d.size(), CV_8U);
  for (int r = 0; r < d.rows; ++r)
    for (int c = 0; c < d.cols; ++c)
      centre.at<std::uint8_t>(r, c) = d.at<float>(r, c) >= half + 0.5 ? 0 : 255;
  cv::Mat to_centre;
  cv::distanceTransform(centre, to_centre, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  Grid<std::uint8_t> reach(free.width, free.height, 0);
  for (int r = 0; r < d.rows; ++r)
    for (int c = 0; c < d.cols; ++c)
      reach.at(c, r) = free.at(c, r) && to_centre.at<float>(r, c) <= half + 0.5 ? 1 : 0;
  cv::Mat cc, stats, centroids;
  const int n =
      cv::connectedComponentsWithStats(detail::view(reach), cc, stats, centroids, 4, CV_32S);
  const double min_cells = fp.robot_width_m * fp.robot_length_m / (cell_m * cell_m);
  components = 0;
  std::vector<bool> keep(n, false);
  for (int i = 1; i < n; ++i)
    if (stats.at<int>(i, cv::CC_STAT_AREA) >= min_cells) {
      keep[i] = true;
      ++components;
    }
  for (int r = 0; r < d.rows; ++r)
    for (int c = 0; c < d.cols; ++c) reach.at(c, r) = keep[cc.at<int>(r, c)] ? 1 : 0;
  return reach;
}

}  // namespace

AreasResult split_areas(const Grid<Cell>& cells, const GridGeometry& geometry,
                        const AreasParams& params) {
  validate(params);
  const double cell_m = geometry.cell_m();
  AreasResult r;
  r.labels = Grid<std::uint16_t>(cells.width, cells.height, 0);
  r.too_narrow = Grid<std::uint8_t>(cells.width, cells.height, 0);
  Grid<std::uint8_t> free(cells.width, cells.height, 0);
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (cells.data[i] == Cell::kFree) {
      free.data[i] = 1;
      ++r.free_cells;
    }
  if (r.free_cells == 0) return r;
  const Grid<std::uint8_t> reach =
      reachable(free, cell_m, params.footprint, r.reachable_components);
  for (std::size_t i = 0; i < free.size(); ++i) {
    r.too_narrow.data[i] = free.data[i] && !reach.data[i];
    r.reachable_cells += reach.data[i];
  }
  if (r.reachable_cells == 0) return r;

  // Rooms on the whole free space (door widths as built), then cut to what the robot reaches.
  Grid<int> rooms = segment_rooms(free, cell_m, params.rooms);
  for (std::size_t i = 0; i < rooms.size(); ++i)
    if (!reach.data[i]) rooms.data[i] = 0;
  detail::keep_largest_pieces(rooms, reach);
  const int min_cells =
      static_cast<int>(std::ceil(params.rooms.min_room_area_m2 / (cell_m * cell_m)));
  const int n = detail::merge_small(rooms, reach, min_cells);

  detail::CorridorSplit split = detail::split_corridors(rooms, n, reach, free, cell_m, params);
  detail::keep_largest_pieces(split.labels, reach);
  // No area smaller than the footprint: such pieces (cut-offs of crossings) go to neighbours.
  {
    const std::vector<int> size = detail::label_sizes(split.labels);
    const double min_fp =
        params.footprint.robot_width_m * params.footprint.robot_length_m / (cell_m * cell_m);
    Grid<int> before = split.labels;
    for (int& v : split.labels.data)
      if (v > 0 && size[v] < min_fp) v = 0;
    detail::fill_unlabelled(split.labels, reach);
    for (std::size_t i = 0; i < before.size(); ++i)
      if (before.data[i] && !split.labels.data[i]) split.labels.data[i] = before.data[i];
  }
  // Relabel 1..m, carrying the kinds (pieces split off by keep_largest_pieces are rooms'
  // leftovers).
  std::vector<int> new_id;
  std::vector<AreaKind> kinds;
  for (int& v : split.labels.data) {
    if (v <= 0) continue;
    if (static_cast<std::size_t>(v) >= new_id.size()) new_id.resize(v + 1, 0);
    if (!new_id[v]) {
      new_id[v] = static_cast<int>(kinds.size()) + 1;
      kinds.push_back(v <= static_cast<int>(split.kinds.size()) ? split.kinds[v - 1]
                                                                : AreaKind::kRoom);
    }
    v = new_id[v];
  }
  if (kinds.size() > 65535) throw BudgetError("more than 65535 areas: the label image is 16-bit");
  for (std::size_t i = 0; i < split.labels.size(); ++i)
    r.labels.data[i] = static_cast<std::uint16_t>(split.labels.data[i]);
  for (std::size_t i = 0; i < kinds.size(); ++i)
    r.areas.push_back({static_cast<int>(i) + 1, kinds[i], 0, 0.0, {}, {}, {}});
  for (auto c : split.checks)
    r.crossing_checks.push_back({geometry.from_cell_coords(c.at_m), c.arms, c.confirmed});
  detail::build_outlines(r, geometry, min_cells);
  detail::build_graph(r, geometry);
  return r;
}

}  // namespace indoormap::areas
