#include "indoormap/core/errors.hpp"
#include "indoormap/objects/objects.hpp"

namespace indoormap::objects {

void validate(const ObjectParams& ob) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw UsageError("invalid parameter " + what);
  };
  require(ob.min_area_m2 >= 0, "objects.min_area_m2: must be >= 0");
  require(ob.join_gap_m >= 0 && ob.join_gap_m <= 1, "objects.join_gap_m: must be in [0, 1]");
  require(ob.neck_width_m >= 0 && ob.neck_width_m <= 2, "objects.neck_width_m: must be in [0, 2]");
  require(ob.neck_min_part_m2 > 0 && ob.neck_min_part_m2 <= 100,
          "objects.neck_min_part_m2: must be in (0, 100]");
  require(ob.min_seen_area_m2 >= 0, "objects.min_seen_area_m2: must be >= 0");
  require(ob.crop_margin_m >= 0 && ob.crop_margin_m <= 10,
          "objects.crop_margin_m: must be in [0, 10]");
  require(ob.split_height_step_m >= 0, "objects.split_height_step_m: must be >= 0 (0: off)");
  require(ob.hanging_min_clearance_m > 0, "objects.hanging_min_clearance_m: must be > 0");
  require(ob.pillar_max_extent_m >= 0, "objects.pillar_max_extent_m: must be >= 0");
  require(ob.lamp_max_extent_m >= 0, "objects.lamp_max_extent_m: must be >= 0");
  require(ob.max_vertical_gap_m > 0, "objects.max_vertical_gap_m: must be > 0");
  require(ob.top_percentile >= 0 && ob.top_percentile <= 100,
          "objects.top_percentile: must be in [0, 100]");
}

}  // namespace indoormap::objects
