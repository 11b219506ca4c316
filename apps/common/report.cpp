#include "report.hpp"

#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "indoormap/core/errors.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace indoormap::app {
namespace {

// The toolkit's output files by name (docs/<app>.md, "Outputs", say more).
const std::map<std::string, std::string>& known_outputs() {
  static const std::map<std::string, std::string> table = {
      {"summary.json", "everything about the run: inputs, figures, parameters, timings"},
      {"report.html", "this page"},
      {"map.pgm", "ROS navigation map image (occupied 0, free 254, unknown 205)"},
      {"map.yaml", "ROS map_server metadata of map.pgm (resolution, origin, thresholds)"},
      {"map.png", "the navigation map in colour with a legend and a scale bar"},
      {"layout.pgm", "the room layout as class values (0 unknown, 1 wall, 2 furniture, 3 free)"},
      {"layout.png", "the room layout in colour with a legend and a scale bar"},
      {"objects.json", "the objects found (furniture, pillars, lamps, columns) with boxes"},
      {"objects.csv", "the objects as a table, one row each"},
      {"objects.png", "the layout with every object's box and label"},
      {"room.geojson", "the room border polygon and its openings, GeoJSON in map metres"},
      {"room.json", "the closed border chain, polygon, openings and components"},
      {"border.png", "the layout with the border chain, polygon and openings"},
      {"rooms.geojson", "a polygon per room and a line per door, GeoJSON in map metres"},
      {"rooms.json", "the room graph: rooms, areas, neighbours, doors, objects"},
      {"rooms.png", "the navigation map with each room tinted, outlined and numbered"},
      {"route.json", "the planned routes as turn-then-go-straight commands"},
      {"route.png", "the safe zone with the best route drawn"},
      {"safe.pgm", "the safe zone: where the robot's centre may be (ROS map image)"},
      {"safe.yaml", "ROS map_server metadata of safe.pgm"},
      {"eval.json", "the evaluation of the result against the ground truth"},
      {"eval.html", "the evaluation report (this page)"},
      {"ground_truth.json", "the simulated scene's ground truth (rooms, walls, objects)"},
      {"ground_truth_seen.pgm", "the ground-truth layout of what the scanners saw"},
      {"ground_truth_seen.yaml", "ROS map_server metadata of ground_truth_seen.pgm"},
      {"trajectory.txt", "the mobile scanner's trajectory (TUM format)"},
      {"areas.geojson", "rooms, corridors and crossings as polygons, doors as lines (GeoJSON)"},
      {"areas.json", "the areas with their kinds, sizes, neighbours and doors"},
      {"areas.png", "the map with each area coloured by kind, with a legend"},
      {"areas_labels.png", "16-bit label image: the area id of every cell (0: none)"},
      {"score.json", "the segmentation score against the ground truth"},
      {"keepout_mask.pgm", "Nav2 keepout filter mask image"},
      {"keepout_mask.yaml", "ROS map metadata of the keepout mask"},
      {"keepout_filter_info.yaml", "Nav2 costmap filter info for the keepout mask"},
      {"speed_mask.pgm", "Nav2 speed filter mask image"},
      {"speed_mask.yaml", "ROS map metadata of the speed mask"},
      {"speed_filter_info.yaml", "Nav2 costmap filter info for the speed mask"},
      {"laser_map.json", "the laser map's figures: scans, poses, consistency check"},
      {"explore.json", "the exploration: goals, path, explored share over time"},
      {"explore.png", "the explored map with the robot's path and goals"},
      {"explore_strip.png", "the exploration as a strip of snapshots over time"},
      {"path.geojson", "the robot's path, GeoJSON in map metres"},
      {"features.jsonl", "the features of every scan (walls, doors, corners), one JSON line each"},
      {"align.json", "the scan-to-scan alignment of consecutive scans"},
  };
  return table;
}

std::string by_extension(const std::string& name) {
  const std::string ext = fs::path(name).extension().string();
  if (ext == ".png") return "picture";
  if (ext == ".pgm") return "grid image (PGM)";
  if (ext == ".yaml") return "YAML metadata";
  if (ext == ".json" || ext == ".jsonl") return "JSON data";
  if (ext == ".geojson") return "GeoJSON in map metres";
  if (ext == ".pcd" || ext == ".ply" || ext == ".las") return "point cloud";
  if (ext == ".3d" || ext == ".pose" || ext == ".frames") return "3DTK scan file";
  return "output file";
}

std::string number_text(const json& v) {
  if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v.get<double>());
  return buf;
}

std::string scalar_text(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number()) return number_text(v);
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  return "none";  // null
}

bool all_scalars(const json& a) {
  for (const auto& e : a)
    if (e.is_structured()) return false;
  return true;
}

std::string pointer_escape(const std::string& key) {
  std::string out;
  for (const char c : key) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return out;
}

// Appends the scalars under v as figures labelled "a.b[2].c", each keyed by its JSON pointer.
void flatten(const json& v, const std::string& pointer, const std::string& label,
             std::vector<formats::ReportFigure>& out, int depth) {
  constexpr int kMaxDepth = 5;
  constexpr std::size_t kMaxListed = 8;
  if (!v.is_structured()) {
    out.push_back({label, scalar_text(v), pointer});
  } else if (v.is_array() && all_scalars(v)) {
    std::string text;
    for (const auto& e : v) text += (text.empty() ? "" : ", ") + scalar_text(e);
    if (text.size() > 200) text = std::to_string(v.size()) + " values (see summary.json)";
    out.push_back({label, v.empty() ? "(none)" : text, ""});
  } else if (depth >= kMaxDepth || (v.is_array() && v.size() > kMaxListed)) {
    out.push_back({label, std::to_string(v.size()) + " entries (see summary.json)", ""});
  } else if (v.is_array()) {
    for (std::size_t i = 0; i < v.size(); ++i)
      flatten(v[i], pointer + "/" + std::to_string(i), label + "[" + std::to_string(i) + "]", out,
              depth + 1);
  } else {
    for (const auto& [k, e] : v.items())
      flatten(e, pointer + "/" + pointer_escape(k), label.empty() ? k : label + "." + k, out,
              depth + 1);
  }
}

// The folder every input file is in (its deepest common one), or "" for one file or none.
fs::path common_folder(const json& files) {
  if (files.size() < 2) return {};
  fs::path common = fs::path(files[0].value("path", "")).parent_path();
  for (const auto& f : files) {
    const fs::path dir = fs::path(f.value("path", "")).parent_path();
    fs::path shared;
    for (auto a = common.begin(), b = dir.begin(); a != common.end() && b != dir.end() && *a == *b;
         ++a, ++b)
      shared /= *a;
    common = shared;
  }
  return common;
}

formats::ReportSection inputs_section(const json& summary) {
  formats::ReportSection s{"Inputs", {}, false};
  const json p = summary.value("provenance", json::object());
  std::string line;
  for (const auto& a : p.value("command_line", json::array())) {
    const std::string arg = a.get<std::string>();
    const bool plain = !arg.empty() && arg.find_first_of(" \t'\"$\\;&|<>*?") == std::string::npos;
    line += (line.empty() ? "" : " ") + (plain ? arg : "'" + arg + "'");
  }
  s.figures.push_back({"command line", line, ""});
  for (const char* k : {"started_utc", "version", "revision"})
    if (p.contains(k)) s.figures.push_back({k, scalar_text(p[k]), std::string("/provenance/") + k});
  const fs::path folder = common_folder(p.value("inputs", json::array()));
  if (!folder.empty()) s.figures.push_back({"input folder", folder.string(), ""});
  return s;
}

// One row per input file: its path (relative to the common folder), size and SHA-256.
formats::ReportTable input_files_table(const json& summary) {
  formats::ReportTable t{"Input files", {"file", "bytes", "SHA-256"}, {}};
  const json files = summary.value("provenance", json::object()).value("inputs", json::array());
  const fs::path folder = common_folder(files);
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string at = "/provenance/inputs/" + std::to_string(i);
    const fs::path path = files[i].value("path", "");
    const std::string shown =
        folder.empty() ? path.string() : path.lexically_relative(folder).string();
    t.rows.push_back({{"", shown, folder.empty() ? at + "/path" : ""},
                      {"", number_text(files[i]["size_bytes"]), at + "/size_bytes"},
                      {"", files[i].value("sha256", ""), at + "/sha256"}});
  }
  return t;
}

// "<program>: <the input's file name, or the folder the inputs are in>".
std::string default_title(const std::string& program, const json& prov) {
  const json files = prov.value("inputs", json::array());
  if (files.empty()) return program;
  const fs::path folder = common_folder(files);
  const fs::path name =
      folder.empty() ? fs::path(files[0].value("path", "")).filename() : folder.filename();
  return program + ": " + name.string() +
         (folder.empty() && files.size() > 1 ? " and " + std::to_string(files.size() - 1) + " more"
                                             : "");
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool is_picture(const std::string& name) {
  const std::string file = fs::path(name).filename().string();
  return fs::path(name).extension() == ".png" && file.find("labels") == std::string::npos &&
         file.find("mask") == std::string::npos;
}

}  // namespace

std::string describe_output(const std::string& relative_path, const ReportExtras& extras) {
  const std::string file = fs::path(relative_path).filename().string();
  if (auto it = extras.descriptions.find(file); it != extras.descriptions.end()) return it->second;
  if (auto it = known_outputs().find(file); it != known_outputs().end()) return it->second;
  return by_extension(file);
}

formats::ReportContent report_content(const json& summary, const fs::path& dir,
                                      const std::vector<std::string>& outputs,
                                      const ReportExtras& extras) {
  constexpr std::size_t kMaxPictures = 12;
  constexpr std::uintmax_t kMaxPictureBytes = 8u << 20;
  formats::ReportContent c;
  const std::string program = summary.value("program", summary.value("app", "indoormap"));
  const json prov = summary.value("provenance", json::object());
  c.title = extras.title.empty() ? default_title(program, prov) : extras.title;
  c.subtitle = program + " " + prov.value("version", "") + " (" + prov.value("revision", "") +
               "), started " + prov.value("started_utc", "") + " UTC";
  c.sections.push_back(inputs_section(summary));
  c.tables.push_back(input_files_table(summary));
  formats::ReportSection results{"Results", {}, false};
  const std::set<std::string> skip = {"program",    "app",      "version",
                                      "provenance", "outputs",  "timings_ms",
                                      "timings_s",  "warnings", "parameters"};
  for (const auto& [k, v] : summary.items())
    if (!skip.count(k) && !v.is_object())
      flatten(v, "/" + pointer_escape(k), k, results.figures, 0);
  c.sections.push_back(results);
  for (const auto& [k, v] : summary.items()) {
    if (skip.count(k) || !v.is_object()) continue;
    formats::ReportSection s{k, {}, false};
    flatten(v, "/" + pointer_escape(k), "", s.figures, 0);
    c.sections.push_back(s);
  }
  if (summary.contains("parameters")) {
    formats::ReportSection s{"Parameters", {}, true};
    flatten(summary["parameters"], "/parameters", "", s.figures, 0);
    c.sections.push_back(s);
  }
  for (const auto& w : summary.value("warnings", json::array()))
    c.warnings.push_back(w.is_string() ? w.get<std::string>() : w.dump());
  for (const char* unit : {"ms", "s"}) {
    const std::string key = std::string("timings_") + unit;
    if (!summary.contains(key)) continue;
    flatten(summary[key], "/" + key, "", c.timings, 0);
    for (auto& t : c.timings) t.label += std::string(" (") + unit + ")";
  }
  for (const auto& f : outputs) {
    c.files.push_back({f, describe_output(f, extras)});
    std::error_code ec;
    const auto size = fs::file_size(dir / f, ec);
    if (is_picture(f) && c.pictures.size() < kMaxPictures && !ec && size <= kMaxPictureBytes)
      c.pictures.push_back({f, describe_output(f, extras), read_bytes(dir / f)});
  }
  return c;
}

void write_report(const fs::path& dir, const json& summary, const std::vector<std::string>& outputs,
                  const ReportExtras& extras, const std::string& name) {
  formats::write_report_html(dir / name, report_content(summary, dir, outputs, extras));
}

}  // namespace indoormap::app
