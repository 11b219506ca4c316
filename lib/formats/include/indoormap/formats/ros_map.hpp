#pragma once
// ROS map_server files (map.pgm + map.yaml), writer and reader side by side, and the reader of
// plain building-map images. Images are written north up: image row 0 holds grid row height-1
// (the highest y), as map_server expects.
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "indoormap/core/cell.hpp"
#include "indoormap/core/grid.hpp"

namespace indoormap::formats {

/// Grey values of the ROS trinary map (negate 0): occupied black, free white, unknown grey.
inline constexpr std::uint8_t kRosOccupied = 0;
inline constexpr std::uint8_t kRosFree = 254;
inline constexpr std::uint8_t kRosUnknown = 205;

/// The keys of a map_server YAML.
struct RosMapMeta {
  std::string image = "map.pgm";
  double resolution_m = 0.05;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< x, y of the lower-left pixel corner, yaw
  int negate = 0;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  /// Written as "# <line>" lines after the keys (how to go back to the input frame, ...);
  /// map_server and read_map_yaml ignore them. A newline in a line is written as a space.
  std::vector<std::string> comments;
};

/// How write_map_yaml spells the file. Both read back the same; each app keeps the bytes it has
/// always written:
///  - kRosMap: a "mode: trinary" line, numbers with 10 significant digits (pcd-to-map's map.yaml,
///    plan-route's safe.yaml; origin 0 is written "0");
///  - kShortest: no mode line, numbers in the shortest text that reads back as the same double,
///    always with a decimal point (scene-sim's ground_truth_layout.yaml; origin 0 is "0.0").
enum class MapYamlStyle { kRosMap, kShortest };

/// Writes a map_server YAML (image, [mode,] resolution, origin with yaw 0, negate, thresholds,
/// then meta.comments) atomically. The yaw of meta.origin is not written: it is always 0.0.
void write_map_yaml(const std::filesystem::path& path, const RosMapMeta& meta,
                    MapYamlStyle style = MapYamlStyle::kRosMap);
/// The meta of a grid: image name, the geometry's resolution and origin, default thresholds.
RosMapMeta map_meta(const std::string& image, const GridGeometry& geometry);

/// Writes <dir>/<stem>.pgm and <dir>/<stem>.yaml: occupied = wall or furniture, free, unknown.
/// `comments` go to the YAML (RosMapMeta::comments).
void write_ros_map(const std::filesystem::path& dir, const std::string& stem,
                   const Grid<Cell>& layout, const GridGeometry& geometry,
                   const std::vector<std::string>& comments = {});

/// A ROS map as map_server reads it: occupancy from the grey levels and the YAML thresholds.
struct RosMap {
  RosMapMeta meta;
  GridGeometry geometry;
  Grid<Cell> cells;  ///< kWall for occupied, kFree, kUnknown
};
/// Decodes the image a map YAML names (PGM or PNG; a relative meta.image is relative to the
/// directory of yaml_path) into occupancy by meta's thresholds. The YAML itself is read in apps/
/// (app::read_map_yaml / app::read_ros_map in apps/common/map_yaml.hpp): YAML is read only
/// there. Throws InputError naming the image; BudgetError when it exceeds max_cells.
RosMap decode_ros_map(const RosMapMeta& meta, const std::filesystem::path& yaml_path,
                      std::int64_t max_cells = 100'000'000);

/// Reads a plain building-map image (PNG / PGM, e.g. the room-segmentation maps): grey level
/// >= free_min is free, anything darker occupied (kWall). North up; origin (0, 0) at the
/// lower-left corner; resolution_m metres per pixel. Throws InputError / BudgetError.
RosMap read_plain_map(const std::filesystem::path& image, double resolution_m, int free_min = 250,
                      std::int64_t max_cells = 100'000'000);

}  // namespace indoormap::formats
