#pragma once
// Scanner positions beyond the input files': a trajectory file (--trajectory), checked against the
// cloud it belongs to.
#include <string>

#include "cloud_hints.hpp"
#include "indoormap/core/cloud.hpp"

namespace indoormap::app {

/// How far outside the cloud's extent (every axis) a trajectory position may lie: a scanner
/// stands inside what it scans, and a head-mounted one a little above the highest return.
inline constexpr double kTrajectoryMarginM = 1.0;

/// Reads the trajectory (formats::read_trajectory) and adds its positions to cloud.scanners.
/// The points' origins are then unknown (cloud.origins cleared). Throws InputError naming the
/// file and line for a bad line, and for a position farther than kTrajectoryMarginM outside
/// `extent` (the wrong frame or unit: an error, not a warning, since every ray would be wrong).
void add_trajectory(const std::string& file, const CloudExtent& extent, PointCloud& cloud);

}  // namespace indoormap::app
