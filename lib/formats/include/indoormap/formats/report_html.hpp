#pragma once
// report.html: one self-contained page per run (every app writes one into its OUTDIR): the
// inputs with their provenance, the main figures, warnings, stage timings, each output file with
// a line on what it is, and the pictures embedded as base64 data URIs. No network, no external
// CSS or JS: the page opens from a USB stick. Every text is HTML-escaped.
//
// Machine-checkable (tests/test_report_slow.cpp reads it through a headless browser):
//   - every figure's value (and table cell) is
//     `<td class="v" data-key="JSON pointer into summary.json">text</td>`;
//   - an inline script sets, on load, `data-loaded="true"`, `data-images` (the number of <img>)
//     and `data-images-shown` (those complete with naturalWidth > 0) on `<p id="check">`.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace indoormap::formats {

/// One figure: its label, its value as displayed, and where it comes from (a JSON pointer into
/// the run's summary.json, e.g. "/points/read"; empty when it comes from nowhere checkable).
struct ReportFigure {
  std::string label;
  std::string value;
  std::string key;
};

struct ReportSection {
  std::string title;
  std::vector<ReportFigure> figures;
  bool collapsed = false;  ///< shown folded (<details>), e.g. the parameters
};

/// A table with a header row, e.g. the input files (name, bytes, SHA-256). A cell's label is
/// unused; its value and key are shown and marked as a figure's are.
struct ReportTable {
  std::string title;
  std::vector<std::string> columns;
  std::vector<std::vector<ReportFigure>> rows;
};

struct ReportFile {
  std::string name;         ///< path relative to the OUTDIR (the link target)
  std::string description;  ///< one line on what it is
};

struct ReportPicture {
  std::string file;       ///< relative path, shown as the caption and linked
  std::string caption;    ///< one line on what it shows
  std::string png_bytes;  ///< the PNG file's bytes, embedded as a data URI
};

struct ReportContent {
  std::string title;     ///< e.g. "pcd-to-map: cloud.pcd"
  std::string subtitle;  ///< e.g. the version and the start time
  /// In page order: the first (the inputs) full width, then the pictures, then the others side
  /// by side; collapsed ones last.
  std::vector<ReportSection> sections;
  std::vector<ReportTable> tables;  ///< right after the first section (e.g. the input files)
  std::vector<std::string> warnings;
  std::vector<ReportFigure> timings;  ///< stage, milliseconds as text, summary.json pointer
  std::vector<ReportFile> files;
  std::vector<ReportPicture> pictures;
};

/// text with & < > " ' replaced by their entities.
std::string html_escape(std::string_view text);

/// RFC 4648 base64 (with = padding) of bytes.
std::string base64_encode(std::string_view bytes);

/// The page as one string.
std::string report_html(const ReportContent& content);

/// Writes report_html(content) to path atomically. Throws OutputError.
void write_report_html(const std::filesystem::path& path, const ReportContent& content);

}  // namespace indoormap::formats
