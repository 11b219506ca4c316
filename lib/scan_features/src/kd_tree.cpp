#include "kd_tree.hpp"

#include <algorithm>
#include <numeric>

namespace indoormap::scan_features::detail {

KdTree2::KdTree2(const std::vector<Eigen::Vector2d>& points) : points_(points) {
  order_.resize(points.size());
  std::iota(order_.begin(), order_.end(), 0);
  build(0, static_cast<int>(order_.size()), 0);
}

void KdTree2::build(int lo, int hi, int depth) {
  if (hi - lo <= 1) return;
  const int mid = (lo + hi) / 2, axis = depth % 2;
  std::nth_element(order_.begin() + lo, order_.begin() + mid, order_.begin() + hi,
                   [&](int a, int b) {
                     return points_[static_cast<std::size_t>(a)][axis] <
                            points_[static_cast<std::size_t>(b)][axis];
                   });
  build(lo, mid, depth + 1);
  build(mid + 1, hi, depth + 1);
}

void KdTree2::search(int lo, int hi, int depth, const Eigen::Vector2d& q, int& best,
                     double& best_d2) const {
  if (hi <= lo) return;
  const int mid = (lo + hi) / 2, axis = depth % 2;
  const int idx = order_[static_cast<std::size_t>(mid)];
  const Eigen::Vector2d& p = points_[static_cast<std::size_t>(idx)];
  const double d2 = (p - q).squaredNorm();
  if (d2 < best_d2) best_d2 = d2, best = idx;
  const double diff = q[axis] - p[axis];
  const bool left_first = diff < 0.0;
  if (left_first)
    search(lo, mid, depth + 1, q, best, best_d2);
  else
    search(mid + 1, hi, depth + 1, q, best, best_d2);
  if (diff * diff < best_d2) {
    if (left_first)
      search(mid + 1, hi, depth + 1, q, best, best_d2);
    else
      search(lo, mid, depth + 1, q, best, best_d2);
  }
}

int KdTree2::nearest(const Eigen::Vector2d& q, double max_dist_m, double& dist2) const {
  int best = -1;
  dist2 = max_dist_m * max_dist_m;
  search(0, static_cast<int>(order_.size()), 0, q, best, dist2);
  return best;
}

}  // namespace indoormap::scan_features::detail
