#pragma once
// Angle units: degrees appear in configs and reports, radians in every computation.
#include <numbers>

namespace indoormap {

/// Radians per degree: angle_rad = angle_deg * kDeg.
inline constexpr double kDeg = std::numbers::pi / 180.0;

}  // namespace indoormap
