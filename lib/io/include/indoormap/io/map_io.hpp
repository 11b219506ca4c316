#pragma once
// ROS map_server files (map.pgm + map.yaml) and raw class images. Images are written north up:
// image row 0 holds grid row height-1 (the highest y), as map_server expects.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::io {

/// Grey values of the ROS trinary map (negate 0): occupied black, free white, unknown grey.
inline constexpr std::uint8_t kRosOccupied = 0;
inline constexpr std::uint8_t kRosFree = 254;
inline constexpr std::uint8_t kRosUnknown = 205;

struct RosMapMeta {
  std::string image = "map.pgm";
  double resolution_m = 0.05;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< x, y of the lower-left pixel corner, yaw
  int negate = 0;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
};

/// Writes <dir>/<stem>.pgm and <dir>/<stem>.yaml: occupied = wall or furniture, free, unknown.
void write_ros_map(const std::filesystem::path& dir, const std::string& stem,
                   const Grid<Cell>& layout, const GridGeometry& geometry);

/// Writes a P5 PGM of the raw values (north up).
void write_pgm(const std::filesystem::path& path, const Grid<std::uint8_t>& grid);
void write_layout_pgm(const std::filesystem::path& path, const Grid<Cell>& layout);

/// A ROS map as map_server reads it: occupancy from the grey levels and the YAML thresholds.
struct RosMap {
  RosMapMeta meta;
  GridGeometry geometry;
  Grid<Cell> cells;  ///< kWall for occupied, kFree, kUnknown
};
/// Reads map.yaml and the image it names (PGM or PNG, relative to the YAML). Throws InputError
/// naming the file and key on malformed input. max_cells bounds the image size.
RosMap read_ros_map(const std::filesystem::path& yaml_path, std::int64_t max_cells = 100'000'000);

/// Reads a plain building-map image (PNG / PGM, e.g. the room-segmentation maps): grey level
/// >= free_min is free, anything darker occupied (kWall). North up; origin (0, 0) at the
/// lower-left corner; resolution_m metres per pixel. Throws InputError / BudgetError.
RosMap read_plain_map(const std::filesystem::path& image, double resolution_m, int free_min = 250,
                      std::int64_t max_cells = 100'000'000);

/// Writes JSON (2-space indent) atomically.
void write_json(const std::filesystem::path& path, const nlohmann::json& j);

}  // namespace indoormap::io
