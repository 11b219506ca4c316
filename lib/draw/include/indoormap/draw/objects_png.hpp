#pragma once
// objects.png (furniture-extract, docs/furniture-extract.md). Users of this header link
// im_objects and im_layout for the value types.
#include <filesystem>

#include "indoormap/layout/pipeline.hpp"
#include "indoormap/objects/objects.hpp"

namespace indoormap::draw {

/// The layout with every object's footprint outlined in the colour of its kind (kind_rgb) and
/// labelled with its id, the labels placed without overlap (beside the object with a leader line
/// when its own place is taken); objects whose id finds no free place are listed in a table
/// (id, kind, area, height) below the legend. The legend lists the kinds that occur and ends in
/// the 1 m scale bar.
void write_objects_png(const std::filesystem::path& path, const layout::MapResult& map,
                       const objects::ObjectsResult& objects);

}  // namespace indoormap::draw
