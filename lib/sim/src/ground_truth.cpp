#include "indoormap/sim/ground_truth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "indoormap/core/angles.hpp"
#include "indoormap/core/errors.hpp"

namespace indoormap::sim {

namespace {

bool is_round(const Furniture& f) {
  return f.type == FurnitureType::kBin || f.type == FurnitureType::kPillar ||
         ((f.type == FurnitureType::kTable || f.type == FurnitureType::kLamp) && f.radius_m > 0);
}

/// Sets every cell whose centre lies in poly to value.
void paint(const GridGeometry& g, Grid<Cell>& cells, const Polygon& poly, Cell value) {
  const auto [lo, hi] = bounds(poly);
  const CellIndex a = g.cell_of(lo), b = g.cell_of(hi);
  for (int r = std::max(0, a.row); r <= std::min(g.height() - 1, b.row); ++r)
    for (int c = std::max(0, a.col); c <= std::min(g.width() - 1, b.col); ++c)
      if (contains(poly, g.center_of({c, r}))) cells.at(c, r) = value;
}
}  // namespace

std::vector<TruthItem> furniture_truth(const Scene& scene) {
  std::vector<TruthItem> out;
  for (std::size_t i = 0; i < scene.furniture.size(); ++i) {
    const Furniture& f = scene.furniture[i];
    TruthItem t;
    t.id = f.id;
    t.type = f.type;
    t.footprint = is_round(f) ? circle_polygon(f.center_m, f.radius_m)
                              : rectangle(f.center_m, f.size_m, f.yaw_deg * kDeg);
    t.z_min_m = std::numeric_limits<double>::infinity();
    t.z_max_m = -t.z_min_m;
    for (const Solid& s : furniture_solids(scene, static_cast<int>(i))) {
      if (s.radius_m > 0 && s.radius_m < 0.01) continue;  // lamp cords are not part of the lamp
      t.z_min_m = std::min(t.z_min_m, s.z0_m);
      t.z_max_m = std::max(t.z_max_m, s.z1_m);
    }
    // A pillar reaches the ceiling; its solid pokes 1 cm into it for a watertight scene.
    if (f.type == FurnitureType::kPillar && f.height_m <= 0 && room_at(scene, f.center_m) >= 0)
      t.z_max_m = ceiling_z(scene.rooms[room_at(scene, f.center_m)], f.center_m);
    t.on_floor = f.type != FurnitureType::kLamp;
    t.room = room_at(scene, f.center_m);
    out.push_back(std::move(t));
  }
  return out;
}

TruthLayout truth_layout(const Scene& scene, const SceneGeometry& geometry, double cell_m,
                         double margin_m, std::int64_t max_cells) {
  if (!(cell_m >= 0.001 && cell_m <= 10))
    throw UsageError("truth cell size must be in [0.001, 10] m");
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& s : geometry.solids) {
    if (s.furniture >= 0) continue;
    const auto [a, b] = bounds(s.footprint);
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(b);
  }
  for (const auto& room : scene.rooms) {
    const auto [a, b] = bounds(room.polygon);
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(b);
  }
  lo.array() -= margin_m;
  hi.array() += margin_m;
  lo = (lo / cell_m).array().floor() * cell_m;
  const double w = std::ceil((hi.x() - lo.x()) / cell_m - 1e-9),
               h = std::ceil((hi.y() - lo.y()) / cell_m - 1e-9);
  if (w * h > static_cast<double>(max_cells))
    throw BudgetError("truth layout: " + std::to_string(static_cast<long long>(w * h)) +
                      " cells exceed the budget; use a coarser cell");
  TruthLayout out;
  out.geometry = GridGeometry(lo, cell_m, static_cast<int>(w), static_cast<int>(h));
  out.cells = Grid<Cell>(out.geometry.width(), out.geometry.height(), Cell::kUnknown);
  for (const auto& room : scene.rooms) paint(out.geometry, out.cells, room.polygon, Cell::kFree);
  for (const auto& df : geometry.door_floors) paint(out.geometry, out.cells, df, Cell::kFree);
  for (const auto& item : furniture_truth(scene))
    if (item.on_floor) paint(out.geometry, out.cells, item.footprint, Cell::kFurniture);
  for (const auto& s : geometry.solids)
    if (s.furniture < 0 && s.z0_m <= 0.0) paint(out.geometry, out.cells, s.footprint, Cell::kWall);
  return out;
}

}  // namespace indoormap::sim
