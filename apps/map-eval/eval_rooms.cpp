#include "eval_rooms.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "indoormap/core/polygon.hpp"
#include "indoormap/formats/objects_json.hpp"
#include "indoormap/formats/rooms_json.hpp"

namespace indoormap::map_eval {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

Eigen::Vector2d eval_rooms_centroid(const Polygon& p) {
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& v : p) c += v;
  return p.empty() ? c : c / static_cast<double>(p.size());
}

/// The truth room (index) holding p, or -1.
int eval_rooms_truth_at(const formats::TruthFile& t, const Eigen::Vector2d& p) {
  for (std::size_t i = 0; i < t.rooms.size(); ++i)
    if (contains(t.rooms[i].polygon, p)) return static_cast<int>(i);
  return -1;
}

/// Objects per truth room: truth items (of at least min_truth_area_m2) and their matches, and
/// the result objects whose footprint centre lies in the room; `outside` counts those in none.
ordered_json eval_rooms_objects(const formats::TruthFile& truth, const fs::path& dir,
                                const sim::EvalParams& op, int& outside) {
  const std::size_t nt = truth.rooms.size();
  ordered_json per_room = ordered_json::array();
  if (fs::exists(dir / "objects.json")) {
    const auto objs = formats::read_objects_json(dir / "objects.json");
    const sim::ObjectScores s = sim::evaluate_objects(truth.furniture, objs, op);
    std::map<std::string, bool> matched_truth, matched_result;
    for (const auto& m : s.matches) matched_truth[m.truth_id] = matched_result[m.result_id] = true;
    std::vector<int> t_n(nt, 0), t_m(nt, 0), r_n(nt, 0), r_m(nt, 0);
    for (const auto& o : truth.furniture) {
      if (!o.on_floor && !op.include_hanging) continue;
      if (std::abs(signed_area(o.footprint)) < op.min_truth_area_m2) continue;
      const int k = eval_rooms_truth_at(truth, eval_rooms_centroid(o.footprint));
      if (k < 0) continue;
      ++t_n[static_cast<std::size_t>(k)];
      t_m[static_cast<std::size_t>(k)] += matched_truth.count(o.id) ? 1 : 0;
    }
    for (const auto& o : objs) {
      if (!o.on_floor && !op.include_hanging) continue;
      const int k = eval_rooms_truth_at(truth, eval_rooms_centroid(o.footprint));
      if (k < 0) {
        ++outside;
        continue;
      }
      ++r_n[static_cast<std::size_t>(k)];
      r_m[static_cast<std::size_t>(k)] += matched_result.count(o.id) ? 1 : 0;
    }
    for (std::size_t k = 0; k < nt; ++k)
      per_room.push_back({{"truth_room", truth.rooms[k].name},
                          {"truth_objects", t_n[k]},
                          {"truth_matched", t_m[k]},
                          {"result_objects", r_n[k]},
                          {"result_matched", r_m[k]}});
  }
  return per_room;
}

}  // namespace

ordered_json evaluate_rooms_block(const formats::TruthFile& truth, const fs::path& dir,
                                  const sim::EvalParams& op, const RoomEvalParams& p) {
  const fs::path file = dir / "rooms.geojson";
  if (!fs::exists(file)) return {{"status", "missing"}, {"file", "rooms.geojson"}};
  const formats::RoomsFile res = formats::read_rooms_geojson(file);
  const std::size_t nt = truth.rooms.size(), nr = res.rooms.size();
  // Intersection areas from IoU: I = IoU (A + B) / (1 + IoU).
  std::vector<std::vector<double>> inter(nt, std::vector<double>(nr, 0.0));
  std::vector<double> ta(nt), ra(nr);
  for (std::size_t j = 0; j < nr; ++j) ra[j] = std::abs(signed_area(res.rooms[j].polygon));
  for (std::size_t i = 0; i < nt; ++i) {
    ta[i] = std::abs(signed_area(truth.rooms[i].polygon));
    for (std::size_t j = 0; j < nr; ++j) {
      const double iou = polygon_iou(truth.rooms[i].polygon, res.rooms[j].polygon, 0.02);
      inter[i][j] = iou * (ta[i] + ra[j]) / (1.0 + iou);
    }
  }
  ordered_json list = ordered_json::array();
  int found = 0, missed = 0, split = 0, merged = 0, within = 0;
  for (std::size_t i = 0; i < nt; ++i) {
    int best = -1, covering = 0;
    for (std::size_t j = 0; j < nr; ++j) {
      if (inter[i][j] >= p.cover_min * ta[i] || inter[i][j] >= p.cover_min * ra[j]) ++covering;
      if (best < 0 || inter[i][j] > inter[i][static_cast<std::size_t>(best)])
        best = static_cast<int>(j);
    }
    ordered_json r = {{"truth_room", truth.rooms[i].name},
                      {"kind", truth.rooms[i].kind},
                      {"truth_area_m2", ta[i]}};
    if (best < 0 || inter[i][static_cast<std::size_t>(best)] < p.cover_min * ta[i]) {
      r["status"] = "missed";
      ++missed;
      list.push_back(r);
      continue;
    }
    const auto b = static_cast<std::size_t>(best);
    int truths_in_best = 0;  // truth rooms that the best result room covers largely
    for (std::size_t k = 0; k < nt; ++k)
      if (inter[k][b] >= p.cover_min * ta[k]) ++truths_in_best;
    const double iou = inter[i][b] / (ta[i] + ra[b] - inter[i][b]);
    const double h = boundary_hausdorff(truth.rooms[i].polygon, res.rooms[b].polygon);
    const double rel = (ra[b] - ta[i]) / ta[i];
    std::string status = "found";
    if (truths_in_best > 1)
      status = "merged", ++merged;
    else if (covering > 1)
      status = "split", ++split;
    else
      ++found;
    const bool ok =
        status == "found" && h <= p.hausdorff_max_m && std::abs(rel) <= p.area_error_max_rel;
    within += ok ? 1 : 0;
    r["status"] = status;
    r["result_room"] = res.rooms[b].id;
    r["iou"] = iou;
    r["hausdorff_m"] = h;
    r["result_area_m2"] = ra[b];
    r["area_error_rel"] = rel;
    r["within_tolerance"] = ok;
    list.push_back(r);
  }
  // Doors: a truth door is found when a result door's midpoint lies within door_match_m of the
  // centre of its passage (the opening's midpoint moved half the wall thickness into the wall).
  ordered_json doors = ordered_json::array();
  int doors_found = 0;
  for (const auto& d : truth.doors) {
    const Eigen::Vector2d centre = 0.5 * (d.a + d.b) + 0.5 * d.wall_thickness_m * d.outward;
    double nearest = 1e300;
    for (const auto& rd : res.doors)
      nearest = std::min(nearest, (0.5 * (rd.end0_m + rd.end1_m) - centre).norm());
    const bool ok = nearest <= p.door_match_m;
    doors_found += ok ? 1 : 0;
    doors.push_back(
        {{"id", d.id},
         {"found", ok},
         {"distance_m", res.doors.empty() ? ordered_json(nullptr) : ordered_json(nearest)}});
  }
  int outside = 0;  // result objects whose centre lies in no truth room (in a wall, or outside)
  const ordered_json per_room = eval_rooms_objects(truth, dir, op, outside);
  const auto share = [](int a, std::size_t b) {
    return b ? ordered_json(static_cast<double>(a) / static_cast<double>(b))
             : ordered_json(nullptr);
  };
  return {
      {"status", "ok"},
      {"file", "rooms.geojson"},
      {"truth_rooms", nt},
      {"result_rooms", nr},
      {"found", found},
      {"missed", missed},
      {"split", split},
      {"merged", merged},
      {"within_tolerance", within},
      {"within_tolerance_share", share(within, nt)},
      {"tolerance", {{"hausdorff_m", p.hausdorff_max_m}, {"area_error_rel", p.area_error_max_rel}}},
      {"truth_doors", truth.doors.size()},
      {"doors_found", doors_found},
      {"doors_found_share", share(doors_found, truth.doors.size())},
      {"result_doors", res.doors.size()},
      {"rooms", list},
      {"doors", doors},
      {"objects_outside_rooms", outside},
      {"objects_per_room", per_room}};
}

}  // namespace indoormap::map_eval
