#pragma once
// The map_server YAML (map.yaml) reader of every app. The ROS map format lives in lib/formats
// (writer, image decoding); its YAML keys are read here because YAML is read only in apps/
// (issue 12), with the same loader as the configs.
#include <cstdint>
#include <filesystem>

#include "indoormap/formats/ros_map.hpp"

namespace indoormap::app {

/// Reads the keys of a map_server YAML (the image is not opened). Throws InputError naming the
/// file and the key on malformed input.
formats::RosMapMeta read_map_yaml(const std::filesystem::path& yaml_path);

/// Reads map.yaml and the image it names (formats::decode_ros_map). Throws InputError /
/// BudgetError naming the file; max_cells bounds the image size.
formats::RosMap read_ros_map(const std::filesystem::path& yaml_path,
                             std::int64_t max_cells = 100'000'000);

}  // namespace indoormap::app
