#pragma once
// Grid geometry and a plain 2D grid value type. One place owns the world <-> cell conversion;
// no algorithm recomputes floor((x - origin) / resolution) by itself.
//
// Conventions (shared by every module and output):
//  - The map frame is metric, right-handed, z up, levelled (see docs/pipeline.md).
//  - Cell (col, row) covers [origin.x + col*cell_m, +cell_m) x [origin.y + row*cell_m, +cell_m):
//    row 0 is the *lowest* y. Image writers flip rows so that north (max y) is up, as ROS does.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace indoormap {

struct CellIndex {
  int col = 0;
  int row = 0;
  friend bool operator==(const CellIndex&, const CellIndex&) = default;
};

class GridGeometry {
 public:
  GridGeometry() = default;
  /// origin_m: map-frame (x, y) of the lower-left corner of cell (0, 0).
  GridGeometry(Eigen::Vector2d origin_m, double cell_m, int width, int height);

  const Eigen::Vector2d& origin_m() const { return origin_m_; }
  double cell_m() const { return cell_m_; }
  int width() const { return width_; }
  int height() const { return height_; }
  std::int64_t cell_count() const { return std::int64_t{width_} * height_; }

  /// Cell containing a map-frame point (may lie outside the grid; check contains()).
  CellIndex cell_of(const Eigen::Vector2d& p_map) const;
  /// Map-frame centre of a cell.
  Eigen::Vector2d center_of(CellIndex c) const;
  /// Map-frame lower-left corner of a cell (c may lie outside the grid: corners of the far edge).
  Eigen::Vector2d corner_of(CellIndex c) const;
  /// Continuous cell coordinates of a map-frame point: (0, 0) is the lower-left corner of cell
  /// (0, 0), (0.5, 0.5) its centre; cell_of(p) == floor(to_cell_coords(p)).
  Eigen::Vector2d to_cell_coords(const Eigen::Vector2d& p_map) const {
    return (p_map - origin_m_) / cell_m_;
  }
  /// Inverse of to_cell_coords: the map-frame point at continuous cell coordinates v.
  Eigen::Vector2d from_cell_coords(const Eigen::Vector2d& v) const {
    return origin_m_ + v * cell_m_;
  }
  /// A length in metres as a (fractional) number of cells.
  double to_cells(double length_m) const { return length_m / cell_m_; }
  bool contains(CellIndex c) const {
    return c.col >= 0 && c.row >= 0 && c.col < width_ && c.row < height_;
  }

  friend bool operator==(const GridGeometry&, const GridGeometry&) = default;

 private:
  Eigen::Vector2d origin_m_ = Eigen::Vector2d::Zero();
  double cell_m_ = 0.05;
  int width_ = 0;
  int height_ = 0;
};

/// Row-major 2D grid of values; element (col, row) at data[row * width + col].
template <class T>
struct Grid {
  int width = 0;
  int height = 0;
  std::vector<T> data;

  Grid() = default;
  Grid(int w, int h, T fill = T{})
      : width(w),
        height(h),
        data(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), fill) {}

  bool contains(int col, int row) const {
    return col >= 0 && row >= 0 && col < width && row < height;
  }
  T& at(int col, int row) { return data[static_cast<std::size_t>(row) * width + col]; }
  const T& at(int col, int row) const { return data[static_cast<std::size_t>(row) * width + col]; }
  T& at(CellIndex c) { return at(c.col, c.row); }
  const T& at(CellIndex c) const { return at(c.col, c.row); }
  std::size_t size() const { return data.size(); }
};

}  // namespace indoormap
