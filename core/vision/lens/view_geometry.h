// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Geometry linking the fisheye image and the rectilinear view, for inspectors and overlays: the inverse of
// source_of() (fisheye pixel -> output pixel), the image circle, and the outline of the view's field of view as
// seen in the fisheye image.
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "vision/lens/lens.h"

namespace bs::vision {

// The output pixel (x, y) whose ray lands on fisheye pixel (fx, fy); nullopt when that fisheye point lies outside
// the lens's field of view, behind the view's image plane, or outside the output image. Inverse of source_of():
// source_of(output_of(p)) == p up to the numerical inversion of the lens model (~1e-9 px).
std::optional<cv::Point2d> output_of(const Lens& lens, const View& view, double fx, double fy);

// The image circle the lens model predicts: centre and radius (pixels) of its field of view, fov_deg / 2 off the
// axis. Named apart from circle_detect.h's ImageCircle (the circle found in a frame): two structs of one name in
// one namespace are one type to the linker (an ODR violation UBSan caught as a garbage bool).
struct LensCircle {
  cv::Point2d centre;
  double radius = 0;
};
std::optional<LensCircle> image_circle(const Lens& lens);

// The border of the output image mapped into the fisheye image: a closed polyline, `per_edge` points per edge,
// leaving out border points that have no source (outside the lens's field of view).
std::vector<cv::Point2d> view_outline(const Lens& lens, const View& view, int per_edge = 64);

}  // namespace bs::vision
