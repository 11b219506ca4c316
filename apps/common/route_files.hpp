#pragma once
// The route planner's output files, shared by plan-route and pcd-to-map --start/--goal
// (docs/plan-route.md): route.json, route.png, safe.pgm + safe.yaml.
#include <filesystem>
#include <string>
#include <vector>

#include "indoormap/formats/route_json.hpp"

namespace indoormap::app {

/// Writes route.json and safe.pgm + safe.yaml (lib/formats) and route.png (lib/draw) into dir,
/// each atomically; returns the file names written. Throws Error on an incomplete report.
std::vector<std::string> write_route_files(const std::filesystem::path& dir,
                                           const formats::RouteReport& report);

}  // namespace indoormap::app
