#pragma once
// pcd-to-map's border outputs (docs/border-closure.md): the room border closed from the layout,
// written as room.geojson, room.json and border.png.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "indoormap/border/border.hpp"
#include "indoormap/layout/pipeline.hpp"

namespace indoormap::app {

/// Writes the room border r of m (closed by border::close_border in closure_ms), atomically, into
/// out:
///  - room.geojson (formats::write_room_geojson): a FeatureCollection in map metres;
///  - room.json (formats::room_json): the raw chain (cells and metres), polygon, openings,
///    components;
///  - border.png (draw::write_border_png): the layout with the chain, the polygon and the
///    openings drawn, with a legend.
/// No closed border is an expected outcome: the files are still written (without the room
/// feature), a warning goes to stderr, and the returned block says closed = false with the
/// reason. Returns the block for summary.json, whose "outputs" lists the files written.
nlohmann::json write_border_outputs(const std::filesystem::path& out, const layout::MapResult& m,
                                    const border::BorderResult& r, double closure_ms);

}  // namespace indoormap::app
