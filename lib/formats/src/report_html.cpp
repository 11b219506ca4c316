#include "indoormap/formats/report_html.hpp"

#include <sstream>

#include "indoormap/core/atomic_file.hpp"

namespace indoormap::formats {
namespace {

constexpr const char* kReportStyle = R"(
body{font-family:sans-serif;margin:1.5em auto;max-width:1100px;color:#222;padding:0 1em}
h1{font-size:1.6em;margin-bottom:.2em}h2{font-size:1.2em;border-bottom:1px solid #ccc;margin-top:1.6em}
.sub{color:#666;margin-top:0}table{border-collapse:collapse;margin:.4em 0}
th,td{text-align:left;padding:2px 12px 2px 0;vertical-align:top}th{font-weight:normal;color:#555}
td.v{font-family:monospace}.warn{background:#fff4e0;border-left:4px solid #e69500;padding:4px 8px}
.pics{display:flex;flex-wrap:wrap;gap:1em;align-items:flex-start}
figure{margin:0;max-width:calc(50% - .5em)}
img{max-width:100%;border:1px solid #ddd;image-rendering:pixelated}figcaption{color:#555}
code{font-size:.95em}details summary{cursor:pointer;color:#555}
h3{font-size:1em;margin:.8em 0 .2em}table.grid th{border-bottom:1px solid #ccc}
.cards{display:flex;flex-wrap:wrap;gap:0 2.5em;align-items:flex-start}.card{max-width:100%}
)";

// Sets the markers the browser test reads (see the header) once the page and its images loaded.
constexpr const char* kReportCheckScript = R"(
window.addEventListener('load', function () {
  var imgs = document.images, shown = 0;
  for (var i = 0; i < imgs.length; ++i)
    if (imgs[i].complete && imgs[i].naturalWidth > 0) ++shown;
  var c = document.getElementById('check');
  c.setAttribute('data-images', String(imgs.length));
  c.setAttribute('data-images-shown', String(shown));
  c.setAttribute('data-loaded', 'true');
  c.textContent = shown + ' of ' + imgs.length + ' pictures shown';
});
)";

void value_cell(std::ostream& o, const ReportFigure& f) {
  o << "<td class=\"v\"";
  if (!f.key.empty()) o << " data-key=\"" << html_escape(f.key) << "\"";
  o << ">" << html_escape(f.value) << "</td>";
}

void figure_rows(std::ostream& o, const std::vector<ReportFigure>& figures) {
  o << "<table>\n";
  for (const auto& f : figures) {
    o << "<tr><th>" << html_escape(f.label) << "</th>";
    value_cell(o, f);
    o << "</tr>\n";
  }
  o << "</table>\n";
}

void table(std::ostream& o, const ReportTable& t) {
  if (t.rows.empty()) return;
  o << "<h3>" << html_escape(t.title) << "</h3>\n<table class=\"grid\">\n<tr>";
  for (const auto& c : t.columns) o << "<th>" << html_escape(c) << "</th>";
  o << "</tr>\n";
  for (const auto& row : t.rows) {
    o << "<tr>";
    for (const auto& cell : row) value_cell(o, cell);
    o << "</tr>\n";
  }
  o << "</table>\n";
}

void section(std::ostream& o, const ReportSection& s) {
  if (s.collapsed) {
    o << "<details><summary><h2 style=\"display:inline\">" << html_escape(s.title)
      << "</h2></summary>\n";
    figure_rows(o, s.figures);
    o << "</details>\n";
    return;
  }
  o << "<h2>" << html_escape(s.title) << "</h2>\n";
  figure_rows(o, s.figures);
}

void pictures(std::ostream& o, const std::vector<ReportPicture>& pics) {
  if (pics.empty()) return;
  o << "<h2>Pictures</h2>\n<div class=\"pics\">\n";
  for (const auto& p : pics) {
    o << "<figure><img alt=\"" << html_escape(p.file) << "\" src=\"data:image/png;base64,"
      << base64_encode(p.png_bytes) << "\"><figcaption><a href=\"" << html_escape(p.file) << "\">"
      << html_escape(p.file) << "</a>: " << html_escape(p.caption) << "</figcaption></figure>\n";
  }
  o << "</div>\n";
}

void files(std::ostream& o, const std::vector<ReportFile>& list) {
  o << "<h2>Output files</h2>\n<table>\n";
  for (const auto& f : list)
    o << "<tr><th><a href=\"" << html_escape(f.name) << "\"><code>" << html_escape(f.name)
      << "</code></a></th><td>" << html_escape(f.description) << "</td></tr>\n";
  o << "</table>\n";
}

}  // namespace

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string base64_encode(std::string_view bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 |
                       static_cast<unsigned char>(bytes[i + 1]) << 8 |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += kAlphabet[v >> 6 & 63];
    out += kAlphabet[v & 63];
  }
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 |
                       (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0u);
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += two ? kAlphabet[v >> 6 & 63] : '=';
    out += '=';
  }
  return out;
}

std::string report_html(const ReportContent& c) {
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>"
    << html_escape(c.title) << "</title>\n<style>" << kReportStyle << "</style>\n</head>\n<body>\n"
    << "<h1>" << html_escape(c.title) << "</h1>\n<p class=\"sub\">" << html_escape(c.subtitle)
    << "</p>\n";
  if (!c.warnings.empty()) {
    o << "<h2>Warnings</h2>\n";
    for (const auto& w : c.warnings) o << "<p class=\"warn\">" << html_escape(w) << "</p>\n";
  }
  // The first section (the inputs) full width, then the pictures, then the other sections and
  // the timings as cards side by side.
  bool first = true;
  for (const auto& s : c.sections) {
    if (s.collapsed) continue;
    if (first) {
      section(o, s);
      for (const auto& t : c.tables) table(o, t);
      pictures(o, c.pictures);
      o << "<div class=\"cards\">\n";
      first = false;
      continue;
    }
    o << "<div class=\"card\">\n";
    section(o, s);
    o << "</div>\n";
  }
  if (first) {
    for (const auto& t : c.tables) table(o, t);
    pictures(o, c.pictures);
    o << "<div class=\"cards\">\n";
  }
  if (!c.timings.empty()) {
    o << "<div class=\"card\">\n<h2>Stage timings</h2>\n";
    figure_rows(o, c.timings);
    o << "</div>\n";
  }
  o << "</div>\n";
  files(o, c.files);
  for (const auto& s : c.sections)
    if (s.collapsed) section(o, s);
  o << "<p id=\"check\" class=\"sub\">pictures not checked (scripts off)</p>\n<script>"
    << kReportCheckScript << "</script>\n</body>\n</html>\n";
  return o.str();
}

void write_report_html(const std::filesystem::path& path, const ReportContent& content) {
  write_file_atomic(path, report_html(content));
}

}  // namespace indoormap::formats
