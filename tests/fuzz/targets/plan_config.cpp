// plan-route's config YAML (-c FILE, config/plan-route.yaml), through merge_plan_config_file,
// then what the app does with an accepted file: validate, --print-config (to_yaml) and
// summary.json (to_json).
#include "plan_config.hpp"

#include "fuzz_target.hpp"

INDOORMAP_FUZZ_TARGET(plan_config) {
  using namespace indoormap::fuzz;
  indoormap::app::PlanConfig c;
  indoormap::app::merge_plan_config_file(c, write_file(fresh_dir(), "plan.yaml", bytes).string());
  (void)indoormap::app::to_yaml(c);
  (void)indoormap::app::to_json(c).dump();
  indoormap::app::validate(c);
}
