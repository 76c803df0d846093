// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A fast approximation of build_reprojection_map for live tuning: the exact lens maths runs only on a grid every
// `step` output pixels; the map in between is bilinear interpolation of that grid. The image-circle border is
// handled per pixel, not per cell:
//  - grid nodes are projected with the lens model continued past its field of view, so a cell straddling the
//    border still interpolates smoothly; each interpolated pixel is then kept only if its source lies within the
//    image-circle radius r(fov/2) and inside the source image, which is what the exact map tests;
//  - every cell's bilinear error is checked a posteriori at its centre and edge midpoints against the exact maths
//    (a grid of half cells); a cell off by more than 0.04 px there is interpolated on the half-cell grid instead
//    (a quarter of the error), or computed exactly, pixel by pixel, when even that would be off by more;
//  - cells touching a node where the model cannot be continued (rectilinear/orthographic at 90 degrees, rays
//    near the backward axis) are computed exactly, pixel by pixel; cells whose four nodes all lie well beyond
//    the field of view (margin max(15 deg, 3 cells)) are left empty.
// The error against the exact map is measured in tests/core/vision/reproject/test_fast_map.cpp (at most 0.04 px for the
// paper's lens and 150 degree view at step 8, across every model) and the speed by `benchscope-cli bench tuner`.
#include <opencv2/core.hpp>

#include "vision/lens/lens.h"

namespace bs::vision {

// Same layout as build_reprojection_map: CV_32FC2, (-1, -1) where there is no source. `step` (>= 1) is the largest
// grid spacing in output pixels; it is reduced so that a cell spans at most sqrt(0.5 r_pp) radians of view (the
// bilinear error grows as the square of that angle over r_pp), down to 1, the exact map.
cv::Mat build_reprojection_map_coarse(const Lens& lens, const View& view, int step = 8);
// The same into `map`, reusing its buffer when it already has the view's size and type: for a 1280x1024 view the
// page faults of a fresh 10 MB buffer cost more than the whole interpolation on this VM (bench tuner).
void build_reprojection_map_coarse(const Lens& lens, const View& view, cv::Mat& map, int step = 8);

}  // namespace bs::vision
