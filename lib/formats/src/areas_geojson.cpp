#include "indoormap/formats/areas_geojson.hpp"

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/formats/png.hpp"
#include "json_write.hpp"

namespace indoormap::formats {
namespace {

using nlohmann::ordered_json;

ordered_json door_json(const areas::Door& d) {
  return {{"between", {d.a, d.b}},
          {"from", detail::xy_json<ordered_json>(d.end0_m)},
          {"to", detail::xy_json<ordered_json>(d.end1_m)},
          {"width_m", d.width_m},
          {"shared_cells", d.shared_cells}};
}

}  // namespace

ordered_json areas_geojson(const areas::AreasResult& r) {
  ordered_json features = ordered_json::array();
  for (const areas::Area& a : r.areas) {
    if (a.outline_m.size() < 3) continue;
    ordered_json rings = ordered_json::array({detail::ring_json<ordered_json>(a.outline_m)});
    for (const auto& h : a.holes_m) rings.push_back(detail::ring_json<ordered_json>(h));
    features.push_back({{"type", "Feature"},
                        {"geometry", {{"type", "Polygon"}, {"coordinates", rings}}},
                        {"properties",
                         {{"type", std::string(areas::to_string(a.kind))},
                          {"id", a.id},
                          {"area_m2", a.area_m2},
                          {"connects_to", a.neighbours}}}});
  }
  for (const areas::Door& d : r.doors)
    features.push_back(
        {{"type", "Feature"},
         {"geometry",
          {{"type", "LineString"},
           {"coordinates",
            {detail::xy_json<ordered_json>(d.end0_m), detail::xy_json<ordered_json>(d.end1_m)}}}},
         {"properties", {{"type", "door"}, {"between", {d.a, d.b}}, {"width_m", d.width_m}}}});
  return {{"type", "FeatureCollection"}, {"features", features}};
}

void write_areas_geojson(const std::filesystem::path& path, const areas::AreasResult& r) {
  write_json(path, areas_geojson(r));
}

ordered_json areas_json(const areas::AreasResult& r) {
  ordered_json list = ordered_json::array(), nodes = ordered_json::array(),
               edges = ordered_json::array(), checks = ordered_json::array();
  for (const areas::Area& a : r.areas) {
    list.push_back({{"id", a.id},
                    {"type", std::string(areas::to_string(a.kind))},
                    {"area_m2", a.area_m2},
                    {"cells", a.cells},
                    {"holes", a.holes_m.size()},
                    {"neighbours", a.neighbours}});
    nodes.push_back(a.id);
  }
  for (const areas::Door& d : r.doors)
    edges.push_back({{"a", d.a}, {"b", d.b}, {"door", door_json(d)}});
  for (const auto& c : r.crossing_checks)
    checks.push_back({{"at_m", detail::xy_json<ordered_json>(c.at_m)},
                      {"arms", c.arms},
                      {"confirmed", c.confirmed}});
  return {{"areas", list},
          {"graph", {{"nodes", nodes}, {"edges", edges}, {"components", r.graph_components}}},
          {"crossing_checks", checks},
          {"free_cells", r.free_cells},
          {"reachable_cells", r.reachable_cells},
          {"reachable_components", r.reachable_components}};
}

// A label PNG larger than this is refused before it is decoded (as the maps' cell budget).
constexpr std::int64_t kMaxLabelPixels = 400'000'000;

void write_labels_png(const std::filesystem::path& path, const Grid<std::uint16_t>& labels) {
  std::vector<std::uint16_t> img(labels.data.size());
  for (int r = 0; r < labels.height; ++r)
    for (int c = 0; c < labels.width; ++c)
      img[static_cast<std::size_t>(labels.height - 1 - r) * labels.width + c] = labels.at(c, r);
  const std::size_t stride = static_cast<std::size_t>(labels.width) * 2;
  write_file_atomic(
      path, encode_png({img.data(), labels.width, labels.height, 1, 16, stride}, 1, path.string()));
}

Grid<std::uint16_t> read_labels_png(const std::filesystem::path& path) {
  const GreyImage img = read_png_grey(path, true, kMaxLabelPixels);
  Grid<std::uint16_t> g(img.width, img.height, 0);
  for (int r = 0; r < img.height; ++r)
    for (int c = 0; c < img.width; ++c)
      g.at(c, img.height - 1 - r) = img.pixels[static_cast<std::size_t>(r) * img.width + c];
  return g;
}

}  // namespace indoormap::formats
