// map-eval's JSON inputs: ground_truth.json, objects.json, room.geojson; the same bytes go through
// all three readers.
#include "fuzz_target.hpp"
#include "indoormap/core/errors.hpp"
#include "indoormap/formats/ground_truth_json.hpp"
#include "indoormap/formats/objects_json.hpp"
#include "indoormap/formats/room_geojson.hpp"

INDOORMAP_FUZZ_TARGET(eval_json) {
  using namespace indoormap::fuzz;
  const auto dir = fresh_dir();
  const auto file = write_file(dir, "input.json", bytes);
  // Each reader either accepts the file or throws indoormap::Error; try all three.
  try {
    (void)indoormap::formats::read_truth_json(file);
  } catch (const indoormap::Error&) {
  }
  try {
    (void)indoormap::formats::read_objects_json(file);
  } catch (const indoormap::Error&) {
  }
  (void)indoormap::formats::read_room_geojson(file);
}
