// Scene YAML (scene-sim SCENE.yaml), through parse_scene_file and the scene checks. The scene is
// not simulated: the simulator's own budget (max_rays) bounds that, and it is not a reader.
#include "indoormap/sim/scene.hpp"

#include "fuzz_target.hpp"
#include "scene_yaml.hpp"

INDOORMAP_FUZZ_TARGET(scene) {
  using namespace indoormap::fuzz;
  const auto parsed = indoormap::scene_sim::parse_scene_file(
      write_file(fresh_dir(), "scene.yaml", bytes).string(), {});
  (void)indoormap::sim::check_scene(parsed.scene);
}
