// Pipeline config YAML (-c FILE), through merge_config_file, then validate and the printers
// (--print-config, summary.json) on whatever was accepted.
#include "config.hpp"

#include "fuzz_target.hpp"

INDOORMAP_FUZZ_TARGET(config) {
  using namespace indoormap::fuzz;
  indoormap::app::PipelineConfig c;
  indoormap::app::merge_config_file(c, write_file(fresh_dir(), "config.yaml", bytes).string());
  (void)indoormap::app::to_yaml(c);
  (void)indoormap::app::to_json(c).dump();
  indoormap::app::validate(c);
}
