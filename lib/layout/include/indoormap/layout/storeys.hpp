#pragma once
// Storeys of a levelled cloud, from the horizontal-surface histogram (the occupied cells per voxel
// layer): a slab between one storey's ceiling and the next one's floor is a run of (nearly) empty
// layers; each storey's floor and ceiling are its lowest and highest strong layers.
// Each storey is then mapped on its own (make_storey_maps). docs/pipeline.md, "Storeys".
#include <cstdint>
#include <string>
#include <vector>

#include "indoormap/core/voxel_geometry.hpp"
#include "indoormap/layout/pipeline.hpp"

namespace indoormap::layout {

struct StoreyParams {
  bool enabled = true;  ///< false: the whole cloud is one storey (today's single-room pipeline)
  /// A slab: a run of layers at least min_slab_m thick whose occupied cells are at most
  /// slab_max_fraction of the fullest layer's, with at least min_height_m of data below it (down
  /// to the previous slab) and above it. Within a storey every layer holds the walls; inside a
  /// slab nothing is seen.
  double slab_max_fraction = 0.02;
  double min_slab_m = 0.1;
  double min_height_m = 1.8;
  /// A storey's floor and ceiling: its lowest and highest layer with at least this share of the
  /// occupied cells of the storey's fullest layer.
  double surface_min_fraction = 0.3;
};

/// Throws UsageError naming the key (storeys.<key>).
void validate(const StoreyParams& params);

struct Storey {
  double floor_z_m = 0.0, ceiling_z_m = 0.0;  ///< surface layer centres, map frame
  double lo_z_m = 0.0, hi_z_m = 0.0;          ///< the points of this storey: z in [lo, hi)
};

/// The storeys, bottom up, from the occupied cells per layer of `geometry`. One storey (the
/// whole height, floor and ceiling left to the layer analysis) unless a slab is found.
std::vector<Storey> detect_storeys(const std::vector<std::int64_t>& occupied_per_layer,
                                   const VoxelGeometry& geometry, const StoreyParams& params = {});

struct StoreyMaps {
  std::vector<Storey> storeys;  ///< every storey found
  std::vector<int> mapped;      ///< the storeys mapped, indices into storeys (all, or --storey)
  std::vector<MapResult> maps;  ///< one per mapped storey
};

/// Levels the cloud once, finds its storeys, and maps each (or only storey `only` when >= 0) with
/// make_map on its points (already levelled: the level result is the whole cloud's). With one
/// storey the result is make_map's on the whole cloud. Throws UsageError when `only` is beyond
/// the storeys found (nothing mapped), and what make_map throws.
StoreyMaps make_storey_maps(PointCloud cloud, const MapParams& params, const StoreyParams& sp,
                            int only = -1);

}  // namespace indoormap::layout
