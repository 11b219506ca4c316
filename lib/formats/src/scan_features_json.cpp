#include "indoormap/formats/scan_features_json.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/formats/json.hpp"
#include "json_write.hpp"

namespace indoormap::formats {

using nlohmann::json;
namespace sf = scan_features;

namespace {

json pose(const laser::Pose2d& p) {
  return {{"x_m", p.x_m}, {"y_m", p.y_m}, {"theta_rad", p.theta_rad}};
}

json walls_json(const std::vector<sf::Wall>& walls) {
  json out = json::array();
  for (const sf::Wall& w : walls)
    out.push_back({{"start_robot", detail::xy_json(w.start_robot)},
                   {"end_robot", detail::xy_json(w.end_robot)},
                   {"start_map", detail::xy_json(w.start_map)},
                   {"end_map", detail::xy_json(w.end_map)},
                   {"length_m", w.length_m()},
                   {"points", w.points},
                   {"rms_m", w.rms_m},
                   {"start", sf::boundary_name(w.start)},
                   {"end", sf::boundary_name(w.end)}});
  return out;
}

json doors_json(const std::vector<sf::Door>& doors) {
  json out = json::array();
  for (const sf::Door& d : doors)
    out.push_back({{"a_robot", detail::xy_json(d.a_robot)},
                   {"b_robot", detail::xy_json(d.b_robot)},
                   {"a_map", detail::xy_json(d.a_map)},
                   {"b_map", detail::xy_json(d.b_map)},
                   {"width_m", d.width_m()},
                   {"kind", sf::door_kind_name(d.kind)},
                   {"walls", {d.wall_before, d.wall_after}}});
  return out;
}

json corners_json(const std::vector<sf::Corner>& corners) {
  json out = json::array();
  for (const sf::Corner& c : corners)
    out.push_back({{"p_robot", detail::xy_json(c.p_robot)},
                   {"p_map", detail::xy_json(c.p_map)},
                   {"type", sf::corner_type_name(c.type)},
                   {"angle_deg", c.angle_rad * 180.0 / std::numbers::pi},
                   {"walls", {c.wall_in, c.wall_out}},
                   {"d_rc_m", c.d_rc_m},
                   {"d_rl_m", c.d_rl_m},
                   {"d_cl_m", c.d_cl_m}});
  return out;
}

json corridors_json(const std::vector<sf::Corridor>& corridors) {
  json out = json::array();
  for (const sf::Corridor& c : corridors)
    out.push_back({{"side_a", c.side_a},
                   {"side_b", c.side_b},
                   {"width_m", c.width_m},
                   {"overlap_m", c.overlap_m}});
  return out;
}

json icp_json(const sf::IcpResult& r, const laser::Pose2d& log) {
  return {
      {"motion_robot", pose(r.transform)},
      {"translation_error_m", (r.transform.position_m() - log.position_m()).norm()},
      {"rotation_error_deg", std::abs(laser::wrap_angle(r.transform.theta_rad - log.theta_rad)) *
                                 180.0 / std::numbers::pi},
      {"rms_m", r.rms_m},
      {"pairs", r.pairs},
      {"iterations", r.iterations},
      {"starts", r.starts},
      {"inlier_share", r.inlier_share},
      {"converged", r.converged}};
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

json scan_features_json(const ScanFeatureRecord& r) {
  const sf::ScanFeatures& f = r.features;
  return {{"scan", r.scan},
          {"time_s", r.time_s},
          {"robot_pose_map", pose(r.robot_pose_map)},
          {"returns", f.returns},
          {"ruptures", f.ruptures},
          {"breakpoints", f.breakpoints},
          {"walls", walls_json(f.walls)},
          {"doors", doors_json(f.doors)},
          {"corners", corners_json(f.corners)},
          {"corridors", corridors_json(f.corridors)}};
}

void write_features_jsonl(const std::filesystem::path& path,
                          std::span<const ScanFeatureRecord> records) {
  write_stream_atomic(path, [&](std::ostream& out) {
    for (const ScanFeatureRecord& r : records) out << scan_features_json(r).dump() << '\n';
  });
}

AlignSummary summarise_alignment(std::span<const AlignRecord> records, AlignSummary s) {
  std::vector<double> t[2][2], a[2][2];
  s.pairs = static_cast<int>(records.size());
  s.moved_pairs = 0;
  for (const AlignRecord& r : records) {
    const bool moved = r.log_motion.position_m().norm() > s.moved_m ||
                       std::abs(r.log_motion.theta_rad) > s.moved_rad;
    s.moved_pairs += moved ? 1 : 0;
    for (int k = 0; k < 2; ++k) {
      const sf::IcpResult& e = k == 0 ? r.point_to_point : r.point_to_line;
      const double te = (e.transform.position_m() - r.log_motion.position_m()).norm();
      const double ae =
          std::abs(laser::wrap_angle(e.transform.theta_rad - r.log_motion.theta_rad)) * 180.0 /
          std::numbers::pi;
      s.converged[k] += e.converged ? 1 : 0;
      for (int m = 0; m < (moved ? 2 : 1); ++m) t[k][m].push_back(te), a[k][m].push_back(ae);
    }
  }
  for (int k = 0; k < 2; ++k)
    for (int m = 0; m < 2; ++m) {
      s.median_translation_error_m[k][m] = median(t[k][m]);
      s.median_rotation_error_deg[k][m] = median(a[k][m]);
    }
  return s;
}

json align_summary_json(const AlignSummary& s) {
  json out = {{"pairs", s.pairs},
              {"moved_pairs", s.moved_pairs},
              {"moved_above_m", s.moved_m},
              {"moved_above_deg", s.moved_rad * 180.0 / std::numbers::pi}};
  for (int k = 0; k < 2; ++k)
    out[k == 0 ? "point_to_point" : "point_to_line"] = {
        {"median_translation_error_m", s.median_translation_error_m[k][0]},
        {"median_rotation_error_deg", s.median_rotation_error_deg[k][0]},
        {"moved_median_translation_error_m", s.median_translation_error_m[k][1]},
        {"moved_median_rotation_error_deg", s.median_rotation_error_deg[k][1]},
        {"converged", s.converged[k]},
        {"median_ms", s.median_ms[k]}};
  return out;
}

void write_align_json(const std::filesystem::path& path, std::span<const AlignRecord> records,
                      const AlignSummary& summary) {
  json pairs = json::array();
  for (const AlignRecord& r : records)
    pairs.push_back({{"scan_ref", r.scan_ref},
                     {"scan_cur", r.scan_cur},
                     {"log_motion_robot", pose(r.log_motion)},
                     {"point_to_point", icp_json(r.point_to_point, r.log_motion)},
                     {"point_to_line", icp_json(r.point_to_line, r.log_motion)}});
  write_json(path, json{{"summary", align_summary_json(summary)}, {"pairs", pairs}});
}

}  // namespace indoormap::formats
