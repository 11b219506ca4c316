#pragma once
// YAML front of scene-sim: the scene file schema (docs/scene-sim.md) and the config file, both
// read with the rules of the one config reader (apps/common/config_reader.hpp). Errors are
// InputError naming the file, the key and the line.
#include <map>
#include <string>

#include "indoormap/sim/mobile.hpp"
#include "indoormap/sim/output.hpp"
#include "indoormap/sim/random_scene.hpp"
#include "indoormap/sim/scene.hpp"
#include "indoormap/sim/seen.hpp"
#include "indoormap/sim/simulate.hpp"

namespace indoormap::scene_sim {

/// Effective parameters of a run besides the scene itself.
struct Config {
  sim::ScannerParams scanner;
  sim::OutputOptions output;
  double sector_deg = 0.0;
  sim::RandomSceneParams random;
  int storeys = 1;  ///< building: storeys stacked on slabs (scene file: copies of the scene)
  double slab_thickness_m = 0.3;
  bool same_footprint = false;  ///< random building: every storey has storey 0's rooms
  bool mobile = false;          ///< mobile-scanner mode (sim/mobile.hpp)
  sim::MobileParams mobile_params;
  sim::SeenParams seen;
};

/// Applies a config file (sections scanner, output, random) on top of config.
void apply_config_file(const std::string& file, Config& config);

struct ParsedScene {
  sim::Scene scene;
  /// The 1-based line of every key path ("rooms[0].doors[1]"), for the messages of check_scene.
  std::map<std::string, std::size_t> key_lines;
};

/// Parses a scene file. The scene's own `scanner:` block overrides keys of base_scanner.
ParsedScene parse_scene_file(const std::string& file, const sim::ScannerParams& base_scanner);

/// The effective configuration as YAML (for --print-config), readable by apply_config_file.
std::string config_to_yaml(const Config& config);

}  // namespace indoormap::scene_sim
