// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The straight-line check of a calibration: points the user clicks along a scene line that is straight in the
// world (a door frame, a chart line) must lie on a straight line in a rectilinear view when the lens is right.
#include <vector>

#include <opencv2/core.hpp>

namespace bs::vision {

struct LineResidual {
  double rms_px = 0;  // RMS perpendicular distance of the points from the total-least-squares line
  double max_px = 0;  // largest perpendicular distance
  int points = 0;
  cv::Point2d point;      // a point on the fitted line (the centroid)
  cv::Point2d direction;  // unit direction of the fitted line
};

// Total least squares (principal axis of the points). Needs at least 3 distinct points: throws
// std::invalid_argument otherwise (2 points always fit exactly, so they say nothing).
LineResidual line_residual(const std::vector<cv::Point2d>& points);

}  // namespace bs::vision
