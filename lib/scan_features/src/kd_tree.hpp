#pragma once
// A static 2D k-d tree over a point set (private to im_scan_features): nearest neighbour within a
// radius. A scan holds a few hundred points; the tree is rebuilt once per alignment.
#include <Eigen/Core>
#include <vector>

namespace indoormap::scan_features::detail {

class KdTree2 {
 public:
  explicit KdTree2(const std::vector<Eigen::Vector2d>& points);
  /// Index of the nearest point within max_dist_m of q, or -1; dist2 receives its squared distance.
  int nearest(const Eigen::Vector2d& q, double max_dist_m, double& dist2) const;

 private:
  void build(int lo, int hi, int depth);
  void search(int lo, int hi, int depth, const Eigen::Vector2d& q, int& best,
              double& best_d2) const;
  const std::vector<Eigen::Vector2d>& points_;
  std::vector<int> order_;  ///< implicit tree: the median of [lo, hi) splits it
};

}  // namespace indoormap::scan_features::detail
