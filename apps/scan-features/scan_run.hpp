#pragma once
// scan-features' run as values: the features of every scan of a log, the scan to draw, and with
// --align the relative motion of every pair of consecutive scans by both ICP variants beside the
// log's. Everything is computed before the first file is written.
#include <optional>
#include <string>
#include <vector>

#include "indoormap/formats/carmen.hpp"
#include "indoormap/formats/scan_features_json.hpp"
#include "scan_config.hpp"

namespace indoormap::app {

struct ScanFeaturesRun {
  std::string log_path;
  ScanFeaturesConfig config;
  formats::CarmenStats stats;
  std::size_t scans_skipped = 0;  ///< FLASER messages laser::validate rejects (non-finite pose)
  std::vector<formats::ScanFeatureRecord> records;
  int picture_scan = 0;
  std::optional<laser::LaserScan> picture;  ///< the scan --scan asked for, when the log has it
  bool align = false;
  std::vector<formats::AlignRecord> pairs;
  formats::AlignSummary align_summary;
  double features_ms = 0.0, align_ms = 0.0, read_ms = 0.0;
};

/// Reads the log once (progress on stderr every config.progress_every_scans scans unless quiet).
/// Throws InputError on a bad line.
ScanFeaturesRun run_scan_features(const std::string& log_path, const ScanFeaturesConfig& config,
                                  int picture_scan, bool align, bool quiet);

}  // namespace indoormap::app
