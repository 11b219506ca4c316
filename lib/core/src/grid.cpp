#include "indoormap/core/grid.hpp"

#include <cmath>

namespace indoormap {

GridGeometry::GridGeometry(Eigen::Vector2d origin_m, double cell_m, int width, int height)
    : origin_m_(std::move(origin_m)), cell_m_(cell_m), width_(width), height_(height) {}

namespace {
// Saturates far-away and non-finite coordinates to an index that is outside every grid, so the
// conversion never overflows an int.
int to_cell_index(double v) {
  constexpr double kLimit = 1 << 30;
  if (!(v > -kLimit)) return -(1 << 30);
  if (!(v < kLimit)) return 1 << 30;
  return static_cast<int>(std::floor(v));
}
}  // namespace

CellIndex GridGeometry::cell_of(const Eigen::Vector2d& p_map) const {
  return {to_cell_index((p_map.x() - origin_m_.x()) / cell_m_),
          to_cell_index((p_map.y() - origin_m_.y()) / cell_m_)};
}

Eigen::Vector2d GridGeometry::center_of(CellIndex c) const {
  return {origin_m_.x() + (c.col + 0.5) * cell_m_, origin_m_.y() + (c.row + 0.5) * cell_m_};
}

Eigen::Vector2d GridGeometry::corner_of(CellIndex c) const {
  return {origin_m_.x() + c.col * cell_m_, origin_m_.y() + c.row * cell_m_};
}

}  // namespace indoormap
