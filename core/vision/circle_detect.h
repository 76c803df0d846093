// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Auto-calibration from one frame: find the fisheye image circle (the lit disc the lens projects onto the sensor)
// and propose the principal point and r_pp that put the lens's field of view on that circle.
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "vision/lens.h"

namespace bs::vision {

struct ImageCircle {
  cv::Point2d centre;   // source pixels
  double radius = 0;    // pixels
  double rms_px = 0;    // RMS distance of the edge points used from the fitted circle
  int edge_points = 0;  // edge points used (points on the image border, where the sensor cuts the circle, excluded)
};

// Threshold (a fraction of the bright level, at least `min_level` of 255), largest connected region, its outer
// contour without the points on the image border, algebraic circle fit refined by Gauss-Newton on the geometric
// distance with outliers (> 3 px) dropped. Accepts 8/16-bit, 1 or 3 channels. nullopt when no disc is found.
std::optional<ImageCircle> detect_image_circle(const cv::Mat& image, double min_level = 20);

// The lens with its principal point on the circle's centre and r_pp chosen so that a ray circle_fov/2 off the axis
// lands on the circle (for equidistant: r_pp = (circle_fov/2) / radius). circle_fov_deg <= 0 means the lens's FOV;
// give a smaller one when the lit disc ends before the lens's FOV does (a dark outer ring, a hood, a chart that
// ends). Model, k and FOV are kept.
Lens propose_lens(const Lens& lens, const ImageCircle& circle, double circle_fov_deg = 0);

}  // namespace bs::vision
