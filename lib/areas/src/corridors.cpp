// Corridors and crossings (docs/grid-areas.md, "Corridors and crossings").
#include "corridors.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>
#include <opencv2/imgproc.hpp>

#include "indoormap/areas/fan.hpp"
#include "label_ops.hpp"

namespace indoormap::areas::detail {
namespace {

constexpr int kNb[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};

/// Skeleton cells within path length k of start (steps of 1 and sqrt 2 along the skeleton), and
/// the rim: the first cells at k or beyond on each way out.
struct Reach {
  std::vector<cv::Point> rim;
  std::vector<cv::Point> within;
};
Reach skeleton_reach(const cv::Mat& skel, cv::Point start, double k, cv::Mat& dist) {
  // dist: CV_32F scratch of skel's size, all negative (unvisited) on entry and on return.
  Reach out;
  using Item = std::pair<float, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  std::vector<cv::Point> touched{start};
  dist.at<float>(start) = 0.0f;
  queue.push({0.0f, start.y * skel.cols + start.x});
  while (!queue.empty()) {
    const auto [dp, idx] = queue.top();
    queue.pop();
    const cv::Point p(idx % skel.cols, idx / skel.cols);
    if (dp > dist.at<float>(p)) continue;
    if (dp >= k) {
      out.rim.push_back(p);
      continue;
    }
    out.within.push_back(p);
    for (const auto& d : kNb) {
      const cv::Point q(p.x + d[0], p.y + d[1]);
      if (q.x < 0 || q.y < 0 || q.x >= skel.cols || q.y >= skel.rows) continue;
      if (!skel.at<std::uint8_t>(q)) continue;
      const float nd = dp + ((d[0] && d[1]) ? 1.41421356f : 1.0f);
      float& dq = dist.at<float>(q);
      if (dq >= 0.0f && dq <= nd) continue;
      if (dq < 0.0f) touched.push_back(q);
      dq = nd;
      queue.push({nd, q.y * skel.cols + q.x});
    }
  }
  for (const auto& p : touched) dist.at<float>(p) = -1.0f;
  return out;
}

/// Groups rim cells into arms (8-adjacent cells belong to one arm); returns each arm's mean.
std::vector<cv::Point2d> arms(const std::vector<cv::Point>& rim) {
  std::vector<int> group(rim.size(), -1);
  std::vector<cv::Point2d> mean;
  std::vector<int> count;
  for (std::size_t i = 0; i < rim.size(); ++i) {
    if (group[i] >= 0) continue;
    const int g = static_cast<int>(mean.size());
    mean.emplace_back(0, 0);
    count.push_back(0);
    std::vector<std::size_t> stack{i};
    group[i] = g;
    while (!stack.empty()) {
      const std::size_t a = stack.back();
      stack.pop_back();
      mean[g] += cv::Point2d(rim[a]);
      ++count[g];
      for (std::size_t b = 0; b < rim.size(); ++b)
        if (group[b] < 0 && std::abs(rim[a].x - rim[b].x) <= 1 && std::abs(rim[a].y - rim[b].y) <= 1) {
          group[b] = g;
          stack.push_back(b);
        }
    }
  }
  for (std::size_t g = 0; g < mean.size(); ++g) mean[g] *= 1.0 / count[g];
  return mean;
}

/// Removes end cells `times` times (spurs shorter than that vanish).
void prune(cv::Mat& skel, int times) {
  std::vector<cv::Point> ends;
  for (int t = 0; t < times; ++t) {
    ends.clear();
    for (int r = 1; r + 1 < skel.rows; ++r)
      for (int c = 1; c + 1 < skel.cols; ++c) {
        if (!skel.at<std::uint8_t>(r, c)) continue;
        int n = 0;
        for (const auto& d : kNb) n += skel.at<std::uint8_t>(r + d[1], c + d[0]);
        if (n <= 1) ends.emplace_back(c, r);
      }
    if (ends.empty()) return;
    for (const auto& p : ends) skel.at<std::uint8_t>(p) = 0;
  }
}

struct Candidate {
  cv::Point at;
  std::vector<cv::Point2d> arm_ends;
  double priority = 0.0;  ///< larger first
};

/// A junction or corner: where its arms' centre lines meet, and each arm's outward direction.
struct Junction {
  Eigen::Vector2d centre;
  std::vector<Eigen::Vector2d> out;
};

/// The arms' directions from their cells at path length k / 2 and k; the centre is the least-squares
/// meeting point of their centre lines (the skeleton's own junction point lies off the centre:
/// in a T it is up the stem, where the inscribed circle is largest).
Junction junction(const cv::Mat& skel, const Candidate& cand, double k, cv::Mat& scratch) {
  const auto near = arms(skeleton_reach(skel, cand.at, 0.5 * k, scratch).rim);
  Junction j;
  Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  const Eigen::Vector2d p(cand.at.x, cand.at.y);
  for (const auto& e : cand.arm_ends) {
    const Eigen::Vector2d e1(e.x, e.y);
    Eigen::Vector2d u = (e1 - p).normalized();
    double best = 1e300;
    for (const auto& f : near) {
      const Eigen::Vector2d e2(f.x, f.y);
      const double dist = std::abs((e1 - e2).norm() - 0.5 * k);
      if ((e1 - e2).dot(u) > 0.0 && dist < best && dist < 0.25 * k) {
        best = dist;
        u = (e1 - e2).normalized();
      }
    }
    j.out.push_back(u);
    const Eigen::Matrix2d proj = Eigen::Matrix2d::Identity() - u * u.transpose();
    a += proj;
    b += proj * e1;
  }
  j.centre = std::abs(a.determinant()) > 1e-3 ? Eigen::Vector2d(a.inverse() * b) : p;
  return j;
}

/// Marks as crossing `id` the cells of mask connected to the junction's centre (within
/// max_dist) that lie no more than cut beyond the centre along every arm.
void mark_crossing(const cv::Mat& mask, const Junction& j, double cut, double max_dist, int id,
                   cv::Mat& crossing_of) {
  auto inside = [&](int x, int y) {
    const Eigen::Vector2d v = Eigen::Vector2d(x, y) - j.centre;
    if (v.norm() > max_dist) return false;
    for (const auto& u : j.out)
      if (v.dot(u) > cut) return false;
    return true;
  };
  const cv::Point c0(static_cast<int>(std::lround(j.centre.x())), static_cast<int>(std::lround(j.centre.y())));
  if (c0.x < 0 || c0.y < 0 || c0.x >= mask.cols || c0.y >= mask.rows || !mask.at<std::uint8_t>(c0)) return;
  std::vector<cv::Point> stack{c0};
  cv::Mat seen(mask.size(), CV_8U, cv::Scalar(0));
  seen.at<std::uint8_t>(c0) = 1;
  while (!stack.empty()) {
    const cv::Point p = stack.back();
    stack.pop_back();
    if (!crossing_of.at<int>(p)) crossing_of.at<int>(p) = id;
    const cv::Point nb[4] = {{p.x + 1, p.y}, {p.x - 1, p.y}, {p.x, p.y + 1}, {p.x, p.y - 1}};
    for (const auto& q : nb) {
      if (q.x < 0 || q.y < 0 || q.x >= mask.cols || q.y >= mask.rows) continue;
      if (seen.at<std::uint8_t>(q) || !mask.at<std::uint8_t>(q) || !inside(q.x, q.y)) continue;
      seen.at<std::uint8_t>(q) = 1;
      stack.push_back(q);
    }
  }
}

}  // namespace

CorridorSplit split_corridors(const Grid<int>& pieces, int n, const Grid<std::uint8_t>& reach,
                              const Grid<std::uint8_t>& free, double cell_m,
                              const AreasParams& params) {
  const CorridorParams& cp = params.corridors;
  (void)free;  // the fan-of-turns test runs on reach: the footprint's own free space
  const int w = pieces.width, h = pieces.height;
  std::vector<cv::Rect> box(n + 1);
  std::vector<bool> seen_label(n + 1, false);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const int l = pieces.at(c, r);
      if (l <= 0) continue;
      box[l] = seen_label[l] ? (box[l] | cv::Rect(c, r, 1, 1)) : cv::Rect(c, r, 1, 1);
      seen_label[l] = true;
    }
  CorridorSplit out;
  out.labels = Grid<int>(w, h, 0);
  auto add = [&](AreaKind k) {
    out.kinds.push_back(k);
    return static_cast<int>(out.kinds.size());
  };
  for (int l = 1; l <= n; ++l) {
    if (!seen_label[l]) continue;
    const cv::Rect b = box[l];
    const cv::Rect crop(b.x - 2, b.y - 2, b.width + 4, b.height + 4);
    cv::Mat mask(crop.size(), CV_8U, cv::Scalar(0));
    for (int r = b.y; r < b.y + b.height; ++r)
      for (int c = b.x; c < b.x + b.width; ++c)
        if (pieces.at(c, r) == l) mask.at<std::uint8_t>(r - crop.y, c - crop.x) = 1;
    // Holes (furniture) filled: the way's width is the walls', not the gaps between tables.
    std::vector<std::vector<cv::Point>> outer;
    cv::findContours(mask.clone(), outer, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
    cv::Mat filled(crop.size(), CV_8U, cv::Scalar(0));
    cv::drawContours(filled, outer, -1, cv::Scalar(1), cv::FILLED);
    cv::Mat d;
    cv::distanceTransform(filled, d, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
    std::vector<float> dv;
    for (int r = 0; r < d.rows; ++r)
      for (int c = 0; c < d.cols; ++c)
        if (filled.at<std::uint8_t>(r, c)) dv.push_back(d.at<float>(r, c));
    std::nth_element(dv.begin(), dv.begin() + static_cast<long>(dv.size() * 9 / 10), dv.end());
    const double p90 = dv[dv.size() * 9 / 10];
    // A long strip of width W: 90 % of its cells are within 0.45 W of a wall.
    const double width = 2.0 * p90 / 0.9;
    const bool corridor = width * cell_m <= cp.max_width_m &&
                          static_cast<double>(dv.size()) >= cp.min_elongation * width * width;
    if (!corridor) {
      const int id = add(AreaKind::kRoom);
      for (int r = b.y; r < b.y + b.height; ++r)
        for (int c = b.x; c < b.x + b.width; ++c)
          if (pieces.at(c, r) == l) out.labels.at(c, r) = id;
      continue;
    }
    cv::Mat skel = filled.clone();
    thin(skel);
    const int k = std::max(3, static_cast<int>(std::lround(width)));
    prune(skel, k);
    // Candidates: junctions (3+ arms k steps away) and corners (2 arms bent by corner_min_deg).
    cv::Mat seen(crop.size(), CV_32F, cv::Scalar(-1.0f));
    std::vector<Candidate> cands;
    const double max_cos = std::cos((180.0 - cp.corner_min_deg) * std::numbers::pi / 180.0);
    for (int r = 0; r < skel.rows; ++r)
      for (int c = 0; c < skel.cols; ++c) {
        if (!skel.at<std::uint8_t>(r, c)) continue;
        const cv::Point p(c, r);
        const auto ends = arms(skeleton_reach(skel, p, k, seen).rim);
        if (ends.size() >= 3) {
          cands.push_back({p, ends, 1000.0 + d.at<float>(p)});
        } else if (ends.size() == 2) {
          const cv::Point2d u = ends[0] - cv::Point2d(p), v = ends[1] - cv::Point2d(p);
          const double cosang = u.dot(v) / std::max(1e-9, std::sqrt(u.dot(u) * v.dot(v)));
          if (cosang > max_cos) cands.push_back({p, ends, cosang});
        }
      }
    std::sort(cands.begin(), cands.end(),
              [](const Candidate& a, const Candidate& b2) { return a.priority > b2.priority; });
    std::vector<Candidate> kept;
    for (const auto& cand : cands) {
      bool near = false;
      for (const auto& o : kept) near = near || cv::norm(cand.at - o.at) < 1.5 * k;
      if (!near) kept.push_back(cand);
    }
    // Fan-of-turns check, arriving along each arm.
    cv::Mat crossing_of(crop.size(), CV_32S, cv::Scalar(0));
    // The way's half width: the median clearance on the skeleton.
    std::vector<float> on_skel;
    for (int r = 0; r < skel.rows; ++r)
      for (int c = 0; c < skel.cols; ++c)
        if (skel.at<std::uint8_t>(r, c)) on_skel.push_back(d.at<float>(r, c));
    if (on_skel.empty()) on_skel.push_back(static_cast<float>(0.5 * width));
    std::nth_element(on_skel.begin(), on_skel.begin() + on_skel.size() / 2, on_skel.end());
    const double half = on_skel[on_skel.size() / 2];
    int crossings = 0;
    for (const auto& cand : kept) {
      const Junction j = junction(skel, cand, k, seen);
      const Eigen::Vector2d at(j.centre.x() + crop.x + 0.5, j.centre.y() + crop.y + 0.5);
      bool ok = false;
      for (const auto& u : j.out)  // arriving along each arm: heading -u
        ok = ok || can_turn_aside(reach, cell_m, params.footprint, cp,
                                  {at, std::atan2(-u.y(), -u.x())});
      out.checks.push_back({at, static_cast<int>(cand.arm_ends.size()), ok});
      if (!ok) continue;
      ++crossings;
      mark_crossing(mask, j, half + cp.crossing_margin_m / cell_m, 2.0 * width, crossings,
                    crossing_of);
    }
    std::vector<int> ids(crossings + 1, 0);
    for (int i = 1; i <= crossings; ++i) ids[i] = add(AreaKind::kCrossing);
    // The rest of the corridor: 4-connected pieces, each a corridor.
    Grid<int> rest(crop.width, crop.height, 0);
    Grid<std::uint8_t> in_piece(crop.width, crop.height, 0);
    for (int r = 0; r < crop.height; ++r)
      for (int c = 0; c < crop.width; ++c) {
        if (!mask.at<std::uint8_t>(r, c)) continue;
        in_piece.at(c, r) = 1;
        const int x = crossing_of.at<int>(r, c);
        if (x) out.labels.at(c + crop.x, r + crop.y) = ids[x];
        else rest.at(c, r) = 1;
      }
    // Cells touching a crossing are left out of the pieces (and given back by the fill below):
    // a one-cell bridge at a crossing's corner must not join two of its arms into one corridor.
    Grid<int> rest_core = rest;
    for (int r = 0; r < crop.height; ++r)
      for (int c = 0; c < crop.width; ++c) {
        if (!rest.at(c, r)) continue;
        for (const auto& dn : kNb) {
          const int cc = c + dn[0], rr = r + dn[1];
          if (cc >= 0 && rr >= 0 && cc < crop.width && rr < crop.height && crossing_of.at<int>(rr, cc))
            rest_core.at(c, r) = 0;
        }
      }
    cv::Mat rest_cc, rest8 = view(rest_core);
    rest8.convertTo(rest8, CV_8U);
    const int ncc = cv::connectedComponents(rest8, rest_cc, 4, CV_32S);
    std::vector<int> cc_size(ncc, 0);
    for (int r = 0; r < crop.height; ++r)
      for (int c = 0; c < crop.width; ++c) ++cc_size[rest_cc.at<int>(r, c)];
    // Pieces shorter than the way is wide are leftovers of the cut: given to their neighbours.
    const int min_piece = static_cast<int>(width * width);
    std::vector<int> cc_id(ncc, 0);
    for (int i = 1; i < ncc; ++i)
      if (cc_size[i] >= min_piece) cc_id[i] = add(AreaKind::kCorridor);
    Grid<int> local(crop.width, crop.height, 0);
    for (int r = 0; r < crop.height; ++r)
      for (int c = 0; c < crop.width; ++c) {
        if (!mask.at<std::uint8_t>(r, c)) continue;
        const int gid = out.labels.at(c + crop.x, r + crop.y);
        const int cc = rest_cc.at<int>(r, c);
        local.at(c, r) = (gid || !cc) ? 0 : cc_id[cc];
      }
    // The cells by the crossings go to the corridors first, then the crossings are put back.
    Grid<std::uint8_t> rest_mask(crop.width, crop.height, 0);
    for (std::size_t i = 0; i < rest.size(); ++i) rest_mask.data[i] = rest.data[i] ? 1 : 0;
    fill_unlabelled(local, rest_mask);
    for (int r = 0; r < crop.height; ++r)
      for (int c = 0; c < crop.width; ++c)
        if (mask.at<std::uint8_t>(r, c) && out.labels.at(c + crop.x, r + crop.y))
          local.at(c, r) = out.labels.at(c + crop.x, r + crop.y);
    fill_unlabelled(local, in_piece);
    if (crossings == 0 && std::none_of(cc_id.begin(), cc_id.end(), [](int v) { return v; })) {
      const int id = add(AreaKind::kCorridor);
      for (std::size_t i = 0; i < local.size(); ++i)
        if (in_piece.data[i]) local.data[i] = id;
    }
    for (int r = 0; r < crop.height; ++r)
      for (int c = 0; c < crop.width; ++c)
        if (in_piece.at(c, r)) out.labels.at(c + crop.x, r + crop.y) = local.at(c, r);
  }
  return out;
}

}  // namespace indoormap::areas::detail
