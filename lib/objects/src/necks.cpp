#include <algorithm>
#include <deque>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "objects_internal.hpp"

namespace indoormap::objects::detail {

namespace {

// One geometric part (8-connected cells) of a label, in its bounding box.
struct Part {
  cv::Rect box;
  cv::Mat mask;  // CV_8U, 1 on the part's cells
};

std::vector<Part> parts_of(const Labels& lab, int id, const cv::Rect& box) {
  cv::Mat m(box.height, box.width, CV_8U, cv::Scalar(0));
  for (int r = 0; r < box.height; ++r)
    for (int c = 0; c < box.width; ++c)
      m.at<std::uint8_t>(r, c) = lab.labels.at(box.x + c, box.y + r) == id;
  cv::Mat cc;
  const int n = cv::connectedComponents(m, cc, 8, CV_32S);
  std::vector<Part> out;
  for (int k = 1; k < n; ++k) out.push_back({box, cc == k});
  for (auto& p : out) p.mask /= 255;
  return out;
}

// The part's cells by nearest (4-connected steps inside the part) core: cores are the components
// of the part opened by a disc of `radius` cells that hold at least min_cells cells. Returns one
// index per cell (-1 outside the part), or nothing when fewer than two cores are found.
std::vector<int> split_part(const Part& p, int radius, std::int64_t min_cells) {
  const int w = p.mask.cols, h = p.mask.rows;
  cv::Mat padded, opened;
  cv::copyMakeBorder(p.mask, padded, radius, radius, radius, radius, cv::BORDER_CONSTANT, 0);
  cv::morphologyEx(padded, opened, cv::MORPH_OPEN,
                   cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * radius + 1, 2 * radius + 1}));
  cv::Mat cc, stats, centroids;
  const int n = cv::connectedComponentsWithStats(opened, cc, stats, centroids, 8, CV_32S);
  std::vector<int> core_of(static_cast<std::size_t>(n), -1);
  int cores = 0;
  for (int k = 1; k < n; ++k)
    if (stats.at<int>(k, cv::CC_STAT_AREA) >= min_cells) core_of[k] = cores++;
  if (cores < 2) return {};
  std::vector<int> owner(static_cast<std::size_t>(w) * h, -1);
  std::deque<int> queue;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (const int k = cc.at<int>(r + radius, c + radius); k && core_of[k] >= 0) {
        owner[static_cast<std::size_t>(r) * w + c] = core_of[k];
        queue.push_back(r * w + c);
      }
  while (!queue.empty()) {
    const int i = queue.front();
    queue.pop_front();
    const int r = i / w, c = i % w;
    for (auto [dc, dr] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
      const int nc = c + dc, nr = r + dr;
      if (nc < 0 || nr < 0 || nc >= w || nr >= h || !p.mask.at<std::uint8_t>(nr, nc)) continue;
      const int j = nr * w + nc;
      if (owner[j] >= 0) continue;
      owner[j] = owner[i];
      queue.push_back(j);
    }
  }
  return owner;
}

// True when a seen surface runs on from one owner's cells into another's: a solid cell (one with
// more than a stray return) next to (8 neighbours) a solid cell of another owner. One piece of
// furniture with a notch behind its front face keeps that face across the neck; two pieces a
// gap apart (shelves end to end) have no face in the gap.
bool face_runs_across(const Part& p, const std::vector<int>& owner,
                      const Grid<std::uint8_t>& solid) {
  const int w = p.mask.cols, h = p.mask.rows;
  auto solid_owner = [&](int c, int r) {
    if (c < 0 || r < 0 || c >= w || r >= h) return -1;
    const int o = owner[static_cast<std::size_t>(r) * w + c];
    return o >= 0 && solid.at(p.box.x + c, p.box.y + r) ? o : -1;
  };
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const int o = solid_owner(c, r);
      if (o < 0) continue;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc)
          if (const int q = solid_owner(c + dc, r + dr); q >= 0 && q != o) return true;
    }
  return false;
}

// Dense labels in raster order of each label's first cell.
Labels relabel_raster(const Grid<std::int32_t>& ids, int max_id) {
  Labels out;
  out.labels = Grid<std::int32_t>(ids.width, ids.height, 0);
  std::vector<int> dense(static_cast<std::size_t>(max_id) + 1, 0);
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (const int v = ids.data[i]) {
      if (!dense[v]) dense[v] = ++out.count;
      out.labels.data[i] = dense[v];
    }
  return out;
}

}  // namespace

Labels split_at_necks(const Labels& in, const Grid<std::uint8_t>& solid, double cell_m,
                      const ObjectParams& params) {
  if (params.neck_width_m <= 0 || in.count == 0) return in;
  // The opening's disc, neck_width_m across (in whole cells, at least 3): it passes no narrower
  // neck, and no part of an object narrower than itself is a core.
  const int radius =
      std::max(1, static_cast<int>(std::lround((params.neck_width_m / cell_m - 1) / 2)));
  const auto min_cells =
      static_cast<std::int64_t>(std::ceil(params.neck_min_part_m2 / (cell_m * cell_m) - 1e-9));
  const int w = in.labels.width, h = in.labels.height;
  std::vector<cv::Rect> box(static_cast<std::size_t>(in.count) + 1);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (const int v = in.labels.at(c, r)) box[v] |= cv::Rect(c, r, 1, 1);
  Grid<std::int32_t> out = in.labels;
  int next = in.count + 1;
  for (int id = 1; id <= in.count; ++id) {
    if (box[id].area() < 2 * min_cells) continue;
    for (const Part& p : parts_of(in, id, box[id])) {
      const std::vector<int> owner = split_part(p, radius, min_cells);
      if (owner.empty() || face_runs_across(p, owner, solid)) continue;
      const int first = next;
      for (int r = 0; r < p.mask.rows; ++r)
        for (int c = 0; c < p.mask.cols; ++c)
          if (const int o = owner[static_cast<std::size_t>(r) * p.mask.cols + c]; o >= 0) {
            out.at(p.box.x + c, p.box.y + r) = first + o;
            next = std::max(next, first + o + 1);
          }
    }
  }
  return relabel_raster(out, next);
}

}  // namespace indoormap::objects::detail
