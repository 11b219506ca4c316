#include "scan_outputs.hpp"

#include <chrono>
#include <cstdio>

#include "indoormap/draw/scan_features_png.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/version.hpp"
#include "provenance.hpp"
#include "report.hpp"

namespace indoormap::app {

using nlohmann::json;

json scan_features_result_json(const ScanFeaturesRun& run) {
  std::size_t walls = 0, doors = 0, corridors = 0, corners[3] = {0, 0, 0};
  for (const auto& r : run.records) {
    walls += r.features.walls.size();
    doors += r.features.doors.size();
    corridors += r.features.corridors.size();
    for (const auto& c : r.features.corners) ++corners[static_cast<int>(c.type)];
  }
  json j = {{"scans_read", run.stats.scans},
            {"scans_used", run.records.size()},
            {"scans_skipped", run.scans_skipped},
            {"picture_scan", run.picture_scan},
            {"walls", walls},
            {"doors", doors},
            {"corners", {{"inner", corners[0]}, {"outer", corners[1]}, {"potential", corners[2]}}},
            {"corridors", corridors}};
  if (run.align) j["align"] = formats::align_summary_json(run.align_summary);
  return j;
}

std::vector<std::string> write_scan_features_outputs(const std::filesystem::path& out,
                                                     const ScanFeaturesRun& run, json timings_ms) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::string> files;
  formats::write_features_jsonl(out / "features.jsonl", run.records);
  files.push_back("features.jsonl");
  const std::string png = "scan_" + std::to_string(run.picture_scan) + ".png";
  const auto& rec = *std::find_if(run.records.begin(), run.records.end(),
                                  [&](const auto& r) { return r.scan == run.picture_scan; });
  char title[256];
  std::snprintf(title, sizeof title, "scan-features: %s scan %d: %zu walls, %zu doors, %zu corners",
                std::filesystem::path(run.log_path).filename().string().c_str(), run.picture_scan,
                rec.features.walls.size(), rec.features.doors.size(), rec.features.corners.size());
  draw::write_scan_features_png(out / png, *run.picture, rec.features, title);
  files.push_back(png);
  if (run.align) {
    formats::write_align_json(out / "align.json", run.pairs, run.align_summary);
    files.push_back("align.json");
  }
  files.push_back(kReportFile);
  files.push_back("summary.json");
  timings_ms["write"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const json summary = {{"program", "scan-features"},
                        {"version", kVersion},
                        {"provenance", provenance_json({run.log_path})},
                        {"log", run.log_path},
                        {"parameters", to_json(run.config)},
                        {"result", scan_features_result_json(run)},
                        {"timings_ms", timings_ms},
                        {"outputs", files}};
  formats::write_json(out / "summary.json", summary);
  write_report(out, summary, files);
  return files;
}

}  // namespace indoormap::app
