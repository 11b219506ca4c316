#include "indoormap/sim/eval.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>

#include "indoormap/core/errors.hpp"
#include "indoormap/core/object_kind.hpp"
#include "indoormap/sim/output.hpp"

namespace indoormap::sim {

namespace fs = std::filesystem;
using nlohmann::json;

LayoutScores evaluate_layout(const GridGeometry& tg, const Grid<Cell>& truth,
                             const GridGeometry& rg, const Grid<Cell>& result) {
  LayoutScores s;
  // Count cells first, convert to m^2 once: exact for equal resolutions.
  std::array<std::array<std::int64_t, 4>, 4> by_result{}, by_truth{};
  for (int r = 0; r < result.height; ++r) {
    for (int c = 0; c < result.width; ++c) {
      const CellIndex ti = tg.cell_of(rg.center_of({c, r}));
      const Cell t = tg.contains(ti) ? truth.at(ti) : Cell::kUnknown;
      ++by_result[static_cast<int>(t)][static_cast<int>(result.at(c, r))];
    }
  }
  for (int r = 0; r < truth.height; ++r) {
    for (int c = 0; c < truth.width; ++c) {
      if (rg.contains(rg.cell_of(tg.center_of({c, r})))) continue;
      ++by_truth[static_cast<int>(truth.at(c, r))][0];
    }
  }
  const double ra = rg.cell_m() * rg.cell_m(), ta = tg.cell_m() * tg.cell_m();
  for (int t = 0; t < 4; ++t)
    for (int r = 0; r < 4; ++r) s.confusion_m2[t][r] = by_result[t][r] * ra + by_truth[t][r] * ta;
  double agree = 0.0, known = 0.0, iou_sum = 0.0;
  int iou_n = 0;
  for (int k = 0; k < 4; ++k) {
    ClassScore& cs = s.classes[k];
    for (int j = 0; j < 4; ++j) {
      cs.truth_m2 += s.confusion_m2[k][j];
      cs.result_m2 += s.confusion_m2[j][k];
    }
    cs.intersection_m2 = s.confusion_m2[k][k];
    cs.union_m2 = cs.truth_m2 + cs.result_m2 - cs.intersection_m2;
    if (cs.union_m2 > 0) cs.iou = cs.intersection_m2 / cs.union_m2;
    if (k > 0 && cs.iou) {
      iou_sum += *cs.iou;
      ++iou_n;
    }
    for (int j = 0; j < 4; ++j) {
      if (k == 0 && j == 0) continue;
      known += s.confusion_m2[k][j];
      if (k == j) agree += s.confusion_m2[k][j];
    }
  }
  if (iou_n > 0) s.mean_iou = iou_sum / iou_n;
  s.accuracy = known > 0 ? agree / known : 0.0;
  return s;
}

ObjectScores evaluate_objects(const std::vector<EvalObject>& truth,
                              const std::vector<EvalObject>& result, double min_iou) {
  ObjectScores s;
  s.truth_count = static_cast<int>(truth.size());
  s.result_count = static_cast<int>(result.size());
  struct Pair {
    double iou;
    int t, r;
  };
  std::vector<Pair> pairs;
  for (int t = 0; t < s.truth_count; ++t) {
    for (int r = 0; r < s.result_count; ++r) {
      if (truth[t].footprint.size() < 3 || result[r].footprint.size() < 3) continue;
      const double iou = polygon_iou(truth[t].footprint, result[r].footprint, 0.01);
      if (iou >= min_iou) pairs.push_back({iou, t, r});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    if (a.iou != b.iou) return a.iou > b.iou;
    return a.t != b.t ? a.t < b.t : a.r < b.r;
  });
  std::vector<bool> t_used(truth.size()), r_used(result.size());
  double sum_top = 0.0, sum_bottom = 0.0, worst = 0.0;
  int n_top = 0, n_bottom = 0;
  for (const Pair& p : pairs) {
    if (t_used[p.t] || r_used[p.r]) continue;
    t_used[p.t] = r_used[p.r] = true;
    ObjectMatch m;
    m.truth_id = truth[p.t].id;
    m.result_id = result[p.r].id;
    m.iou = p.iou;
    if (truth[p.t].z_max_m && result[p.r].z_max_m) {
      m.z_max_error_m = *result[p.r].z_max_m - *truth[p.t].z_max_m;
      sum_top += std::abs(*m.z_max_error_m);
      worst = std::max(worst, std::abs(*m.z_max_error_m));
      ++n_top;
    }
    if (truth[p.t].z_min_m && result[p.r].z_min_m) {
      m.z_min_error_m = *result[p.r].z_min_m - *truth[p.t].z_min_m;
      sum_bottom += std::abs(*m.z_min_error_m);
      worst = std::max(worst, std::abs(*m.z_min_error_m));
      ++n_bottom;
    }
    s.matches.push_back(std::move(m));
  }
  s.matched = static_cast<int>(s.matches.size());
  for (int t = 0; t < s.truth_count; ++t)
    if (!t_used[t]) s.missed.push_back(truth[t].id);
  for (int r = 0; r < s.result_count; ++r)
    if (!r_used[r]) s.spurious.push_back(result[r].id);
  s.recall = s.truth_count > 0 ? static_cast<double>(s.matched) / s.truth_count : 0.0;
  s.precision = s.result_count > 0 ? static_cast<double>(s.matched) / s.result_count : 0.0;
  if (n_top > 0) s.mean_abs_z_max_error_m = sum_top / n_top;
  if (n_bottom > 0) s.mean_abs_z_min_error_m = sum_bottom / n_bottom;
  if (n_top + n_bottom > 0) s.max_abs_height_error_m = worst;
  return s;
}

void validate(const EvalParams& params) {
  if (!(params.min_object_iou > 0 && params.min_object_iou <= 1))
    throw UsageError("invalid parameter min_object_iou: must be in (0, 1]");
}

ObjectScores evaluate_objects(const std::vector<EvalObject>& truth, std::vector<EvalObject> result,
                              const EvalParams& params) {
  validate(params);
  std::vector<EvalObject> expected;
  for (const auto& f : truth)
    if (f.on_floor || params.include_hanging) expected.push_back(f);
  // Without include_hanging both sides are what stands on the floor: result objects of kind
  // "hanging" or "lamp" are left out as the truth's lamps are.
  if (!params.include_hanging)
    std::erase_if(result, [](const EvalObject& o) { return !o.on_floor; });
  return evaluate_objects(expected, result, params.min_object_iou);
}

std::vector<RoomMatch> evaluate_rooms(const std::vector<TruthRoom>& truth,
                                      const std::vector<Polygon>& result) {
  std::vector<RoomMatch> out;
  for (std::size_t r = 0; r < result.size(); ++r) {
    RoomMatch m;
    m.result_index = static_cast<int>(r);
    m.result_area_m2 = std::abs(signed_area(result[r]));
    for (std::size_t t = 0; t < truth.size(); ++t) {
      const double iou = polygon_iou(truth[t].polygon, result[r], 0.02);
      if (iou > m.iou) {
        m.iou = iou;
        m.truth_index = static_cast<int>(t);
      }
    }
    if (m.truth_index >= 0) {
      const TruthRoom& t = truth[m.truth_index];
      m.truth_name = t.name;
      m.truth_area_m2 = std::abs(signed_area(t.polygon));
      m.hausdorff_m = boundary_hausdorff(t.polygon, result[r], 0.01);
      m.area_error_m2 = m.result_area_m2 - m.truth_area_m2;
      m.area_error_rel = m.truth_area_m2 > 0 ? m.area_error_m2 / m.truth_area_m2 : 0.0;
    }
    out.push_back(std::move(m));
  }
  return out;
}

// ---- Files -------------------------------------------------------------------------------------

namespace {

json parse_json_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::exception& e) {  // parse errors, and out_of_range for numbers like 1e999
    throw InputError(path.string(), std::string("invalid JSON: ") + e.what());
  }
  if (!j.is_object()) throw InputError(path.string(), "the top level is not a JSON object");
  return j;
}

// Any JSON access the readers did not check by hand (a value of an unexpected type deep in the
// file) becomes an InputError naming the file, never an untyped exception.
template <class F>
auto guarded(const fs::path& path, F&& read) {
  try {
    return read();
  } catch (const json::exception& e) {
    throw InputError(path.string(), std::string("unexpected JSON content: ") + e.what());
  }
}

[[noreturn]] void bad(const fs::path& path, const std::string& key, const std::string& problem) {
  throw InputError(path.string(), "key '" + key + "': " + problem);
}

double number(const json& j, const fs::path& path, const std::string& key) {
  if (!j.is_number()) bad(path, key, "expected a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) bad(path, key, "not finite");
  return v;
}

Eigen::Vector2d point(const json& j, const fs::path& path, const std::string& key) {
  if (!j.is_array() || j.size() < 2) bad(path, key, "expected [x, y]");
  return {number(j[0], path, key + "[0]"), number(j[1], path, key + "[1]")};
}

Polygon polygon(const json& j, const fs::path& path, const std::string& key) {
  if (!j.is_array()) bad(path, key, "expected a list of [x, y] points");
  if (j.size() > 1'000'000) bad(path, key, "more than 1,000,000 vertices");
  Polygon poly;
  for (std::size_t i = 0; i < j.size(); ++i)
    poly.push_back(point(j[i], path, key + "[" + std::to_string(i) + "]"));
  if (poly.size() >= 2 && (poly.front() - poly.back()).norm() < 1e-12)
    poly.pop_back();  // closed ring
  if (poly.size() < 3) bad(path, key, "a polygon needs at least 3 distinct vertices");
  return poly;
}

const json& member(const json& j, const char* name, const fs::path& path, const std::string& key) {
  if (!j.is_object() || !j.contains(name))
    bad(path, key.empty() ? name : key + "." + name, "missing");
  return j.at(name);
}

}  // namespace

TruthFile read_truth_json_unguarded(const fs::path& path) {
  const json j = parse_json_file(path);
  TruthFile t;
  t.path = path;
  if (!j.is_object() || j.value("format", "") != "indoormap-ground-truth")
    throw InputError(
        path.string(),
        "not a scene-sim ground truth (key 'format' must be \"indoormap-ground-truth\")");
  const json& rooms = member(j, "rooms", path, "");
  if (!rooms.is_array()) bad(path, "rooms", "expected a list");
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    const std::string key = "rooms[" + std::to_string(i) + "]";
    TruthRoom r;
    r.name = rooms[i].value("name", key);
    r.kind = rooms[i].value("kind", "room");
    r.polygon = polygon(member(rooms[i], "polygon", path, key), path, key + ".polygon");
    t.rooms.push_back(std::move(r));
  }
  const json& furniture = member(j, "furniture", path, "");
  if (!furniture.is_array()) bad(path, "furniture", "expected a list");
  for (std::size_t i = 0; i < furniture.size(); ++i) {
    const std::string key = "furniture[" + std::to_string(i) + "]";
    const json& f = furniture[i];
    EvalObject o;
    o.id = f.value("id", key);
    o.type = f.value("type", "");
    o.footprint = polygon(member(f, "footprint", path, key), path, key + ".footprint");
    o.z_min_m = number(member(f, "z_min_m", path, key), path, key + ".z_min_m");
    o.z_max_m = number(member(f, "z_max_m", path, key), path, key + ".z_max_m");
    o.on_floor = f.value("on_floor", true);
    t.furniture.push_back(std::move(o));
  }
  const json& layout = member(j, "layout", path, "");
  const json& image = member(layout, "image", path, "layout");
  if (!image.is_string()) bad(path, "layout.image", "expected a file name");
  t.layout_image = path.parent_path() / image.get<std::string>();
  const double res =
      number(member(layout, "resolution", path, "layout"), path, "layout.resolution");
  const json& origin = member(layout, "origin", path, "layout");
  const Eigen::Vector2d o = point(origin, path, "layout.origin");
  const double w = number(member(layout, "width", path, "layout"), path, "layout.width");
  const double h = number(member(layout, "height", path, "layout"), path, "layout.height");
  if (!(res > 0) || w < 1 || h < 1 || w * h > 4e8)
    bad(path, "layout", "resolution / width / height out of range");
  t.layout_geometry = GridGeometry(o, res, static_cast<int>(w), static_cast<int>(h));
  return t;
}

Grid<Cell> read_layout_pgm(const fs::path& path, const GridGeometry& expected) {
  const Grid<std::uint8_t> raw = read_pgm(path, true);
  if (expected.width() > 0 && (raw.width != expected.width() || raw.height != expected.height()))
    throw InputError(path.string(), "image is " + std::to_string(raw.width) + " x " +
                                        std::to_string(raw.height) + " but " +
                                        std::to_string(expected.width()) + " x " +
                                        std::to_string(expected.height()) + " was expected");
  Grid<Cell> out(raw.width, raw.height);
  for (std::size_t i = 0; i < raw.data.size(); ++i) {
    if (raw.data[i] > 3)
      throw InputError(path.string(),
                       "pixel value " + std::to_string(raw.data[i]) +
                           " is not a layout class 0..3 (is this map.pgm instead of layout.pgm?)");
    out.data[i] = static_cast<Cell>(raw.data[i]);
  }
  return out;
}

std::vector<EvalObject> read_objects_json_unguarded(const fs::path& path) {
  const json j = parse_json_file(path);
  const json& objects = member(j, "objects", path, "");
  if (!objects.is_array()) bad(path, "objects", "expected a list");
  std::vector<EvalObject> out;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::string key = "objects[" + std::to_string(i) + "]";
    const json& o = objects[i];
    if (!o.is_object()) bad(path, key, "expected an object");
    EvalObject e;
    if (o.contains("id"))
      e.id = o["id"].is_string() ? o["id"].get<std::string>() : o["id"].dump();
    else
      e.id = std::to_string(i);
    e.type = o.value("type", o.value("label", ""));
    // furniture-extract's "hanging" and "lamp" objects do not claim to stand on the floor.
    if (o.contains("kind") && o["kind"].is_string()) {
      const auto kind = parse_object_kind(o["kind"].get<std::string>());
      e.on_floor = !kind || stands_on_floor(*kind);
    }
    if (o.contains("footprint")) {
      e.footprint = polygon(o["footprint"], path, key + ".footprint");
    } else if (o.contains("obb")) {
      const json& b = o["obb"];
      const Eigen::Vector2d c =
          point(member(b, "center", path, key + ".obb"), path, key + ".obb.center");
      const double w = number(member(b, "width_m", path, key + ".obb"), path, key + ".obb.width_m");
      const double l =
          number(member(b, "length_m", path, key + ".obb"), path, key + ".obb.length_m");
      const double a =
          number(member(b, "angle_deg", path, key + ".obb"), path, key + ".obb.angle_deg");
      if (!(w > 0 && l > 0)) bad(path, key + ".obb", "width_m and length_m must be positive");
      e.footprint = rectangle(c, {l, w}, a * std::numbers::pi / 180.0);
    } else {
      bad(path, key, "needs 'footprint' or 'obb'");
    }
    if (o.contains("z_min_m")) e.z_min_m = number(o["z_min_m"], path, key + ".z_min_m");
    if (o.contains("z_max_m")) e.z_max_m = number(o["z_max_m"], path, key + ".z_max_m");
    out.push_back(std::move(e));
  }
  return out;
}

std::vector<Polygon> read_room_geojson_unguarded(const fs::path& path) {
  const json j = parse_json_file(path);
  if (j.value("type", "") != "FeatureCollection")
    bad(path, "type", "expected \"FeatureCollection\"");
  const json& features = member(j, "features", path, "");
  if (!features.is_array()) bad(path, "features", "expected a list");
  std::vector<Polygon> out;
  for (std::size_t i = 0; i < features.size(); ++i) {
    const std::string key = "features[" + std::to_string(i) + "]";
    const json& f = features[i];
    if (!f.is_object() || !f.contains("properties") || !f["properties"].is_object()) continue;
    if (f["properties"].value("kind", "") != "room") continue;
    const json& g = member(f, "geometry", path, key);
    if (g.value("type", "") != "Polygon")
      bad(path, key + ".geometry.type", "a room must be a Polygon");
    const json& rings = member(g, "coordinates", path, key + ".geometry");
    if (!rings.is_array() || rings.empty())
      bad(path, key + ".geometry.coordinates", "expected a list of rings");
    out.push_back(polygon(rings[0], path, key + ".geometry.coordinates[0]"));
  }
  return out;
}

TruthFile read_truth_json(const fs::path& path) {
  return guarded(path, [&] { return read_truth_json_unguarded(path); });
}

std::vector<EvalObject> read_objects_json(const fs::path& path) {
  return guarded(path, [&] { return read_objects_json_unguarded(path); });
}

std::vector<Polygon> read_room_geojson(const fs::path& path) {
  return guarded(path, [&] { return read_room_geojson_unguarded(path); });
}

}  // namespace indoormap::sim
