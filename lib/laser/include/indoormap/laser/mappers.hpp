#pragma once
// Both occupancy mappers behind one factory, for callers that pick the method by configuration.
#include <memory>
#include <string_view>

#include "indoormap/laser/himm.hpp"
#include "indoormap/laser/log_odds.hpp"

namespace indoormap::laser {

enum class MapperKind { kHimm, kLogOdds };

inline constexpr std::string_view to_string(MapperKind k) {
  return k == MapperKind::kHimm ? "himm" : "log_odds";
}

std::unique_ptr<OccupancyMapper> make_mapper(MapperKind kind, const OccupancyGridParams& grid,
                                             const HimmParams& himm = {},
                                             const LogOddsParams& log_odds = {});

}  // namespace indoormap::laser
