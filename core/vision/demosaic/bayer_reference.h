// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The reference definition of BenchScope's own demosaics: plain scalar code, one pixel at a time
// (bayer_pixel.h). demosaic() runs the fast path (bayer_simd.h); tests compare the two pixel for pixel.
#include <opencv2/core.hpp>

#include "vision/demosaic/bayer.h"

namespace bs::vision {

// Same contract as demosaic() for DemosaicMethod::Bilinear and MalvarHeCutler; throws std::invalid_argument for
// the OpenCV methods.
cv::Mat demosaic_reference(const cv::Mat& raw, BayerPattern p, DemosaicMethod m);

namespace detail {
// The checks demosaic() and demosaic_reference() share: type and minimum size, naming the reason.
void check_demosaic_input(const cv::Mat& raw);
}  // namespace detail

}  // namespace bs::vision
