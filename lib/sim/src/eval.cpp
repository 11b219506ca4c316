#include "indoormap/sim/eval.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "indoormap/core/errors.hpp"

namespace indoormap::sim {

LayoutScores evaluate_layout(const GridGeometry& tg, const Grid<Cell>& truth,
                             const GridGeometry& rg, const Grid<Cell>& result) {
  LayoutScores s;
  // Count cells first, convert to m^2 once: exact for equal resolutions.
  std::array<std::array<std::int64_t, 4>, 4> by_result{}, by_truth{};
  for (int r = 0; r < result.height; ++r) {
    for (int c = 0; c < result.width; ++c) {
      const CellIndex ti = tg.cell_of(rg.center_of({c, r}));
      const Cell t = tg.contains(ti) ? truth.at(ti) : Cell::kUnknown;
      ++by_result[static_cast<int>(t)][static_cast<int>(result.at(c, r))];
    }
  }
  for (int r = 0; r < truth.height; ++r) {
    for (int c = 0; c < truth.width; ++c) {
      if (rg.contains(rg.cell_of(tg.center_of({c, r})))) continue;
      ++by_truth[static_cast<int>(truth.at(c, r))][0];
    }
  }
  const double ra = rg.cell_m() * rg.cell_m(), ta = tg.cell_m() * tg.cell_m();
  for (int t = 0; t < 4; ++t)
    for (int r = 0; r < 4; ++r) s.confusion_m2[t][r] = by_result[t][r] * ra + by_truth[t][r] * ta;
  double agree = 0.0, known = 0.0, iou_sum = 0.0;
  int iou_n = 0;
  for (int k = 0; k < 4; ++k) {
    ClassScore& cs = s.classes[k];
    for (int j = 0; j < 4; ++j) {
      cs.truth_m2 += s.confusion_m2[k][j];
      cs.result_m2 += s.confusion_m2[j][k];
    }
    cs.intersection_m2 = s.confusion_m2[k][k];
    cs.union_m2 = cs.truth_m2 + cs.result_m2 - cs.intersection_m2;
    if (cs.union_m2 > 0) cs.iou = cs.intersection_m2 / cs.union_m2;
    if (k > 0 && cs.iou) {
      iou_sum += *cs.iou;
      ++iou_n;
    }
    for (int j = 0; j < 4; ++j) {
      if (k == 0 && j == 0) continue;
      known += s.confusion_m2[k][j];
      if (k == j) agree += s.confusion_m2[k][j];
    }
  }
  if (iou_n > 0) s.mean_iou = iou_sum / iou_n;
  s.accuracy = known > 0 ? agree / known : 0.0;
  return s;
}

namespace {

struct Footprint {
  Eigen::Vector2d lo, hi;
  double area_m2 = 0.0;
  int index = 0;
};

std::vector<Footprint> footprints(const std::vector<EvalObject>& objects) {
  std::vector<Footprint> out;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (objects[i].footprint.size() < 3) continue;  // no area: matches nothing
    const auto [lo, hi] = bounds(objects[i].footprint);
    out.push_back({lo, hi, std::abs(signed_area(objects[i].footprint)), static_cast<int>(i)});
  }
  return out;
}

// Calls f(t, r) for every truth / result pair whose IoU can reach min_iou (> 0): their boxes
// overlap and the overlap of the boxes is at least min_iou of the larger footprint (the
// intersection is within the boxes' overlap, the union at least the larger area). A sweep over
// the result boxes sorted by their left edge, so that n items spread over a building cost
// O(n log n) box tests instead of the n^2 of testing every pair (30,000 truth items took over a
// minute). The pairs are the same as the all-pairs loop's, so the scores are unchanged.
template <class F>
void for_candidate_pairs(const std::vector<EvalObject>& truth,
                         const std::vector<EvalObject>& result, double min_iou, F&& f) {
  const std::vector<Footprint> tf = footprints(truth);
  std::vector<Footprint> rf = footprints(result);
  if (!(min_iou > 0)) {  // every pair qualifies (IoU 0 >= min_iou)
    for (const auto& t : tf)
      for (const auto& r : rf) f(t.index, r.index);
    return;
  }
  std::sort(rf.begin(), rf.end(),
            [](const Footprint& a, const Footprint& b) { return a.lo.x() < b.lo.x(); });
  double widest = 0.0;
  for (const auto& r : rf) widest = std::max(widest, r.hi.x() - r.lo.x());
  std::vector<double> left(rf.size());
  for (std::size_t i = 0; i < rf.size(); ++i) left[i] = rf[i].lo.x();
  for (const auto& t : tf) {
    // Result boxes that can reach t.lo.x start at most `widest` to its left.
    auto i = static_cast<std::size_t>(
        std::lower_bound(left.begin(), left.end(), t.lo.x() - widest) - left.begin());
    for (; i < rf.size() && rf[i].lo.x() <= t.hi.x(); ++i) {
      const Footprint& r = rf[i];
      const double ox = std::min(t.hi.x(), r.hi.x()) - std::max(t.lo.x(), r.lo.x());
      const double oy = std::min(t.hi.y(), r.hi.y()) - std::max(t.lo.y(), r.lo.y());
      if (ox < 0 || oy < 0) continue;
      // A margin for the raster IoU's own error, so that no pair it would accept is dropped.
      if (ox * oy < 0.5 * min_iou * std::max(t.area_m2, r.area_m2)) continue;
      f(t.index, r.index);
    }
  }
}

}  // namespace

ObjectScores evaluate_objects(const std::vector<EvalObject>& truth,
                              const std::vector<EvalObject>& result, double min_iou) {
  ObjectScores s;
  s.truth_count = static_cast<int>(truth.size());
  s.result_count = static_cast<int>(result.size());
  struct Pair {
    double iou;
    int t, r;
  };
  std::vector<Pair> pairs = [&] {
    std::vector<Pair> out;
    for_candidate_pairs(truth, result, min_iou, [&](int t, int r) {
      const double iou = polygon_iou(truth[t].footprint, result[r].footprint, 0.01);
      if (iou >= min_iou) out.push_back({iou, t, r});
    });
    return out;
  }();
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    if (a.iou != b.iou) return a.iou > b.iou;
    return a.t != b.t ? a.t < b.t : a.r < b.r;
  });
  std::vector<bool> t_used(truth.size()), r_used(result.size());
  double sum_top = 0.0, sum_bottom = 0.0, worst = 0.0;
  int n_top = 0, n_bottom = 0;
  for (const Pair& p : pairs) {
    if (t_used[p.t] || r_used[p.r]) continue;
    t_used[p.t] = r_used[p.r] = true;
    ObjectMatch m;
    m.truth_id = truth[p.t].id;
    m.result_id = result[p.r].id;
    m.iou = p.iou;
    if (truth[p.t].z_max_m && result[p.r].z_max_m) {
      m.z_max_error_m = *result[p.r].z_max_m - *truth[p.t].z_max_m;
      sum_top += std::abs(*m.z_max_error_m);
      worst = std::max(worst, std::abs(*m.z_max_error_m));
      ++n_top;
    }
    if (truth[p.t].z_min_m && result[p.r].z_min_m) {
      m.z_min_error_m = *result[p.r].z_min_m - *truth[p.t].z_min_m;
      sum_bottom += std::abs(*m.z_min_error_m);
      worst = std::max(worst, std::abs(*m.z_min_error_m));
      ++n_bottom;
    }
    s.matches.push_back(std::move(m));
  }
  s.matched = static_cast<int>(s.matches.size());
  for (int t = 0; t < s.truth_count; ++t)
    if (!t_used[t]) s.missed.push_back(truth[t].id);
  for (int r = 0; r < s.result_count; ++r)
    if (!r_used[r]) s.spurious.push_back(result[r].id);
  s.recall = s.truth_count > 0 ? static_cast<double>(s.matched) / s.truth_count : 0.0;
  s.precision = s.result_count > 0 ? static_cast<double>(s.matched) / s.result_count : 0.0;
  if (n_top > 0) s.mean_abs_z_max_error_m = sum_top / n_top;
  if (n_bottom > 0) s.mean_abs_z_min_error_m = sum_bottom / n_bottom;
  if (n_top + n_bottom > 0) s.max_abs_height_error_m = worst;
  return s;
}

void validate(const EvalParams& params) {
  if (!(params.min_object_iou > 0 && params.min_object_iou <= 1))
    throw UsageError("invalid parameter min_object_iou: must be in (0, 1]");
  if (!(params.min_truth_area_m2 >= 0 && params.min_truth_area_m2 <= 100))
    throw UsageError("invalid parameter min_object_area_m2: must be in [0, 100] m^2");
}

ObjectScores evaluate_objects(const std::vector<EvalObject>& truth, std::vector<EvalObject> result,
                              const EvalParams& params) {
  validate(params);
  std::vector<EvalObject> expected;
  for (const auto& f : truth)
    if (f.on_floor || params.include_hanging) expected.push_back(f);
  // Without include_hanging both sides are what stands on the floor: result objects of kind
  // "hanging" or "lamp" are left out as the truth's lamps are.
  if (!params.include_hanging)
    std::erase_if(result, [](const EvalObject& o) { return !o.on_floor; });
  ObjectScores s = evaluate_objects(expected, result, params.min_object_iou);
  s.matched_all = s.matched;
  std::vector<std::string> small;
  for (const auto& f : expected)
    if (std::abs(signed_area(f.footprint)) < params.min_truth_area_m2) small.push_back(f.id);
  if (small.empty()) return s;
  auto is_small = [&](const std::string& id) {
    return std::find(small.begin(), small.end(), id) != small.end();
  };
  s.truth_below_min_area = static_cast<int>(small.size());
  s.truth_count -= s.truth_below_min_area;
  s.matched =
      static_cast<int>(std::count_if(s.matches.begin(), s.matches.end(),
                                     [&](const ObjectMatch& m) { return !is_small(m.truth_id); }));
  std::erase_if(s.missed, is_small);
  s.recall = s.truth_count > 0 ? static_cast<double>(s.matched) / s.truth_count : 0.0;
  s.precision = s.result_count > 0 ? static_cast<double>(s.matched_all) / s.result_count : 0.0;
  return s;
}

std::vector<RoomMatch> evaluate_rooms(const std::vector<TruthRoom>& truth,
                                      const std::vector<Polygon>& result) {
  std::vector<RoomMatch> out;
  for (std::size_t r = 0; r < result.size(); ++r) {
    RoomMatch m;
    m.result_index = static_cast<int>(r);
    m.result_area_m2 = std::abs(signed_area(result[r]));
    for (std::size_t t = 0; t < truth.size(); ++t) {
      const double iou = polygon_iou(truth[t].polygon, result[r], 0.02);
      if (iou > m.iou) {
        m.iou = iou;
        m.truth_index = static_cast<int>(t);
      }
    }
    if (m.truth_index >= 0) {
      const TruthRoom& t = truth[m.truth_index];
      m.truth_name = t.name;
      m.truth_area_m2 = std::abs(signed_area(t.polygon));
      m.hausdorff_m = boundary_hausdorff(t.polygon, result[r], 0.01);
      m.area_error_m2 = m.result_area_m2 - m.truth_area_m2;
      m.area_error_rel = m.truth_area_m2 > 0 ? m.area_error_m2 / m.truth_area_m2 : 0.0;
    }
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace indoormap::sim
