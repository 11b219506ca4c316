#include "indoormap/formats/costmap_masks.hpp"

#include <cmath>
#include <sstream>

#include "indoormap/core/atomic_file.hpp"
#include "indoormap/formats/pgm.hpp"
#include "indoormap/formats/ros_map.hpp"

namespace indoormap::formats {

int scale_mode_value(std::uint8_t pixel) {
  // map_server, mode scale, negate 0: occ = (255 - pixel) / 255; occ >= occupied_thresh (1) is
  // 100, occ <= free_thresh (0) is 0, otherwise round(100 * (occ - free) / (occupied - free)).
  return static_cast<int>(std::lround(100.0 * (255.0 - pixel) / 255.0));
}

std::uint8_t scale_mode_pixel(int value) {
  const int v = std::clamp(value, 0, 100);
  return static_cast<std::uint8_t>(std::lround(255.0 - 2.55 * v));
}

Grid<std::uint8_t> speed_mask(const areas::AreasResult& r, const SpeedPercents& percent) {
  Grid<std::uint8_t> g(r.labels.width, r.labels.height, scale_mode_pixel(0));
  for (std::size_t i = 0; i < g.size(); ++i) {
    const int id = r.labels.data[i];
    if (!id) continue;
    const double p = percent[static_cast<std::size_t>(r.areas[id - 1].kind)];
    const int value = p >= 100.0 ? 0 : std::max(1, static_cast<int>(std::lround(p)));
    g.data[i] = scale_mode_pixel(value);
  }
  return g;
}

namespace {

void write_filter_info(const std::filesystem::path& path, int type, const std::string& mask_topic) {
  std::ostringstream s;
  s << "# Nav2 Costmap Filter Info Server parameters (written by grid-areas)\n"
    << "costmap_filter_info_server:\n  ros__parameters:\n"
    << "    type: " << type << "\n"
    << "    filter_info_topic: \"/costmap_filter_info\"\n"
    << "    mask_topic: \"" << mask_topic << "\"\n"
    << "    base: 0.0\n    multiplier: 1.0\n";
  write_file_atomic(path, s.str());
}

void write_mask_yaml(const std::filesystem::path& path, const std::string& image,
                     const GridGeometry& g, const std::string& mode, double occupied, double free) {
  std::ostringstream s;
  s.precision(10);
  s << "image: " << image << "\nmode: " << mode << "\nresolution: " << g.cell_m() << "\norigin: ["
    << g.origin_m().x() << ", " << g.origin_m().y() << ", 0]\n"
    << "negate: 0\noccupied_thresh: " << occupied << "\nfree_thresh: " << free << "\n";
  write_file_atomic(path, s.str());
}

}  // namespace

void write_costmap_masks(const std::filesystem::path& dir, const areas::AreasResult& r,
                         const GridGeometry& geometry, const SpeedPercents& percent) {
  write_pgm(dir / "speed_mask.pgm", speed_mask(r, percent));
  write_mask_yaml(dir / "speed_mask.yaml", "speed_mask.pgm", geometry, "scale", 1.0, 0.0);
  write_filter_info(dir / "speed_filter_info.yaml", 1, "/speed_filter_mask");
  Grid<std::uint8_t> keepout(r.too_narrow.width, r.too_narrow.height, kRosFree);
  for (std::size_t i = 0; i < keepout.size(); ++i)
    if (r.too_narrow.data[i]) keepout.data[i] = kRosOccupied;
  write_pgm(dir / "keepout_mask.pgm", keepout);
  write_mask_yaml(dir / "keepout_mask.yaml", "keepout_mask.pgm", geometry, "trinary", 0.65, 0.196);
  write_filter_info(dir / "keepout_filter_info.yaml", 0, "/keepout_filter_mask");
}

}  // namespace indoormap::formats
