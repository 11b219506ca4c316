#pragma once
// The map_server YAML (map.yaml) reader of every app. The ROS map format lives in lib/formats
// (writer, image decoding); its YAML keys are read here because YAML is read only in apps/
// (issue 12), with the same loader as the configs.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "indoormap/formats/ros_map.hpp"

namespace indoormap::app {

/// Reads the keys of a map_server YAML (the image is not opened). Throws InputError naming the
/// file and the key on malformed input.
formats::RosMapMeta read_map_yaml(const std::filesystem::path& yaml_path);

/// Reads map.yaml and the image it names (formats::decode_ros_map). Throws InputError /
/// BudgetError naming the file; max_cells bounds the image size. A rotated map (origin yaw != 0)
/// is refused (InputError): every reader of grids assumes an axis-aligned map frame.
formats::RosMap read_ros_map(const std::filesystem::path& yaml_path,
                             std::int64_t max_cells = 100'000'000);

/// The map an app's MAP argument names: a map YAML (.yaml / .yml; resolution_m must then be 0),
/// or a plain PNG / PGM image read with resolution_m metres per pixel and free_min
/// (formats::read_plain_map). Throws UsageError when the resolution does not fit the kind, or
/// when free_min_given (--free-min on the command line) names a map YAML, where it cannot act.
formats::RosMap load_map_argument(const std::string& path, double resolution_m, int free_min,
                                  bool free_min_given = false);

/// The files a MAP argument reads, for the provenance (provenance.hpp): a map YAML and the image
/// it names (relative to the YAML's folder), or the plain image itself. Call after
/// load_map_argument succeeded.
std::vector<std::string> map_argument_files(const std::string& path);

}  // namespace indoormap::app
