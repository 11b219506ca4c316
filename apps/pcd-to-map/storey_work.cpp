#include "storey_work.hpp"

#include <utility>

#include "objects_outputs.hpp"
#include "pipeline_run.hpp"

namespace indoormap::app {

StoreyWork compute_storey(int index, layout::MapResult map, const PipelineConfig& cfg) {
  StoreyWork w;
  w.index = index;
  w.map = std::move(map);
  // The inner walls of a floor may be strips of stray returns: the rooms step sees every piece.
  w.objs = timed_objects(w.map, cfg.objects, &w.objects_ms, false);
  const Grid<std::int32_t> pieces = w.objs.labels;
  w.rooms = find_storey_rooms(w.map, w.objs, cfg.border);  // drops the inner walls from the objects
  if (strays_unfiltered(w.map)) {
    // The objects again without the stray cells; those on what the rooms took for wall leave.
    w.objs = timed_objects(w.map, cfg.objects, &w.objects_ms, true);
    remove_objects_on(w.objs, pieces, w.rooms);
  } else {
    objects::drop_stray_pieces(w.objs, w.map.geometry, cfg.objects);
  }
  w.border = timed_border(w.map, cfg.border, &w.border_ms);
  w.furniture_count = w.objs.objects.size();
  add_border_objects(w.objs, w.border, cfg.objects.min_area_m2);
  assign_rooms(w.rooms, w.objs);
  return w;
}

}  // namespace indoormap::app
