#pragma once
// report.html for every app: the page's content built from what the app already has (its
// summary.json and its list of output files), written with the other outputs into the
// OutputSet's directory (formats::write_report_html, lib/formats/report_html.hpp).
//
// What goes where: the provenance block ("Inputs": command line, start, version, revision, each
// input's size and SHA-256), summary.json's top-level values ("Results") and objects (one section
// each; arrays of at most 8 objects entry by entry), "warnings", "timings_ms", every output file
// with a line on what it is (a shared table of the toolkit's file names; an app adds or overrides
// lines through ReportExtras) and the PNG pictures among the outputs, embedded. "parameters" come
// last, folded.
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "indoormap/formats/report_html.hpp"

namespace indoormap::app {

/// The page's file name in every OUTDIR.
inline constexpr const char* kReportFile = "report.html";

struct ReportExtras {
  std::string title;  ///< default: "<program>: <first input's file name>"
  /// Lines for output file names (the file name, without folders) the shared table does not
  /// know or describes differently for this app.
  std::map<std::string, std::string> descriptions;
};

/// One line on what an output file is (by its file name; a generic line by extension otherwise).
std::string describe_output(const std::string& relative_path, const ReportExtras& extras = {});

/// The page for a run whose outputs (paths relative to dir, summary.json among them) are in dir.
formats::ReportContent report_content(const nlohmann::json& summary,
                                      const std::filesystem::path& dir,
                                      const std::vector<std::string>& outputs,
                                      const ReportExtras& extras = {});

/// Writes dir/name from report_content(summary, dir, outputs, extras). Throws OutputError.
void write_report(const std::filesystem::path& dir, const nlohmann::json& summary,
                  const std::vector<std::string>& outputs, const ReportExtras& extras = {},
                  const std::string& name = kReportFile);

}  // namespace indoormap::app
