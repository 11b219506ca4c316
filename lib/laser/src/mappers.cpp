#include "indoormap/laser/mappers.hpp"

namespace indoormap::laser {

std::unique_ptr<OccupancyMapper> make_mapper(MapperKind kind, const OccupancyGridParams& grid,
                                             const HimmParams& himm,
                                             const LogOddsParams& log_odds) {
  if (kind == MapperKind::kHimm) return std::make_unique<HimmMapper>(grid, himm);
  return std::make_unique<LogOddsMapper>(grid, log_odds);
}

}  // namespace indoormap::laser
