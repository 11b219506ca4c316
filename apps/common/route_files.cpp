#include "route_files.hpp"

#include "indoormap/core/errors.hpp"
#include "indoormap/draw/route_png.hpp"

namespace indoormap::app {

std::vector<std::string> write_route_files(const std::filesystem::path& dir,
                                           const formats::RouteReport& rep) {
  if (!rep.safe || !rep.result) throw Error("write_route_outputs: incomplete report");
  formats::write_route_json(dir / "route.json", rep);
  draw::write_route_png(dir / "route.png", rep);
  formats::write_safe_map(dir, *rep.safe, rep.geometry);
  return {"route.json", "route.png", "safe.pgm", "safe.yaml"};
}

}  // namespace indoormap::app
