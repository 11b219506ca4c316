#pragma once
// route.png (docs/plan-route.md). Users of this header link im_planning for the value types.
#include <filesystem>

#include "indoormap/formats/route_json.hpp"

namespace indoormap::draw {

/// route.png: safe zone, trajectory region, the best route with numbered turns (and the other
/// routes thin), start and goal, a legend and a 1 m scale bar; north up.
void write_route_png(const std::filesystem::path& path, const formats::RouteReport& report);

}  // namespace indoormap::draw
