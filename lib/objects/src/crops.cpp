#include <algorithm>
#include <cmath>
#include <limits>

#include "indoormap/objects/objects.hpp"

namespace indoormap::objects {

std::vector<std::vector<std::size_t>> crop_indices(const ObjectsResult& result,
                                                   const GridGeometry& geo,
                                                   const std::vector<Eigen::Vector3f>& points_map,
                                                   double crop_margin_m) {
  const int w = geo.width(), h = geo.height();
  const std::size_t n_obj = result.objects.size();
  std::vector<std::vector<std::size_t>> out(n_obj);
  if (n_obj == 0 || w == 0 || h == 0) return out;
  const int dil = std::max(0, static_cast<int>(std::ceil(crop_margin_m / geo.cell_m() - 1e-9)));

  // Cell -> objects whose dilated footprint covers it, as a compressed list (CSR).
  std::vector<std::pair<std::int64_t, int>> covered;  // (cell index, object index)
  Grid<std::int32_t> last(w, h, -1);
  for (std::size_t k = 0; k < n_obj; ++k) {
    const auto& o = result.objects[k];
    std::vector<CellIndex> cells = o.own_cells;
    if (cells.empty())
      for (int r = o.min_cell.row; r <= o.max_cell.row; ++r)
        for (int c = o.min_cell.col; c <= o.max_cell.col; ++c)
          if (result.labels.at(c, r) == o.id) cells.push_back({c, r});
    for (const auto& [c, r] : cells)
      for (int rr = std::max(0, r - dil); rr <= std::min(h - 1, r + dil); ++rr)
        for (int cc = std::max(0, c - dil); cc <= std::min(w - 1, c + dil); ++cc)
          if (last.at(cc, rr) != static_cast<std::int32_t>(k)) {
            last.at(cc, rr) = static_cast<std::int32_t>(k);
            covered.emplace_back(static_cast<std::int64_t>(rr) * w + cc, static_cast<int>(k));
          }
  }
  std::sort(covered.begin(), covered.end());
  std::vector<std::uint32_t> first(static_cast<std::size_t>(w) * h + 1, 0);
  for (const auto& [cell, k] : covered) ++first[static_cast<std::size_t>(cell) + 1];
  for (std::size_t i = 1; i < first.size(); ++i) first[i] += first[i - 1];

  std::vector<float> zlo(n_obj), zhi(n_obj);
  for (std::size_t k = 0; k < n_obj; ++k) {
    const auto& o = result.objects[k];
    zlo[k] = o.has_height ? static_cast<float>(o.z_min_m - crop_margin_m)
                          : -std::numeric_limits<float>::infinity();
    zhi[k] = o.has_height ? static_cast<float>(o.z_max_m + crop_margin_m)
                          : std::numeric_limits<float>::infinity();
  }
  for (std::size_t i = 0; i < points_map.size(); ++i) {
    const auto& p = points_map[i];
    if (!p.allFinite()) continue;
    const CellIndex c = geo.cell_of({p.x(), p.y()});
    if (!geo.contains(c)) continue;
    const auto cell = static_cast<std::size_t>(c.row) * w + c.col;
    for (std::uint32_t j = first[cell]; j < first[cell + 1]; ++j) {
      const int k = covered[j].second;
      if (p.z() >= zlo[k] && p.z() <= zhi[k]) out[k].push_back(i);
    }
  }
  return out;
}

}  // namespace indoormap::objects
