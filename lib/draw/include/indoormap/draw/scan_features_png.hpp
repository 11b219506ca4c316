#pragma once
// The picture of one laser scan with its features (scan-features' scan_<N>.png): the returns,
// walls (with an arrow at their end: free side on the left), doors, corners by type, corridors,
// the sensor; map frame, north up, with legend and scale bar.
#include <filesystem>
#include <string>

#include "indoormap/laser/scan.hpp"
#include "indoormap/scan_features/features.hpp"

namespace indoormap::draw {

/// Writes the picture atomically (throws OutputError). target_width_px: about this wide.
void write_scan_features_png(const std::filesystem::path& path, const laser::LaserScan& scan,
                             const scan_features::ScanFeatures& features, const std::string& title,
                             int target_width_px = 1000);

}  // namespace indoormap::draw
