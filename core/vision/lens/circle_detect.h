// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Auto-calibration from one frame: find the fisheye image circle (the lit disc the lens projects onto the sensor)
// and propose the principal point and r_pp that put the lens's field of view on that circle.
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "vision/lens/lens.h"

namespace bs::vision {

struct ImageCircle {
  cv::Point2d centre;   // source pixels
  double radius = 0;    // pixels
  double rms_px = 0;    // RMS distance of the edge points used from the fitted circle
  int edge_points = 0;  // edge points used (inliers of the robust fit)
  int rays = 0;         // rays that found an edge at all (the others ran into the sensor's border while still lit)
};

// Sub-pixel rim points along rays, then a robust circle fit, in two stages:
//  1. coarse: threshold (a fraction of the bright level, at least `min_level` of 255), largest region, its outer
//     contour off the image border, circle fit: only a start, often pixels off (dark objects at the rim bite in);
//  2. fine, twice: 720 rays from the current centre; along each the outermost transition from lit to the dark
//     outside (beyond which the ray stays dark up to the sensor's border: rays that leave the sensor while lit are
//     dropped, so the sensor's cut of the circle never counts), located sub-pixel where the profile crosses half
//     way between the local lit level and the dark level. Lit and dark are judged against the dark level and the
//     noise measured at the rays' outer ends, so vignetting and noise only change how many rays count. RANSAC over
//     3-point circles (1 px) rejects rim points where a dark object or line touches the rim (those transitions lie
//     inside the circle), then Gauss-Newton on the geometric distance over the inliers.
// Accepts 8/16-bit (any bits in 16), 1 or 3 channels. nullopt when no disc is found.
std::optional<ImageCircle> detect_image_circle(const cv::Mat& image, double min_level = 20);

// The lens with its principal point on the circle's centre and r_pp chosen so that a ray circle_fov/2 off the axis
// lands on the circle (for equidistant: r_pp = (circle_fov/2) / radius). circle_fov_deg <= 0 means the lens's FOV;
// give a smaller one when the lit disc ends before the lens's FOV does (a dark outer ring, a hood, a chart that
// ends). Model, k and FOV are kept; the calibration record says "circle-fit" with the fit's RMS and point count.
Lens propose_lens(const Lens& lens, const ImageCircle& circle, double circle_fov_deg = 0);

}  // namespace bs::vision
