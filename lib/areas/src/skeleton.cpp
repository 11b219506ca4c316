// Zhang-Suen thinning (Zhang and Suen, CACM 1984).
#include <opencv2/core.hpp>
#include <vector>

#include "corridors.hpp"

namespace indoormap::areas::detail {

void thin(cv::Mat& img) {
  // img: CV_8U, 0/1, with a zero border (the callers pad their crops).
  std::vector<cv::Point> del;
  bool changed = true;
  while (changed) {
    changed = false;
    for (int pass = 0; pass < 2; ++pass) {
      del.clear();
      for (int r = 1; r + 1 < img.rows; ++r)
        for (int c = 1; c + 1 < img.cols; ++c) {
          if (!img.at<std::uint8_t>(r, c)) continue;
          const int p2 = img.at<std::uint8_t>(r - 1, c), p3 = img.at<std::uint8_t>(r - 1, c + 1),
                    p4 = img.at<std::uint8_t>(r, c + 1), p5 = img.at<std::uint8_t>(r + 1, c + 1),
                    p6 = img.at<std::uint8_t>(r + 1, c), p7 = img.at<std::uint8_t>(r + 1, c - 1),
                    p8 = img.at<std::uint8_t>(r, c - 1), p9 = img.at<std::uint8_t>(r - 1, c - 1);
          const int b = p2 + p3 + p4 + p5 + p6 + p7 + p8 + p9;
          if (b < 2 || b > 6) continue;
          const int a = (!p2 && p3) + (!p3 && p4) + (!p4 && p5) + (!p5 && p6) + (!p6 && p7) +
                        (!p7 && p8) + (!p8 && p9) + (!p9 && p2);
          if (a != 1) continue;
          if (pass == 0 && ((p2 && p4 && p6) || (p4 && p6 && p8))) continue;
          if (pass == 1 && ((p2 && p4 && p8) || (p2 && p6 && p8))) continue;
          del.emplace_back(c, r);
        }
      for (const auto& q : del) img.at<std::uint8_t>(q) = 0;
      changed = changed || !del.empty();
    }
  }
}

}  // namespace indoormap::areas::detail
