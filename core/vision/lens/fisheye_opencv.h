// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// BenchScope's lens (vision/lens.h) as OpenCV's fisheye camera (cv::fisheye: K, D) and back.
//
// Both are the same Kannala-Brandt polynomial r = f * theta (1 + k1 theta^2 + k2 theta^4 + k3 theta^6 + k4 theta^8),
// and both put pixel centres at integer coordinates with (0, 0) the centre of the top-left pixel, so cx, cy carry
// over unchanged. What differs: BenchScope has one focal length (r_pp = 1 / f, radians per pixel) and describes
// rays in its screen-centred frame (x forward, y right, z up), OpenCV has fx and fy and a camera frame with x right,
// y down, z forward. A BenchScope ray (x, y, z) is the OpenCV point (y, -z, x).
#include <array>
#include <optional>

#include <opencv2/core.hpp>

#include "vision/lens/lens.h"

namespace bs::vision {

struct OpenCvFisheye {
  double fx = 0, fy = 0;  // focal lengths, pixels
  double cx = 0, cy = 0;  // principal point, pixels (OpenCV: +y down, (0, 0) = centre of the top-left pixel)
  std::array<double, 4> k{};
  cv::Matx33d camera_matrix() const;
  cv::Vec4d distortion() const;
  static OpenCvFisheye from(const cv::Matx33d& K, const cv::Vec4d& D);
};

// Equidistant (k = 0) or Kannala-Brandt lenses; other models are not OpenCV fisheye cameras (throws
// std::invalid_argument naming the model).
OpenCvFisheye to_opencv_fisheye(const Lens& lens);

// The lens of an OpenCV fisheye camera: r_pp = 1 / sqrt(fx fy) (the geometric mean keeps the imaged solid angle;
// checkerboard calibration refits with fx = fy first, see checkerboard_calibration.h, so that the mean is no
// silent compromise), cx, cy and k as they are, type Kannala-Brandt (or equidistant when every k is zero).
// Size, field of view and calibration record come from `base`.
Lens lens_from_opencv_fisheye(const OpenCvFisheye& cam, const Lens& base);

// Where a point in OpenCV's camera frame (x right, y down, z forward; any unit) lands in the source image under
// BenchScope's lens model, or nullopt when the model cannot image it (beyond the lens's field of view).
std::optional<cv::Point2d> project_camera_point(const Lens& lens, const cv::Vec3d& point);

// The unit ray, in OpenCV's camera frame, that lands on source pixel `px`; nullopt outside the image circle.
std::optional<cv::Vec3d> camera_ray(const Lens& lens, cv::Point2d px);

}  // namespace bs::vision
