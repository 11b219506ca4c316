#include "indoormap/scan_features/icp.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "indoormap/core/errors.hpp"
#include "kd_tree.hpp"

namespace indoormap::scan_features {

using V = Eigen::Vector2d;

const char* icp_kind_name(IcpKind k) {
  return k == IcpKind::kPointToPoint ? "point_to_point" : "point_to_line";
}

void IcpParams::validate() const {
  auto positive = [](double v, const char* key) {
    if (!(v > 0.0 && std::isfinite(v)))
      throw UsageError(std::string("icp.") + key + " must be positive, got " + std::to_string(v));
  };
  if (max_iterations < 1) throw UsageError("icp.max_iterations must be >= 1");
  if (min_pairs < 3) throw UsageError("icp.min_pairs must be >= 3");
  positive(max_pair_m, "max_pair_m");
  positive(trim_factor, "trim_factor");
  positive(converged_m, "converged_m");
  positive(converged_rad, "converged_rad");
  positive(normal_radius_m, "normal_radius_m");
  if (!(min_trim_m >= 0.0)) throw UsageError("icp.min_trim_m must be >= 0");
  if (!(max_range_m >= 0.0)) throw UsageError("icp.max_range_m must be >= 0 (0: the scan's)");
  positive(inlier_m, "inlier_m");
}

void AlignSearch::validate() const {
  if (rotation_offsets_rad.empty())
    throw UsageError("align.rotation_offsets_rad must not be empty");
  for (double r : rotation_offsets_rad)
    if (!std::isfinite(r)) throw UsageError("align.rotation_offsets_rad must be finite");
  if (!(accept_inlier_share >= 0.0 && accept_inlier_share <= 1.0))
    throw UsageError("align.accept_inlier_share must be in [0, 1]");
}

laser::Pose2d procrustes(std::span<const V> src, std::span<const V> dst) {
  V cs = V::Zero(), cd = V::Zero();
  for (std::size_t i = 0; i < src.size(); ++i) cs += src[i], cd += dst[i];
  cs /= static_cast<double>(src.size());
  cd /= static_cast<double>(dst.size());
  Eigen::Matrix2d h = Eigen::Matrix2d::Zero();
  for (std::size_t i = 0; i < src.size(); ++i) h += (src[i] - cs) * (dst[i] - cd).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix2d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix2d d = Eigen::Matrix2d::Identity();
  d(1, 1) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  const Eigen::Matrix2d r = svd.matrixV() * d * svd.matrixU().transpose();
  const V t = cd - r * cs;
  return {t.x(), t.y(), std::atan2(r(1, 0), r(0, 0))};
}

laser::Pose2d relative_pose(const laser::Pose2d& a, const laser::Pose2d& b) {
  const double c = std::cos(a.theta_rad), s = std::sin(a.theta_rad);
  const V d = b.position_m() - a.position_m();
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y(),
          laser::wrap_angle(b.theta_rad - a.theta_rad)};
}

std::vector<V> scan_points_laser(const laser::LaserScan& scan, double max_range_m) {
  const double max_r =
      max_range_m > 0.0 ? std::min(max_range_m, scan.max_range_m) : scan.max_range_m;
  std::vector<V> out;
  out.reserve(scan.size());
  for (std::size_t i = 0; i < scan.size(); ++i) {
    const double r = scan.ranges_m[i];
    if (!(r > 0.0 && r < max_r)) continue;
    const double a = scan.beam_angle_rad(i);
    out.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return out;
}

namespace {

/// Unit normals of ref from its scan-order neighbours within radius (zero: no surface there).
std::vector<V> normals(const std::vector<V>& ref, double radius_m) {
  std::vector<V> out(ref.size(), V::Zero());
  const int n = static_cast<int>(ref.size());
  for (int i = 0; i < n; ++i) {
    int lo = i, hi = i;
    while (lo > 0 &&
           (ref[static_cast<std::size_t>(lo - 1)] - ref[static_cast<std::size_t>(i)]).norm() <=
               radius_m)
      --lo;
    while (hi + 1 < n &&
           (ref[static_cast<std::size_t>(hi + 1)] - ref[static_cast<std::size_t>(i)]).norm() <=
               radius_m)
      ++hi;
    if (hi - lo < 2) continue;
    V c = V::Zero();
    for (int k = lo; k <= hi; ++k) c += ref[static_cast<std::size_t>(k)];
    c /= hi - lo + 1;
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (int k = lo; k <= hi; ++k) {
      const V d = ref[static_cast<std::size_t>(k)] - c;
      cov += d * d.transpose();
    }
    const double angle = 0.5 * std::atan2(2.0 * cov(0, 1), cov(0, 0) - cov(1, 1));
    out[static_cast<std::size_t>(i)] = {-std::sin(angle), std::cos(angle)};
  }
  return out;
}

struct Pairs {
  std::vector<V> src, dst, normal;
  double rms_m = 0.0;
};

/// Nearest-neighbour pairs of the moved cur points, trimmed.
Pairs make_pairs(const detail::KdTree2& tree, const std::vector<V>& ref, const std::vector<V>& nrm,
                 const std::vector<V>& moved, const IcpParams& p) {
  std::vector<std::pair<double, std::pair<int, int>>> found;
  found.reserve(moved.size());
  for (std::size_t i = 0; i < moved.size(); ++i) {
    double d2 = 0.0;
    const int j = tree.nearest(moved[i], p.max_pair_m, d2);
    if (j < 0) continue;
    if (p.kind == IcpKind::kPointToLine && nrm[static_cast<std::size_t>(j)].isZero()) continue;
    found.push_back({d2, {static_cast<int>(i), j}});
  }
  Pairs out;
  if (found.empty()) return out;
  auto mid = found.begin() + static_cast<std::ptrdiff_t>(found.size() / 2);
  std::nth_element(found.begin(), mid, found.end());
  const double cut = std::max(p.min_trim_m, p.trim_factor * std::sqrt(mid->first));
  double sq = 0.0;
  for (const auto& [d2, ij] : found) {
    if (d2 > cut * cut) continue;
    const V& q = ref[static_cast<std::size_t>(ij.second)];
    const V& s = moved[static_cast<std::size_t>(ij.first)];
    out.src.push_back(s);
    out.dst.push_back(q);
    out.normal.push_back(nrm[static_cast<std::size_t>(ij.second)]);
    const double e = p.kind == IcpKind::kPointToLine ? out.normal.back().dot(s - q) : std::sqrt(d2);
    sq += e * e;
  }
  out.rms_m = out.src.empty() ? 0.0 : std::sqrt(sq / static_cast<double>(out.src.size()));
  return out;
}

/// One Gauss-Newton step of the point-to-line error (small-angle rotation about the origin).
laser::Pose2d point_to_line_step(const Pairs& pr) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < pr.src.size(); ++i) {
    const V& s = pr.src[i];
    const V& n = pr.normal[i];
    const Eigen::Vector3d j(n.x(), n.y(), n.x() * -s.y() + n.y() * s.x());
    a += j * j.transpose();
    b -= j * n.dot(s - pr.dst[i]);
  }
  const Eigen::Vector3d x = a.ldlt().solve(b);
  if (!x.allFinite()) return {};
  return {x(0), x(1), x(2)};
}

}  // namespace

IcpResult align_points(const std::vector<V>& ref, const std::vector<V>& cur,
                       const laser::Pose2d& guess, const IcpParams& p) {
  IcpResult res;
  res.transform = guess;
  if (ref.size() < static_cast<std::size_t>(p.min_pairs) ||
      cur.size() < static_cast<std::size_t>(p.min_pairs))
    return res;
  const detail::KdTree2 tree(ref);
  const std::vector<V> nrm = p.kind == IcpKind::kPointToLine
                                 ? normals(ref, p.normal_radius_m)
                                 : std::vector<V>(ref.size(), V::UnitX());
  std::vector<V> moved(cur.size());
  for (res.iterations = 1; res.iterations <= p.max_iterations; ++res.iterations) {
    for (std::size_t i = 0; i < cur.size(); ++i) moved[i] = res.transform.transform(cur[i]);
    const Pairs pr = make_pairs(tree, ref, nrm, moved, p);
    res.pairs = static_cast<int>(pr.src.size());
    res.rms_m = pr.rms_m;
    if (res.pairs < p.min_pairs) return res;
    const laser::Pose2d step =
        p.kind == IcpKind::kPointToLine ? point_to_line_step(pr) : procrustes(pr.src, pr.dst);
    res.transform = step.compose(res.transform);
    if (step.position_m().norm() < p.converged_m && std::abs(step.theta_rad) < p.converged_rad) {
      res.converged = true;
      break;
    }
  }
  res.iterations = std::min(res.iterations, p.max_iterations);
  int inliers = 0;
  for (const V& c : cur) {
    double d2 = 0.0;
    if (tree.nearest(res.transform.transform(c), p.inlier_m, d2) >= 0) ++inliers;
  }
  res.inlier_share = static_cast<double>(inliers) / static_cast<double>(cur.size());
  return res;
}

IcpResult align_scans(const laser::LaserScan& ref, const laser::LaserScan& cur,
                      const IcpParams& params, const AlignSearch& search,
                      std::span<const laser::Pose2d> guesses) {
  const std::vector<V> r = scan_points_laser(ref, params.max_range_m);
  const std::vector<V> c = scan_points_laser(cur, params.max_range_m);
  const laser::Pose2d identity;
  if (guesses.empty()) guesses = std::span<const laser::Pose2d>(&identity, 1);
  IcpResult best;
  best.inlier_share = -1.0;
  int starts = 0;
  for (const laser::Pose2d& g : guesses)
    for (double offset : search.rotation_offsets_rad) {
      ++starts;
      const laser::Pose2d start{g.x_m, g.y_m, laser::wrap_angle(g.theta_rad + offset)};
      IcpResult res = align_points(r, c, start, params);
      if (res.inlier_share > best.inlier_share) best = res;
      if (best.inlier_share >= search.accept_inlier_share) {
        best.starts = starts;
        return best;
      }
    }
  best.starts = starts;
  best.inlier_share = std::max(best.inlier_share, 0.0);
  return best;
}

}  // namespace indoormap::scan_features
