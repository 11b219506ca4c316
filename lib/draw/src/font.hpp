#pragma once
// Private to im_draw: the one font of every picture (legends, labels, scale bars).
#include <opencv2/imgproc.hpp>

namespace indoormap::draw {

inline constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

}  // namespace indoormap::draw
