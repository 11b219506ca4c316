#include "cloud_hints.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace indoormap::app {

namespace {

std::string fmt(const char* f, double a, double b = 0, double c = 0) {
  char buf[320];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

}  // namespace

CloudExtent extent_of(const cloud_io::LoadResult& loaded) {
  CloudExtent e;
  e.empty = !(loaded.lo_m.array() <= loaded.hi_m.array()).all();
  if (!e.empty) {
    e.lo_m = loaded.lo_m.cast<double>();
    e.hi_m = loaded.hi_m.cast<double>();
  }
  return e;
}

std::string unit_hint(const CloudExtent& e, double unit_m) {
  const Eigen::Vector3d s = e.size_m();
  if (e.empty || std::max(s.x(), s.y()) <= kUnitHintExtentM) return "";
  const std::string spans = "the cloud spans " + fmt("%.4g x %.4g x %.4g m", s.x(), s.y(), s.z());
  if (unit_m <= 0.001) return "";  // read as millimetres already: no smaller unit to suggest
  return spans + " (read with a unit of " + fmt("%g", unit_m) +
         " m): is it in millimetres or centimetres? try --unit mm (or --unit cm, input.unit_m)";
}

std::string height_hint(const CloudExtent& e, double bounds_gap_m) {
  if (e.empty || e.size_m().z() <= bounds_gap_m) return "";
  return fmt(
      "the points span heights %.4g .. %.4g m, but they are more than voxel.bounds_gap_m "
      "(%g m) apart: only the ones around the median were kept (too few points, or "
      "outliers far above or below the room)",
      e.lo_m.z(), e.hi_m.z(), bounds_gap_m);
}

std::string up_axis_warning(const VoxelGeometry& g, const std::string& inputs) {
  const double h = static_cast<double>(g.nz) * g.cell_m;
  const double w = static_cast<double>(std::min(g.nx, g.ny)) * g.cell_m;
  if (!(h > kUpAxisMinM && h > kUpAxisRatio * w)) return "";
  return inputs + ": the cloud is " + fmt("%.3g m high but only %.3g m wide", h, w) +
         " along its narrower side: is its up axis another one? check --up-axis (z or y; "
         "input.up_axis), or the floor found may be a wall";
}

}  // namespace indoormap::app
