#include "indoormap/sim/output.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "indoormap/cloud_io/write.hpp"
#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/version.hpp"

namespace indoormap::sim {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

ordered_json xy(const Eigen::Vector2d& p) { return ordered_json::array({p.x(), p.y()}); }
ordered_json xyz(const Eigen::Vector3d& p) { return ordered_json::array({p.x(), p.y(), p.z()}); }
ordered_json poly_json(const Polygon& poly) {
  ordered_json a = ordered_json::array();
  for (const auto& p : poly) a.push_back(xy(p));
  return a;
}

/// Shortest text that reads back as the same double.
std::string shortest(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, r.ptr);
  if (s.find_first_of(".eE") == std::string::npos && s.find("inf") == std::string::npos) s += ".0";
  return s;
}

cv::Vec3b colour(Cell c) {  // BGR
  switch (c) {
    case Cell::kUnknown: return {128, 128, 128};
    case Cell::kWall: return {40, 40, 40};
    case Cell::kFurniture: return {40, 120, 230};
    case Cell::kFree: return {255, 255, 255};
  }
  return {255, 0, 255};
}

ordered_json opening_json(const Room& room, const Opening& o, bool door) {
  const int n = static_cast<int>(room.polygon.size());
  const Eigen::Vector2d a = room.polygon[o.edge], b = room.polygon[(o.edge + 1) % n];
  const Eigen::Vector2d u = (b - a).normalized();
  ordered_json j;
  j["edge"] = o.edge;
  j["at_m"] = o.at_m;
  j["width_m"] = o.width_m;
  if (door) {
    j["height_m"] = o.top_m;
  } else {
    j["sill_m"] = o.bottom_m;
    j["top_m"] = o.top_m;
  }
  j["center"] = xy(a + u * o.at_m);
  j["segment"] = ordered_json::array({xy(a + u * (o.at_m - o.width_m / 2)), xy(a + u * (o.at_m + o.width_m / 2))});
  return j;
}

}  // namespace

void write_layout_pgm(const fs::path& path, const Grid<Cell>& cells) {
  std::string bytes = "P5\n" + std::to_string(cells.width) + " " + std::to_string(cells.height) + "\n255\n";
  const std::size_t header = bytes.size();
  bytes.resize(header + cells.size());
  for (int r = 0; r < cells.height; ++r)
    for (int c = 0; c < cells.width; ++c)
      bytes[header + static_cast<std::size_t>(cells.height - 1 - r) * cells.width + c] =
          static_cast<char>(static_cast<std::uint8_t>(cells.at(c, r)));
  write_file_atomic(path, bytes);
}

void write_layout_png(const fs::path& path, const Grid<Cell>& cells, const GridGeometry& geometry,
                      const std::vector<Eigen::Vector2d>& markers_m) {
  const int scale = std::clamp(900 / std::max(1, cells.width), 1, 8);
  const int legend_h = 28;
  const int W = std::max(cells.width * scale, 420), H = cells.height * scale + legend_h;
  cv::Mat img(H, W, CV_8UC3, cv::Scalar(255, 255, 255));
  for (int r = 0; r < cells.height; ++r) {
    for (int c = 0; c < cells.width; ++c) {
      const cv::Vec3b col = colour(cells.at(c, r));
      const int y0 = (cells.height - 1 - r) * scale;
      cv::rectangle(img, cv::Rect(c * scale, y0, scale, scale), cv::Scalar(col[0], col[1], col[2]), cv::FILLED);
    }
  }
  for (const auto& m : markers_m) {
    const double x = (m.x() - geometry.origin_m().x()) / geometry.cell_m() * scale;
    const double y = (cells.height - (m.y() - geometry.origin_m().y()) / geometry.cell_m()) * scale;
    cv::circle(img, cv::Point(static_cast<int>(x), static_cast<int>(y)), std::max(3, scale * 2), cv::Scalar(0, 0, 220), cv::FILLED);
  }
  int x = 6;
  const int y = cells.height * scale + 6;
  for (Cell c : {Cell::kUnknown, Cell::kWall, Cell::kFurniture, Cell::kFree}) {
    const cv::Vec3b col = colour(c);
    cv::rectangle(img, cv::Rect(x, y, 16, 16), cv::Scalar(col[0], col[1], col[2]), cv::FILLED);
    cv::rectangle(img, cv::Rect(x, y, 16, 16), cv::Scalar(0, 0, 0), 1);
    cv::putText(img, std::string(to_string(c)), cv::Point(x + 20, y + 13), cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    x += 95;
  }
  if (!markers_m.empty()) {
    cv::circle(img, cv::Point(x + 8, y + 8), 5, cv::Scalar(0, 0, 220), cv::FILLED);
    cv::putText(img, "scanner", cv::Point(x + 20, y + 13), cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  }
  std::vector<uchar> buf;
  if (!cv::imencode(".png", img, buf)) throw OutputError(path.string(), "PNG encoding failed");
  write_file_atomic(path, std::string_view(reinterpret_cast<const char*>(buf.data()), buf.size()));
}

void write_map_yaml(const fs::path& path, const std::string& image, const GridGeometry& g) {
  std::ostringstream y;
  y << "image: " << image << "\n"
    << "resolution: " << shortest(g.cell_m()) << "\n"
    << "origin: [" << shortest(g.origin_m().x()) << ", " << shortest(g.origin_m().y()) << ", 0.0]\n"
    << "negate: 0\n"
    << "occupied_thresh: 0.65\n"
    << "free_thresh: 0.196\n";
  write_file_atomic(path, y.str());
}

std::vector<std::string> write_3dtk(const fs::path& dir, const SimResult& sim) {
  std::vector<cloud_io::TdtkScan> scans;
  for (const ScanBlock& b : sim.scans)
    scans.push_back({std::span(sim.points).subspan(b.begin, b.end - b.begin),
                     sim.scanner_positions_m[b.scanner]});
  return cloud_io::write_3dtk_scans(dir, scans);
}

void validate(const OutputOptions& options) {
  if (!(options.truth_cell_m >= 0.001 && options.truth_cell_m <= 10))
    throw UsageError("truth cell size must be in [0.001, 10] m");
}

WrittenOutputs write_scene_outputs(const fs::path& dir, const Scene& input, const SimResult& sim,
                                   const OutputOptions& options) {
  validate(options);
  ensure_writable_dir(dir);
  const Scene scene = normalised(input);
  const SceneGeometry geometry = build_geometry(scene);
  WrittenOutputs out;
  out.layout = truth_layout(scene, geometry, options.truth_cell_m);
  const auto items = furniture_truth(scene);

  const Eigen::Vector3d viewpoint = sim.scanner_positions_m.empty() ? Eigen::Vector3d::Zero() : sim.scanner_positions_m.front();
  cloud_io::write_pcd_binary((dir / "cloud.pcd").string(), sim.points, viewpoint);
  out.files.push_back("cloud.pcd");

  write_layout_pgm(dir / "ground_truth_layout.pgm", out.layout.cells);
  std::vector<Eigen::Vector2d> markers;
  for (const auto& s : scene.scanners) markers.push_back(s.position_m.head<2>());
  write_layout_png(dir / "ground_truth_layout.png", out.layout.cells, out.layout.geometry, markers);
  write_map_yaml(dir / "ground_truth_layout.yaml", "ground_truth_layout.pgm", out.layout.geometry);
  out.files.insert(out.files.end(), {"ground_truth_layout.pgm", "ground_truth_layout.png", "ground_truth_layout.yaml"});

  ordered_json j;
  j["format"] = "indoormap-ground-truth";
  j["format_version"] = 1;
  j["generator"] = options.generator + " " + kVersion;
  j["scene"] = scene.name;
  j["seed"] = scene.seed;
  j["frame"] =
      "scene frame: metres, right-handed, z up, floor at z = 0. The cloud is in the tilted frame: "
      "p_cloud = tilt.rotation * p_scene (rotation about the origin).";
  const Eigen::Matrix3d R = tilt_rotation(scene.tilt);
  ordered_json rot = ordered_json::array();
  for (int r = 0; r < 3; ++r) rot.push_back(ordered_json::array({R(r, 0), R(r, 1), R(r, 2)}));
  const double tilt_deg = std::acos(std::clamp(R(2, 2), -1.0, 1.0)) * 180.0 / std::acos(-1.0);
  j["tilt"] = {{"roll_deg", scene.tilt.roll_deg}, {"pitch_deg", scene.tilt.pitch_deg},
               {"angle_deg", tilt_deg}, {"convention", "R = Ry(pitch) * Rx(roll)"}, {"rotation", rot}};
  double wall_height = 0.0;
  ordered_json rooms = ordered_json::array();
  for (std::size_t r = 0; r < scene.rooms.size(); ++r) {
    const Room& room = scene.rooms[r];
    double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
    for (const auto& v : room.polygon) {
      zmin = std::min(zmin, ceiling_z(room, v));
      zmax = std::max(zmax, ceiling_z(room, v));
    }
    wall_height = std::max(wall_height, zmax);
    ordered_json jr;
    jr["id"] = r;
    jr["name"] = room.name;
    jr["kind"] = room.kind == RoomKind::kCorridor ? "corridor" : "room";
    jr["polygon"] = poly_json(room.polygon);
    jr["area_m2"] = signed_area(room.polygon);
    jr["wall_thickness_m"] = room.wall_thickness_m;
    jr["floor_z_m"] = 0.0;
    jr["wall_height_m"] = zmax;
    jr["ceiling"] = {{"height_m", room.ceiling.height_m}, {"slope_deg", room.ceiling.slope_deg},
                     {"rise_azimuth_deg", room.ceiling.rise_azimuth_deg}, {"min_z_m", zmin}, {"max_z_m", zmax}};
    jr["doors"] = ordered_json::array();
    for (const auto& d : room.doors) jr["doors"].push_back(opening_json(room, d, true));
    jr["windows"] = ordered_json::array();
    for (const auto& w : room.windows) jr["windows"].push_back(opening_json(room, w, false));
    rooms.push_back(jr);
  }
  j["wall_height_m"] = wall_height;
  j["rooms"] = rooms;
  ordered_json furn = ordered_json::array();
  for (std::size_t i = 0; i < items.size(); ++i) {
    const auto& t = items[i];
    const Furniture& f = scene.furniture[i];
    ordered_json jf;
    jf["id"] = t.id;
    jf["type"] = std::string(to_string(t.type));
    jf["footprint"] = poly_json(t.footprint);
    jf["z_min_m"] = t.z_min_m;
    jf["z_max_m"] = t.z_max_m;
    jf["on_floor"] = t.on_floor;
    jf["room"] = t.room;
    jf["center"] = xy(f.center_m);
    jf["yaw_deg"] = f.yaw_deg;
    if (f.radius_m > 0 && (f.type == FurnitureType::kBin || f.type == FurnitureType::kPillar ||
                           f.type == FurnitureType::kTable || f.type == FurnitureType::kLamp)) {
      jf["radius_m"] = f.radius_m;
    } else {
      jf["size"] = xy(f.size_m);
    }
    furn.push_back(jf);
  }
  j["furniture"] = furn;
  ordered_json scanners = ordered_json::array();
  for (std::size_t s = 0; s < scene.scanners.size(); ++s) {
    scanners.push_back({{"position_m", xyz(scene.scanners[s].position_m)},
                        {"position_cloud_m", xyz(s < sim.scanner_positions_m.size() ? sim.scanner_positions_m[s] : Eigen::Vector3d::Zero())},
                        {"heading_deg", scene.scanners[s].heading_deg}});
  }
  j["scanners"] = scanners;
  const ScannerParams& sp = scene.scanner;
  j["scanner_model"] = {{"azimuth_step_deg", sp.azimuth_step_deg}, {"elevation_step_deg", sp.elevation_step_deg},
                        {"elevation_min_deg", sp.elevation_min_deg}, {"elevation_max_deg", sp.elevation_max_deg},
                        {"range_min_m", sp.range_min_m}, {"range_max_m", sp.range_max_m},
                        {"range_sigma_m", sp.range_sigma_m}, {"mixed_pixel_probability", sp.mixed_pixel_probability},
                        {"mixed_pixel_min_jump_m", sp.mixed_pixel_min_jump_m}};
  j["cloud"] = {{"file", "cloud.pcd"}, {"frame", "tilted"}, {"points", sim.points.size()},
                {"rays", sim.rays}, {"mixed_pixels", sim.mixed_pixels}, {"scans", sim.scans.size()}};
  const auto& g = out.layout.geometry;
  j["layout"] = {{"image", "ground_truth_layout.pgm"}, {"picture", "ground_truth_layout.png"},
                 {"yaml", "ground_truth_layout.yaml"}, {"resolution", g.cell_m()},
                 {"origin", ordered_json::array({g.origin_m().x(), g.origin_m().y(), 0.0})},
                 {"width", g.width()}, {"height", g.height()},
                 {"rows", "image row 0 = highest y"},
                 {"classes", {{"0", "unknown"}, {"1", "wall"}, {"2", "furniture"}, {"3", "free"}}}};
  if (options.write_3dtk) {
    auto files = write_3dtk(dir / options.tdtk_subdir, sim);
    for (auto& f : files) out.files.push_back(options.tdtk_subdir + "/" + f);
    j["tdtk"] = {{"directory", options.tdtk_subdir}, {"scans", sim.scans.size()},
                 {"convention", "points in the scan's local frame (tilted frame minus the scanner position), "
                                "3DTK units and axes (cm, left-handed, y up: x = -100 Y, y = 100 Z, z = 100 X); "
                                ".pose = scanner position in the same units, Euler angles 0 0 0"}};
  }
  write_file_atomic(dir / "ground_truth.json", j.dump(2) + "\n");
  out.files.push_back("ground_truth.json");
  return out;
}

Grid<std::uint8_t> read_pgm(const fs::path& path, bool flip) {
  // A directory would read as an empty file, a FIFO would block in open().
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path.string(), "cannot open: no such file");
  if (!fs::is_regular_file(path, ec)) throw InputError(path.string(), "not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open");
  // The magic number is two bytes followed by whitespace or a comment (not read as a
  // whitespace-delimited token: that could be as long as the file).
  char magic[2] = {};
  in.read(magic, 2);
  const auto got = in.gcount();  // before peek(), which resets it
  const int after = in.peek();
  if (got < 2 || magic[0] != 'P' || magic[1] != '5' ||
      !(after == '#' || (after != EOF && std::isspace(after))))
    throw InputError(path.string(), "not a binary PGM (P5) file");
  long long vals[3];
  for (auto& v : vals) {
    in >> std::ws;
    while (in.peek() == '#') {
      std::string comment;
      std::getline(in, comment);
      in >> std::ws;
    }
    if (!(in >> v)) throw InputError(path.string(), "bad PGM header");
  }
  const long long w = vals[0], h = vals[1], maxval = vals[2];
  if (w <= 0 || h <= 0 || w > 100000 || h > 100000 || w * h > 400'000'000LL)
    throw InputError(path.string(),
                     "PGM size " + std::to_string(w) + " x " + std::to_string(h) + " out of range");
  if (maxval <= 0 || maxval > 255) throw InputError(path.string(), "only 8-bit PGM is supported");
  in.get();  // the single whitespace after maxval
  // The pixels must be in the file before the grid is allocated for them.
  const auto data_start = static_cast<long long>(in.tellg());
  const auto file_size = static_cast<long long>(fs::file_size(path, ec));
  const long long present = !in || ec || data_start < 0 ? 0 : std::max(0LL, file_size - data_start);
  if (present < w * h)
    throw InputError(path.string(), "PGM data truncated: " + std::to_string(w) + " x " +
                                        std::to_string(h) + " pixels need " +
                                        std::to_string(w * h) + " bytes, the file holds " +
                                        std::to_string(present));
  Grid<std::uint8_t> g(static_cast<int>(w), static_cast<int>(h));
  std::vector<char> row(static_cast<std::size_t>(w));
  for (long long r = 0; r < h; ++r) {
    if (!in.read(row.data(), w)) throw InputError(path.string(), "PGM data truncated");
    const int gr = flip ? static_cast<int>(h - 1 - r) : static_cast<int>(r);
    for (long long c = 0; c < w; ++c)
      g.at(static_cast<int>(c), gr) = static_cast<std::uint8_t>(row[c]);
  }
  return g;
}

}  // namespace indoormap::sim
