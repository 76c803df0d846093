// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where a ray of the synthetic room lands in the fisheye image: the forward lens model the vision tests place their
// expected points with (the room's corners, grid lines and picked points), one definition for all of them.
#include <optional>

#include <opencv2/core.hpp>

#include "vision/lens/fisheye_opencv.h"

namespace bs::test {

// `v` in BenchScope's ray space (x forward, y right, z up); nullopt beyond the FOV, on the lens axis, or closer
// than `margin_px` to the image's border (a test that reads the pixel a point rounds to keeps it a pixel inside).
inline std::optional<cv::Point2d> project_ray(const vision::Lens& lens, const cv::Vec3d& v, double margin_px = 0) {
  // BenchScope's ray space in OpenCV's camera frame (x right, y down, z forward).
  const auto p = vision::project_camera_point(lens, cv::Vec3d(v[1], -v[2], v[0]));
  if (!p || (v[1] == 0 && v[2] == 0)) return std::nullopt;
  if (p->x < margin_px || p->y < margin_px || p->x > lens.width - 1 - margin_px || p->y > lens.height - 1 - margin_px)
    return std::nullopt;
  return p;
}

}  // namespace bs::test
