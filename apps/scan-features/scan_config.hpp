#pragma once
// YAML configuration of scan-features (config/scan-features.yaml): sections segments.*, lines.*,
// doors.*, corners.*, corridors.* (scan_features::FeatureParams), icp.* (IcpParams, both
// variants), align.* (the start search and what counts as a moved pair) and log.*
// (formats::CarmenReadOptions). One visit table serves the file reader, --print-config and
// summary.json.
#include <nlohmann/json.hpp>
#include <string>

#include "indoormap/formats/carmen.hpp"
#include "indoormap/scan_features/features.hpp"
#include "indoormap/scan_features/icp.hpp"

namespace indoormap::app {

struct ScanFeaturesConfig {
  scan_features::FeatureParams features;
  scan_features::IcpParams icp;  ///< kind is ignored: --align runs both variants
  scan_features::AlignSearch search;
  double moved_m = 0.05;                    ///< a pair "moved" beyond this translation ...
  double moved_rad = 0.017453292519943295;  ///< ... or this rotation (1 deg) by the log's poses
  formats::CarmenReadOptions log;
  int progress_every_scans = 500;  ///< a progress line on stderr (0: none; -q silences it too)
};

template <class C, class F>
void visit_scan_features(C& c, F&& f) {
  f("segments", "lambda_rad", c.features.segments.lambda_rad);
  f("segments", "sigma_r_m", c.features.segments.sigma_r_m);
  f("segments", "max_range_m", c.features.segments.max_range_m);
  f("lines", "split_distance_m", c.features.lines.split_distance_m);
  f("lines", "merge_distance_m", c.features.lines.merge_distance_m);
  f("lines", "min_points", c.features.lines.min_points);
  f("lines", "min_length_m", c.features.lines.min_length_m);
  f("doors", "min_width_m", c.features.doors.min_width_m);
  f("doors", "max_width_m", c.features.doors.max_width_m);
  f("doors", "max_angle_rad", c.features.doors.max_angle_rad);
  f("doors", "max_offset_m", c.features.doors.max_offset_m);
  f("doors", "min_depth_m", c.features.doors.min_depth_m);
  f("corners", "min_angle_rad", c.features.corners.min_angle_rad);
  f("corners", "max_gap_m", c.features.corners.max_gap_m);
  f("corners", "potential_max_gap_m", c.features.corners.potential_max_gap_m);
  f("corridors", "min_wall_length_m", c.features.corridors.min_wall_length_m);
  f("corridors", "min_width_m", c.features.corridors.min_width_m);
  f("corridors", "max_width_m", c.features.corridors.max_width_m);
  f("corridors", "max_angle_rad", c.features.corridors.max_angle_rad);
  f("corridors", "min_overlap_m", c.features.corridors.min_overlap_m);
  f("corridors", "side_offset_m", c.features.corridors.side_offset_m);
  f("icp", "max_iterations", c.icp.max_iterations);
  f("icp", "max_pair_m", c.icp.max_pair_m);
  f("icp", "trim_factor", c.icp.trim_factor);
  f("icp", "min_trim_m", c.icp.min_trim_m);
  f("icp", "converged_m", c.icp.converged_m);
  f("icp", "converged_rad", c.icp.converged_rad);
  f("icp", "min_pairs", c.icp.min_pairs);
  f("icp", "normal_radius_m", c.icp.normal_radius_m);
  f("icp", "max_range_m", c.icp.max_range_m);
  f("icp", "inlier_m", c.icp.inlier_m);
  f("align", "accept_inlier_share", c.search.accept_inlier_share);
  f("align", "moved_m", c.moved_m);
  f("align", "moved_rad", c.moved_rad);
  f("log", "fov_rad", c.log.fov_rad);
  f("log", "default_max_range_m", c.log.default_max_range_m);
  f("log", "max_line_bytes", c.log.max_line_bytes);
  f("log", "max_beams", c.log.max_beams);
  f("log", "progress_every_scans", c.progress_every_scans);
}

/// Reads a YAML file over config; unknown sections and keys are errors (InputError: file, key,
/// line).
void merge_scan_features_config_file(ScanFeaturesConfig& config, const std::string& path);
/// Every parameter struct's validate(); throws UsageError naming the field.
void validate(const ScanFeaturesConfig& config);
std::string to_yaml(const ScanFeaturesConfig& config);
nlohmann::json to_json(const ScanFeaturesConfig& config);

}  // namespace indoormap::app
