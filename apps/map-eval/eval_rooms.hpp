#pragma once
// map-eval's rooms of a floor (eval.json's "rooms"; docs/evaluation.md, "Rooms of a floor"): the
// result's rooms.geojson against the truth rooms (corridor included), matched by overlap; per
// truth room its status, polygon Hausdorff and area error; doors found; objects per room.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "indoormap/formats/ground_truth_json.hpp"
#include "indoormap/sim/eval.hpp"

namespace indoormap::map_eval {

struct RoomEvalParams {
  double hausdorff_max_m = 0.15;     ///< a room "within tolerance": Hausdorff at most this ...
  double area_error_max_rel = 0.03;  ///< ... and |area error| at most this share of the truth's
  double door_match_m = 0.3;         ///< a result door's midpoint this near the passage centre
  double cover_min = 0.2;            ///< overlaps below this share of the truth room's area: none
};

/// The "rooms" block. Status "missing" without RESULT/rooms.geojson. Throws InputError for a
/// malformed rooms.geojson (named).
nlohmann::ordered_json evaluate_rooms_block(const formats::TruthFile& truth,
                                            const std::filesystem::path& result_dir,
                                            const sim::EvalParams& objects_params,
                                            const RoomEvalParams& params = {});

}  // namespace indoormap::map_eval
