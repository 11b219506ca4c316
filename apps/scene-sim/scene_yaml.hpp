#pragma once
// YAML front of scene-sim: the scene file schema (docs/scene-sim.md) and the config file.
// Errors are InputError naming the file, the key and the line.
#include <yaml-cpp/yaml.h>

#include <map>
#include <string>

#include "indoormap/sim/output.hpp"
#include "indoormap/sim/random_scene.hpp"
#include "indoormap/sim/scene.hpp"
#include "indoormap/sim/simulate.hpp"

namespace indoormap::scene_sim {

/// Effective parameters of a run besides the scene itself.
struct Config {
  sim::ScannerParams scanner;
  sim::OutputOptions output;
  double sector_deg = 0.0;
  sim::RandomSceneParams random;
};

/// Reads a YAML file, turning yaml-cpp's exceptions into InputError (file, problem, line).
YAML::Node load_yaml_file(const std::string& file);

/// Applies a config file (keys scanner, output, random) on top of config.
void apply_config_file(const std::string& file, Config& config);

/// Parses a scene file. The scene's own `scanner:` block overrides keys of base_scanner.
/// key_lines receives the 1-based line of every key path ("rooms[0].doors[1]") for messages.
sim::Scene parse_scene_file(const std::string& file, const sim::ScannerParams& base_scanner,
                            std::map<std::string, std::size_t>& key_lines);

/// The effective configuration as YAML (for --print-config), readable by apply_config_file.
std::string config_to_yaml(const Config& config);

}  // namespace indoormap::scene_sim
