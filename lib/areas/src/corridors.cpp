// Corridors and crossings (docs/grid-areas.md, "Corridors and crossings").
#include "corridors.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <queue>

#include "indoormap/areas/fan.hpp"
#include "label_ops.hpp"

namespace indoormap::areas::detail {
namespace {

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

/// The arms' directions from their cells at path length k / 2 and k; the centre is the
/// least-squares meeting point of their centre lines (the skeleton's own junction point lies off
/// the centre: in a T it is up the stem, where the inscribed circle is largest).
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
  const cv::Point c0(static_cast<int>(std::lround(j.centre.x())),
                     static_cast<int>(std::lround(j.centre.y())));
  if (c0.x < 0 || c0.y < 0 || c0.x >= mask.cols || c0.y >= mask.rows || !mask.at<std::uint8_t>(c0))
    return;
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

/// A room piece cut out of the label grid: its mask in a crop (2 cells of padding), the mask with
/// its holes filled, and the filled mask's clearance.
struct Piece {
  cv::Rect crop;
  cv::Mat mask, filled, d;
  double width = 0.0;  ///< estimated width of the way (cells)
};

Piece cut_piece(const Grid<int>& pieces, int l, cv::Rect b) {
  Piece p;
  p.crop = cv::Rect(b.x - 2, b.y - 2, b.width + 4, b.height + 4);
  p.mask = cv::Mat(p.crop.size(), CV_8U, cv::Scalar(0));
  for (int r = b.y; r < b.y + b.height; ++r)
    for (int c = b.x; c < b.x + b.width; ++c)
      if (pieces.at(c, r) == l) p.mask.at<std::uint8_t>(r - p.crop.y, c - p.crop.x) = 1;
  // Holes (furniture) filled: the way's width is the walls', not the gaps between tables.
  std::vector<std::vector<cv::Point>> outer;
  cv::findContours(p.mask.clone(), outer, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  p.filled = cv::Mat(p.crop.size(), CV_8U, cv::Scalar(0));
  cv::drawContours(p.filled, outer, -1, cv::Scalar(1), cv::FILLED);
  cv::distanceTransform(p.filled, p.d, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  std::vector<float> dv;
  for (int r = 0; r < p.d.rows; ++r)
    for (int c = 0; c < p.d.cols; ++c)
      if (p.filled.at<std::uint8_t>(r, c)) dv.push_back(p.d.at<float>(r, c));
  std::nth_element(dv.begin(), dv.begin() + static_cast<long>(dv.size() * 9 / 10), dv.end());
  // A long strip of width W: 90 % of its cells are within 0.45 W of a wall.
  p.width = 2.0 * dv[dv.size() * 9 / 10] / 0.9;
  return p;
}

bool is_corridor(const Piece& p, double cell_m, const CorridorParams& cp) {
  return p.width * cell_m <= cp.max_width_m &&
         cv::countNonZero(p.filled) >= cp.min_elongation * p.width * p.width;
}

/// Junction (3+ arms at path length k) and corner (2 arms bent by corner_min_deg) candidates, at
/// most one per 1.5 k, junctions first.
std::vector<Candidate> candidates(const cv::Mat& skel, const cv::Mat& d, int k,
                                  const CorridorParams& cp, cv::Mat& scratch) {
  std::vector<Candidate> cands;
  const double max_cos = std::cos((180.0 - cp.corner_min_deg) * std::numbers::pi / 180.0);
  for (int r = 0; r < skel.rows; ++r)
    for (int c = 0; c < skel.cols; ++c) {
      if (!skel.at<std::uint8_t>(r, c)) continue;
      const cv::Point p(c, r);
      const auto ends = arms(skeleton_reach(skel, p, k, scratch).rim);
      if (ends.size() >= 3) {
        cands.push_back({p, ends, 1000.0 + d.at<float>(p)});
      } else if (ends.size() == 2) {
        const cv::Point2d u = ends[0] - cv::Point2d(p), v = ends[1] - cv::Point2d(p);
        const double cosang = u.dot(v) / std::max(1e-9, std::sqrt(u.dot(u) * v.dot(v)));
        if (cosang > max_cos) cands.push_back({p, ends, cosang});
      }
    }
  std::sort(cands.begin(), cands.end(),
            [](const Candidate& a, const Candidate& b) { return a.priority > b.priority; });
  std::vector<Candidate> kept;
  for (const auto& cand : cands) {
    bool near = false;
    for (const auto& o : kept) near = near || cv::norm(cand.at - o.at) < 1.5 * k;
    if (!near) kept.push_back(cand);
  }
  return kept;
}

/// Median clearance on the skeleton: the way's half width (cells).
double half_width(const cv::Mat& skel, const cv::Mat& d, double fallback) {
  std::vector<float> on_skel;
  for (int r = 0; r < skel.rows; ++r)
    for (int c = 0; c < skel.cols; ++c)
      if (skel.at<std::uint8_t>(r, c)) on_skel.push_back(d.at<float>(r, c));
  if (on_skel.empty()) return fallback;
  std::nth_element(on_skel.begin(), on_skel.begin() + on_skel.size() / 2, on_skel.end());
  return on_skel[on_skel.size() / 2];
}

/// Confirms each candidate with the fan-of-turns test (arriving along each arm at the junction's
/// centre) and marks the confirmed crossings 1..m in the returned crop-sized CV_32S image.
cv::Mat confirmed_crossings(const Piece& p, const Grid<std::uint8_t>& reach, double cell_m,
                            const AreasParams& params, std::vector<CrossingCheck>& checks,
                            int& count) {
  const CorridorParams& cp = params.corridors;
  cv::Mat skel = p.filled.clone();
  thin(skel);
  const int k = std::max(3, static_cast<int>(std::lround(p.width)));
  prune(skel, k);
  cv::Mat scratch(p.crop.size(), CV_32F, cv::Scalar(-1.0f));
  const double half = half_width(skel, p.d, 0.5 * p.width);
  cv::Mat crossing_of(p.crop.size(), CV_32S, cv::Scalar(0));
  count = 0;
  for (const auto& cand : candidates(skel, p.d, k, cp, scratch)) {
    const Junction j = junction(skel, cand, k, scratch);
    const Eigen::Vector2d at(j.centre.x() + p.crop.x + 0.5, j.centre.y() + p.crop.y + 0.5);
    bool ok = false;
    for (const auto& u : j.out)  // arriving along each arm: heading -u
      ok = ok ||
           can_turn_aside(reach, cell_m, params.footprint, cp, {at, std::atan2(-u.y(), -u.x())});
    checks.push_back({at, static_cast<int>(cand.arm_ends.size()), ok});
    if (!ok) continue;
    mark_crossing(p.mask, j, half + cp.crossing_margin_m / cell_m, 2.0 * p.width, ++count,
                  crossing_of);
  }
  return crossing_of;
}

/// The corridor's cells without the crossings, as 4-connected pieces: labels (crop-sized) of
/// the pieces of at least min_cells (new corridor ids from add), 0 elsewhere. Cells touching a
/// crossing are left out of the pieces: a one-cell bridge at a crossing's corner must not join
/// two of its arms into one corridor.
template <class Add>
Grid<int> corridor_pieces(const Grid<int>& rest, const cv::Mat& crossing_of, int min_cells,
                          Add&& add) {
  Grid<int> core = rest;
  for (int r = 0; r < rest.height; ++r)
    for (int c = 0; c < rest.width; ++c) {
      if (!rest.at(c, r)) continue;
      for (const auto& dn : kNb) {
        const int cc = c + dn[0], rr = r + dn[1];
        if (cc >= 0 && rr >= 0 && cc < rest.width && rr < rest.height &&
            crossing_of.at<int>(rr, cc))
          core.at(c, r) = 0;
      }
    }
  cv::Mat cc_img, core8 = view(core);
  core8.convertTo(core8, CV_8U);
  const int ncc = cv::connectedComponents(core8, cc_img, 4, CV_32S);
  std::vector<int> size(ncc, 0), id(ncc, 0);
  for (int r = 0; r < rest.height; ++r)
    for (int c = 0; c < rest.width; ++c) ++size[cc_img.at<int>(r, c)];
  for (int i = 1; i < ncc; ++i)
    if (size[i] >= min_cells) id[i] = add(AreaKind::kCorridor);
  Grid<int> out(rest.width, rest.height, 0);
  for (int r = 0; r < rest.height; ++r)
    for (int c = 0; c < rest.width; ++c) out.at(c, r) = id[cc_img.at<int>(r, c)];
  return out;
}

}  // namespace

CorridorSplit split_corridors(const Grid<int>& pieces, int n, const Grid<std::uint8_t>& reach,
                              const Grid<std::uint8_t>& free, double cell_m,
                              const AreasParams& params) {
  (void)free;  // the fan-of-turns test runs on reach: the footprint's own free space
  std::vector<cv::Rect> box(n + 1);
  std::vector<bool> seen_label(n + 1, false);
  for (int r = 0; r < pieces.height; ++r)
    for (int c = 0; c < pieces.width; ++c) {
      const int l = pieces.at(c, r);
      if (l <= 0) continue;
      box[l] = seen_label[l] ? (box[l] | cv::Rect(c, r, 1, 1)) : cv::Rect(c, r, 1, 1);
      seen_label[l] = true;
    }
  CorridorSplit out;
  out.labels = Grid<int>(pieces.width, pieces.height, 0);
  auto add = [&](AreaKind k) {
    out.kinds.push_back(k);
    return static_cast<int>(out.kinds.size());
  };
  for (int l = 1; l <= n; ++l) {
    if (!seen_label[l]) continue;
    const Piece p = cut_piece(pieces, l, box[l]);
    const cv::Rect crop = p.crop;
    if (!is_corridor(p, cell_m, params.corridors)) {
      const int id = add(AreaKind::kRoom);
      for (int r = 0; r < crop.height; ++r)
        for (int c = 0; c < crop.width; ++c)
          if (p.mask.at<std::uint8_t>(r, c)) out.labels.at(c + crop.x, r + crop.y) = id;
      continue;
    }
    int crossings = 0;
    const cv::Mat crossing_of =
        confirmed_crossings(p, reach, cell_m, params, out.checks, crossings);
    std::vector<int> ids(crossings + 1, 0);
    for (int i = 1; i <= crossings; ++i) ids[i] = add(AreaKind::kCrossing);
    Grid<int> rest(crop.width, crop.height, 0), local(crop.width, crop.height, 0);
    Grid<std::uint8_t> in_piece(crop.width, crop.height, 0), rest_mask(crop.width, crop.height, 0);
    for (int r = 0; r < crop.height; ++r)
      for (int c = 0; c < crop.width; ++c) {
        if (!p.mask.at<std::uint8_t>(r, c)) continue;
        in_piece.at(c, r) = 1;
        rest.at(c, r) = rest_mask.at(c, r) = crossing_of.at<int>(r, c) ? 0 : 1;
      }
    // Pieces shorter than the way is wide are leftovers of the cut: given to their neighbours,
    // corridors first, then the crossings are put back.
    local = corridor_pieces(rest, crossing_of, static_cast<int>(p.width * p.width), add);
    const bool no_corridor =
        std::none_of(local.data.begin(), local.data.end(), [](int v) { return v; });
    fill_unlabelled(local, rest_mask);
    for (int r = 0; r < crop.height; ++r)
      for (int c = 0; c < crop.width; ++c)
        if (const int x = crossing_of.at<int>(r, c); x && in_piece.at(c, r))
          local.at(c, r) = ids[x];
    fill_unlabelled(local, in_piece);
    if (crossings == 0 && no_corridor) {
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
