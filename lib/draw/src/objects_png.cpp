#include "indoormap/draw/objects_png.hpp"

#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "indoormap/draw/layout_png.hpp"
#include "indoormap/draw/palette.hpp"

namespace indoormap::draw {

namespace {

/// The object's cell nearest to the mean of its cells: a label point inside the object even
/// when its footprint is L- or U-shaped. The footprint's mean without cells.
Eigen::Vector2d object_label_at(const objects::FurnitureObject& o,
                                const objects::ObjectsResult& res, const GridGeometry& geo) {
  std::vector<CellIndex> cells = o.own_cells;
  if (cells.empty() && res.labels.width > 0)
    for (int r = o.min_cell.row; r <= o.max_cell.row; ++r)
      for (int c = o.min_cell.col; c <= o.max_cell.col; ++c)
        if (res.labels.contains(c, r) && res.labels.at(c, r) == o.id) cells.push_back({c, r});
  if (cells.empty()) {
    Eigen::Vector2d m = Eigen::Vector2d::Zero();
    for (const auto& p : o.footprint_m) m += p;
    return o.footprint_m.empty() ? m : Eigen::Vector2d(m / double(o.footprint_m.size()));
  }
  double mc = 0.0, mr = 0.0;
  for (const auto& c : cells) {
    mc += c.col;
    mr += c.row;
  }
  mc /= static_cast<double>(cells.size());
  mr /= static_cast<double>(cells.size());
  CellIndex best = cells.front();
  double best_d = std::numeric_limits<double>::max();
  for (const auto& c : cells) {
    const double d = (c.col - mc) * (c.col - mc) + (c.row - mr) * (c.row - mr);
    if (d < best_d) best_d = d, best = c;
  }
  return geo.center_of(best);
}

std::string objects_fixed(double v, const char* unit) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f%s", v, unit);
  return buf;
}

}  // namespace

void write_objects_png(const std::filesystem::path& path, const layout::MapResult& map,
                       const objects::ObjectsResult& res) {
  RenderOptions ro;
  ro.title = "objects: " + std::to_string(res.objects.size());
  for (const auto& s : map.cloud_map.scanners) ro.markers_map.emplace_back(s.x(), s.y());
  std::array<bool, kObjectKinds.size()> used{};
  for (const auto& o : res.objects) {
    Overlay ov;
    ov.points_m = o.footprint_m;
    ov.label = std::to_string(o.id);
    ov.label_at_m = object_label_at(o, res, map.geometry);
    ov.rgb = kind_rgb(o.kind);
    ov.table_row = {ov.label, std::string(to_string(o.kind)), objects_fixed(o.area_m2, " m2"),
                    o.has_height ? objects_fixed(o.z_max_m - o.z_min_m, " m") : "-"};
    used[static_cast<std::size_t>(o.kind)] = true;
    ro.overlays.push_back(std::move(ov));
  }
  // The legend lists the kinds that occur (furniture always).
  used[static_cast<std::size_t>(ObjectKind::kFurniture)] = true;
  for (const ObjectKind k : kObjectKinds)
    if (used[static_cast<std::size_t>(k)])
      ro.legend.push_back({std::string(to_string(k)) + " (id)", kind_rgb(k)});
  ro.unlabelled.title = "objects with no room for their id on the map:";
  ro.unlabelled.header = {"id", "kind", "area", "height"};
  ro.unlabelled.col_px = {36, 100, 80, 64};
  write_layout_png(path, map.layout.layout, map.geometry, ro);
}

}  // namespace indoormap::draw
