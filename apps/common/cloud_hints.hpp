#pragma once
// Hints that turn a pipeline error (or a confident but wrong map) into the likely real problem:
// a cloud in millimetres or centimetres read as metres, points far apart in height, a wrong up
// axis. Heuristics on the cloud's extent; each states the figures it is based on.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "indoormap/cloud_io/load.hpp"
#include "indoormap/core/voxel_geometry.hpp"

namespace indoormap::app {

/// Axis-aligned extent of the finite points (output frame: metres, z up); empty when none.
struct CloudExtent {
  Eigen::Vector3d lo_m = Eigen::Vector3d::Zero(), hi_m = Eigen::Vector3d::Zero();
  bool empty = true;
  Eigen::Vector3d size_m() const { return hi_m - lo_m; }
};
CloudExtent extent_of(const cloud_io::LoadResult& loaded);  ///< the bounds taken while loading

/// A horizontal extent above this suggests a unit other than the one given (no indoor scan spans
/// a kilometre; the project's clouds, the Jacobs scan and the simulated scenes span < 100 m).
inline constexpr double kUnitHintExtentM = 1000.0;

/// "the cloud spans X x Y x Z m: is it in millimetres or centimetres? ..." when the horizontal
/// extent is above kUnitHintExtentM; empty otherwise. unit_m: the unit the cloud was read in.
std::string unit_hint(const CloudExtent& e, double unit_m);

/// For "all points lie at one height": the points' height span and voxel.bounds_gap_m, when the
/// span is wider than one gap (the robust bounds kept only the points around the median).
std::string height_hint(const CloudExtent& e, double bounds_gap_m);

/// A warning when the grid (the robust bounds of the levelled cloud) is taller than kUpAxisMinM
/// and more than kUpAxisRatio times its narrower horizontal side: a cloud with another up axis
/// read as z up (a room's height then becomes a horizontal side, and a wall the floor). Empty
/// otherwise.
inline constexpr double kUpAxisMinM = 4.0;
inline constexpr double kUpAxisRatio = 1.5;
std::string up_axis_warning(const VoxelGeometry& g, const std::string& inputs);

}  // namespace indoormap::app
