#include "border_outputs.hpp"

#include <iostream>
#include <string>

#include "indoormap/draw/border_png.hpp"
#include "indoormap/formats/json.hpp"
#include "indoormap/formats/room_geojson.hpp"

namespace indoormap::app {

namespace fs = std::filesystem;
using nlohmann::json;

json write_border_outputs(const fs::path& out, const layout::MapResult& m,
                          const border::BorderResult& r, double ms) {
  formats::write_json(out / "room.json", formats::room_json(r, m.geometry));
  formats::write_room_geojson(out / "room.geojson", r);
  draw::write_border_png(out / "border.png", m, r);

  json openings = json::array();
  int doors = 0;
  for (const auto& o : r.openings) {
    openings.push_back(formats::border_opening_json(o));
    doors += o.is_door_candidate ? 1 : 0;
  }
  if (!r.closed) std::cerr << "pcd-to-map: warning: no closed room border: " << r.reason << "\n";
  for (const auto& w : r.warnings) std::cerr << "pcd-to-map: warning: border: " << w << "\n";
  json block = {{"closed", r.closed},
                {"area_m2", r.area_m2},
                {"perimeter_m", r.perimeter_m},
                {"chain_cells", r.chain.size()},
                {"polygon_vertices", r.polygon_m.size()},
                {"openings", openings},
                {"door_candidates", doors},
                {"components", r.components.size()},
                {"interior_objects", r.interior_objects.size()},
                {"warnings", r.warnings},
                {"time_ms", ms},
                {"outputs", {"room.geojson", "room.json", "border.png"}}};
  if (!r.closed) block["reason"] = r.reason;
  return block;
}

}  // namespace indoormap::app
