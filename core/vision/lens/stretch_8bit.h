// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Grey images of any bit depth as 8-bit, for the OpenCV steps that take 8-bit input only (the checkerboard corner
// finder, the circle finder's coarse threshold): one helper so that both stretch a 16-bit image alike.
#include <opencv2/core.hpp>

namespace bs::vision {

// `grey` itself when it is 8-bit; otherwise scaled so that its maximum becomes 255 (a 10- or 12-bit image kept in
// the low bits of 16 fills the range).
inline cv::Mat stretch_to_8bit(const cv::Mat& grey) {
  if (grey.depth() == CV_8U) return grey;
  double max = 0;
  cv::minMaxLoc(grey, nullptr, &max);
  cv::Mat out;
  grey.convertTo(out, CV_8U, max > 0 ? 255.0 / max : 1.0);
  return out;
}

}  // namespace bs::vision
