#pragma once
// The files of a scan-features run: features.jsonl, scan_<N>.png, align.json (with --align) and
// summary.json, all written by one function at the end of main.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scan_run.hpp"

namespace indoormap::app {

/// summary.json's "result": counts, feature totals and the alignment figures.
nlohmann::json scan_features_result_json(const ScanFeaturesRun& run);

/// Writes every output into out (each atomically); summary.json last, holding `timings_ms` and
/// the list of files. Returns the names in writing order.
std::vector<std::string> write_scan_features_outputs(const std::filesystem::path& out,
                                                     const ScanFeaturesRun& run,
                                                     nlohmann::json timings_ms);

}  // namespace indoormap::app
