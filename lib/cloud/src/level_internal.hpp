#pragma once
// Internal to im_cloud: the support checks of estimate_level (level_support.cpp).
#include <string>
#include <vector>

#include "indoormap/cloud/level.hpp"

namespace indoormap::cloud::detail {

// Warnings about what the levelling rests on (into r.warnings), and whether it may be applied:
// false (the reason in r.note) when r.tilt_deg is above max_tilt_deg or its plane (the floor if
// found, else the ceiling) holds too little area or reaches round no scanner. Sets r.support.
bool level_supported(const std::vector<Eigen::Vector3d>& sample, const LevelParams& p,
                     const std::vector<Eigen::Vector3d>& scanners, LevelResult& r);

/// "12 %".
std::string level_percent(double share);

// The share of `plane`'s inliers among `sample` whose 0.1 m column holds a point of `sample`
// more than 0.3 m beyond the plane on `side` (+1: above, -1: below; 0 when the plane is not
// found). Nothing lies below a floor or above a ceiling; a plane that cuts through walls (the
// rows of a 16-beam lidar crossing the walls near the horizon fit planes within the inlier band)
// has the walls' other points beyond it.
double beyond_share(const std::vector<Eigen::Vector3d>& sample, const PlaneFit& plane,
                    double inlier_m, double side);

}  // namespace indoormap::cloud::detail
