#pragma once
// What pcd-to-map computes for each storey before writing anything: the objects, the rooms (the
// inner walls dropped from the objects), the room border (its interior objects added) and each
// object's room. Shared with the Python bindings (apps/python), which return it as numpy arrays.
#include <cstddef>

#include "config.hpp"
#include "indoormap/border/border.hpp"
#include "indoormap/layout/pipeline.hpp"
#include "indoormap/objects/objects.hpp"
#include "rooms_outputs.hpp"

namespace indoormap::app {

struct StoreyWork {
  int index = 0;  ///< the storey (0: the lowest)
  layout::MapResult map;
  objects::ObjectsResult objs;
  border::BorderResult border;
  StoreyRooms rooms;
  std::size_t furniture_count = 0;  ///< objects before the border's interior objects joined
  double objects_ms = 0.0, border_ms = 0.0;
};

/// The storey `index`'s work on its map (moved in), with cfg's objects.* and border.* keys.
StoreyWork compute_storey(int index, layout::MapResult map, const PipelineConfig& cfg);

}  // namespace indoormap::app
