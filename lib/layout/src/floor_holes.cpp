#include "floor_holes.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace indoormap::layout::detail {

namespace {

struct Component {
  std::int64_t cells = 0, free_border = 0, border = 0;
  bool edge = false, drop = false;
};

}  // namespace

std::vector<std::uint8_t> hole_barrier(const std::vector<NavState>& state,
                                       const cloud::VoxelGrid& g,
                                       const std::vector<std::uint8_t>& walls,
                                       const WallProof& proof) {
  const std::int64_t w = g.nx, z0 = std::max<std::int64_t>(0, proof.lo_layer),
                     z1 = std::min<std::int64_t>(g.nz - 1, proof.hi_layer);
  std::vector<std::uint8_t> barrier(state.size(), 0);
  for (std::size_t i = 0; i < state.size(); ++i) {
    barrier[i] = state[i] == NavState::kOccupied;
    if (barrier[i] || walls.empty() || !walls[i]) continue;
    const std::int64_t x = static_cast<std::int64_t>(i) % w, y = static_cast<std::int64_t>(i) / w;
    for (std::int64_t z = z0; z <= z1 && !barrier[i]; ++z) barrier[i] = g.count(x, y, z) != 0;
  }
  return barrier;
}

std::int64_t fill_floor_holes(std::vector<NavState>& state,
                              const std::vector<std::uint8_t>& barrier_cells,
                              const std::vector<std::uint8_t>& drop, int w, int h,
                              const HoleParams& params) {
  if (w <= 0 || h <= 0) return 0;
  // The barrier cells closed across gaps of up to barrier_gap_cells: a wall's face seen sparsely
  // (a mobile scanner passing by) has such gaps, through which a gap of the floor's rings beside
  // it joined the wall's unseen inside, and so the unseen world outside.
  cv::Mat barrier(h, w, CV_8U);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      barrier.at<std::uint8_t>(r, c) = barrier_cells[static_cast<std::size_t>(r) * w + c] != 0;
  if (params.barrier_gap_cells > 0) {
    const int k = 2 * ((params.barrier_gap_cells + 1) / 2) + 1;
    cv::morphologyEx(barrier, barrier, cv::MORPH_CLOSE,
                     cv::getStructuringElement(cv::MORPH_RECT, {k, k}));
  }
  cv::Mat unknown(h, w, CV_8U);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      unknown.at<std::uint8_t>(r, c) =
          state[static_cast<std::size_t>(r) * w + c] == NavState::kUnknown &&
          !barrier.at<std::uint8_t>(r, c);
  cv::Mat labels;
  const int n = cv::connectedComponents(unknown, labels, 4, CV_32S);
  std::vector<Component> comp(static_cast<std::size_t>(n));
  const int dr[4] = {-1, 1, 0, 0}, dc[4] = {0, 0, -1, 1};
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const int l = labels.at<int>(r, c);
      if (l == 0) continue;
      Component& k = comp[static_cast<std::size_t>(l)];
      ++k.cells;
      k.drop = k.drop || drop[static_cast<std::size_t>(r) * w + c];
      for (int d = 0; d < 4; ++d) {
        const int rr = r + dr[d], cc = c + dc[d];
        if (rr < 0 || cc < 0 || rr >= h || cc >= w) {
          k.edge = true;
          continue;
        }
        const NavState s = state[static_cast<std::size_t>(rr) * w + cc];
        if (s == NavState::kUnknown && !barrier.at<std::uint8_t>(rr, cc)) continue;
        ++k.border;
        k.free_border += s == NavState::kFree;
      }
    }
  std::vector<std::uint8_t> fill(comp.size(), 0);
  for (std::size_t l = 1; l < comp.size(); ++l) {
    const Component& k = comp[l];
    fill[l] = !k.edge && !k.drop && k.border > 0 &&
              static_cast<double>(k.cells) <= params.max_cells &&
              static_cast<double>(k.free_border) >= params.min_free_share * k.border;
  }
  std::int64_t filled = 0;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      if (fill[static_cast<std::size_t>(labels.at<int>(r, c))]) {
        state[static_cast<std::size_t>(r) * w + c] = NavState::kFree;
        ++filled;
      }
  return filled;
}

}  // namespace indoormap::layout::detail
