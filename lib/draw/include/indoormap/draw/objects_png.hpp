#pragma once
// objects.png (furniture-extract, docs/furniture-extract.md). Users of this header link
// im_objects and im_layout for the value types.
#include <filesystem>

#include "indoormap/layout/pipeline.hpp"
#include "indoormap/objects/objects.hpp"

namespace indoormap::draw {

/// The layout with every object's footprint outlined in the colour of its kind and labelled with
/// its id; the legend lists the kinds that occur.
void write_objects_png(const std::filesystem::path& path, const layout::MapResult& map,
                       const objects::ObjectsResult& objects);

}  // namespace indoormap::draw
