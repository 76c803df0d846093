// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Synthetic captures with ground truth: a flat test chart (checkerboard, straight lines, colour patches) standing
// one unit in front of the camera, seen through a lens model, rendered as the sensor would record it.
#include <opencv2/core.hpp>

#include "vision/demosaic/bayer.h"
#include "vision/lens/lens.h"

namespace bs::vision {

// Colour (BGR, 0..1) of the chart at plane coordinates (y right, z up); the chart is the plane x = 1.
// Dark straight lines run along y = +-0.5 and z = +-0.4 (width 0.02, in a light quiet zone 0.12 wide), so they
// stay straight in any rectilinear view.
cv::Vec3d chart_colour(double y, double z);

// What the fisheye camera records of the chart: CV_8UC3 (or CV_16UC3 with bits > 8, values in the low `bits`)
// ground truth, 2x2 supersampled; rays that miss the chart (more than ~87 degrees off axis) or lie outside the
// lens's field of view are black. The inverse lens model is solved numerically for every model.
cv::Mat render_fisheye(const Lens& lens, int bits = 8);

// Angle off the optical axis for a fisheye radius in pixels (inverse of Lens::radius); nullopt beyond the FOV.
std::optional<double> lens_theta(const Lens& lens, double radius_px);

}  // namespace bs::vision
