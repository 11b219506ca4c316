#pragma once
// scan-features' files: features.jsonl (one JSON object per scan and line: walls, doors, corners
// with their type, corridors, each in the robot frame and the map frame) and align.json (each
// estimated relative motion of consecutive scans beside the one from the log's poses). Both are
// written atomically. Field names carry units and frames (_robot / _map, _m, _rad, _deg).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <span>
#include <vector>

#include "indoormap/laser/scan.hpp"
#include "indoormap/scan_features/features.hpp"
#include "indoormap/scan_features/icp.hpp"

namespace indoormap::formats {

/// The features of one scan of a log.
struct ScanFeatureRecord {
  int scan = 0;  ///< 0-based index of the FLASER message in the log
  double time_s = 0.0;
  laser::Pose2d robot_pose_map;
  scan_features::ScanFeatures features;
};

/// One line of features.jsonl (without the newline).
nlohmann::json scan_features_json(const ScanFeatureRecord& record);
void write_features_jsonl(const std::filesystem::path& path,
                          std::span<const ScanFeatureRecord> records);

/// One pair of consecutive scans: the robot's motion from scan ref to scan cur, in ref's robot
/// frame, by the log's poses and by each ICP variant.
struct AlignRecord {
  int scan_ref = 0, scan_cur = 0;
  laser::Pose2d log_motion;
  scan_features::IcpResult point_to_point, point_to_line;  ///< transform: robot motion
};

/// The errors of every pair against the log, and their medians (over all pairs and over the
/// pairs whose log motion exceeds moved_m or moved_rad).
struct AlignSummary {
  int pairs = 0, moved_pairs = 0;
  double moved_m = 0.05, moved_rad = 0.017453292519943295;
  /// [variant][0: all, 1: moved]; variant 0 point-to-point, 1 point-to-line.
  double median_translation_error_m[2][2] = {{0, 0}, {0, 0}};
  double median_rotation_error_deg[2][2] = {{0, 0}, {0, 0}};
  int converged[2] = {0, 0};
  double median_ms[2] = {0, 0};
};

/// The summary of the records (moved_m / moved_rad as given in `thresholds`).
AlignSummary summarise_alignment(std::span<const AlignRecord> records,
                                 AlignSummary thresholds = {});
nlohmann::json align_summary_json(const AlignSummary& s);
/// align.json: {"summary": ..., "pairs": [...]}.
void write_align_json(const std::filesystem::path& path, std::span<const AlignRecord> records,
                      const AlignSummary& summary);

}  // namespace indoormap::formats
