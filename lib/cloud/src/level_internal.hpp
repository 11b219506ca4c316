#pragma once
// Internal to im_cloud: the support checks of estimate_level (level_support.cpp).
#include <vector>

#include "indoormap/cloud/level.hpp"

namespace indoormap::cloud::detail {

// Warnings about what the levelling rests on (into r.warnings), and whether it may be applied:
// false (the reason in r.note) when r.tilt_deg is above max_tilt_deg or its plane (the floor if
// found, else the ceiling) holds too little area or reaches round no scanner. Sets r.support.
bool level_supported(const std::vector<Eigen::Vector3d>& sample, const LevelParams& p,
                     const std::vector<Eigen::Vector3d>& scanners, LevelResult& r);

}  // namespace indoormap::cloud::detail
