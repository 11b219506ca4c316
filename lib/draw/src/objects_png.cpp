#include "indoormap/draw/objects_png.hpp"

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "indoormap/draw/layout_png.hpp"

namespace indoormap::draw {

void write_objects_png(const std::filesystem::path& path, const layout::MapResult& map,
                       const objects::ObjectsResult& res) {
  RenderOptions ro;
  ro.title = "objects: " + std::to_string(res.objects.size());
  for (const auto& s : map.cloud_map.scanners) ro.markers_map.emplace_back(s.x(), s.y());
  // One colour per kind; the legend lists the kinds that occur.
  const std::vector<std::pair<std::string, std::array<std::uint8_t, 3>>> colours = {
      {"furniture", {170, 0, 150}}, {"pillar", {200, 30, 30}}, {"hanging", {0, 130, 200}},
      {"lamp", {0, 170, 170}},      {"column", {120, 60, 0}},  {"installation", {120, 60, 0}}};
  std::vector<bool> used(colours.size(), false);
  for (const auto& o : res.objects) {
    Overlay ov;
    ov.points_m = o.footprint_m;
    ov.label = std::to_string(o.id);
    std::size_t k = 0;
    while (k + 1 < colours.size() && colours[k].first != to_string(o.kind)) ++k;
    if (colours[k].first != to_string(o.kind)) k = 0;
    used[k] = true;
    ov.rgb = colours[k].second;
    ro.overlays.push_back(ov);
  }
  for (std::size_t k = 0; k < colours.size(); ++k)
    if (used[k] || k == 0) ro.legend.push_back({colours[k].first + " (id)", colours[k].second});
  write_layout_png(path, map.layout.layout, map.geometry, ro);
}

}  // namespace indoormap::draw
