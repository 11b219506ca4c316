// Corridors and crossings (docs/grid-areas.md, "Corridors and crossings").
#include "corridors.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "indoormap/areas/fan.hpp"
#include "label_ops.hpp"

namespace indoormap::areas::detail {
namespace {

constexpr int kNb[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};

/// Skeleton cells at exactly k 8-steps (along the skeleton) from start, and all cells within k.
struct Reach {
  std::vector<cv::Point> rim;
  std::vector<cv::Point> within;
};
Reach skeleton_reach(const cv::Mat& skel, cv::Point start, int k, cv::Mat& seen) {
  Reach out;
  std::vector<std::pair<cv::Point, int>> queue{{start, 0}};
  seen.at<int>(start) = 1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const auto [p, dist] = queue[head];
    out.within.push_back(p);
    if (dist == k) {
      out.rim.push_back(p);
      continue;
    }
    for (const auto& d : kNb) {
      const cv::Point q(p.x + d[0], p.y + d[1]);
      if (q.x < 0 || q.y < 0 || q.x >= skel.cols || q.y >= skel.rows) continue;
      if (!skel.at<std::uint8_t>(q) || seen.at<int>(q)) continue;
      seen.at<int>(q) = 1;
      queue.push_back({q, dist + 1});
    }
  }
  for (const auto& p : out.within) seen.at<int>(p) = 0;
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

}  // namespace

CorridorSplit split_corridors(const Grid<int>& pieces, int n, const Grid<std::uint8_t>& reach,
                              const Grid<std::uint8_t>& free, double cell_m,
                              const AreasParams& params) {
  const CorridorParams& cp = params.corridors;
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
    cv::Mat seen(crop.size(), CV_32S, cv::Scalar(0));
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
    const int cut = std::max(1, static_cast<int>(std::lround(0.5 * width + cp.crossing_margin_m / cell_m)));
    int crossings = 0;
    std::vector<int> crossing_ids;
    for (const auto& cand : kept) {
      const Eigen::Vector2d at(cand.at.x + crop.x + 0.5, cand.at.y + crop.y + 0.5);
      bool ok = false;
      for (const auto& e : cand.arm_ends) {
        const Eigen::Vector2d dir(cand.at.x - e.x, cand.at.y - e.y);
        ok = ok || can_turn_aside(reach, cell_m, params.footprint, cp,
                                  {at, std::atan2(dir.y(), dir.x())});
      }
      out.checks.push_back({at, static_cast<int>(cand.arm_ends.size()), ok});
      if (!ok) continue;
      ++crossings;
      for (const auto& q : skeleton_reach(skel, cand.at, cut, seen).within)
        if (!crossing_of.at<int>(q)) crossing_of.at<int>(q) = crossings;
    }
    (void)free;
    // Each cell goes with its nearest skeleton cell.
    cv::Mat inv = 1 - skel, dist, nearest;
    cv::distanceTransform(inv, dist, nearest, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
    std::vector<int> crossing_of_label(static_cast<std::size_t>(crop.area()) + 1, 0);
    for (int r = 0; r < skel.rows; ++r)
      for (int c = 0; c < skel.cols; ++c)
        if (skel.at<std::uint8_t>(r, c)) crossing_of_label[nearest.at<int>(r, c)] = crossing_of.at<int>(r, c);
    std::vector<int> ids(crossings + 1, 0);
    for (int i = 1; i <= crossings; ++i) ids[i] = add(AreaKind::kCrossing);
    // The rest of the corridor: 4-connected pieces, each a corridor.
    Grid<int> rest(crop.width, crop.height, 0);
    Grid<std::uint8_t> in_piece(crop.width, crop.height, 0);
    for (int r = 0; r < crop.height; ++r)
      for (int c = 0; c < crop.width; ++c) {
        if (!mask.at<std::uint8_t>(r, c)) continue;
        in_piece.at(c, r) = 1;
        const int x = crossing_of_label[nearest.at<int>(r, c)];
        if (x) out.labels.at(c + crop.x, r + crop.y) = ids[x];
        else rest.at(c, r) = 1;
      }
    cv::Mat rest_cc, rest8 = view(rest);
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
        local.at(c, r) = gid ? gid : (cc ? cc_id[cc] : 0);
      }
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
