#include "indoormap/sim/output.hpp"

#include "indoormap/core/errors.hpp"

namespace indoormap::sim {

void validate(const OutputOptions& options) {
  if (!(options.truth_cell_m >= 0.001 && options.truth_cell_m <= 10))
    throw UsageError("truth cell size must be in [0.001, 10] m");
}

}  // namespace indoormap::sim
