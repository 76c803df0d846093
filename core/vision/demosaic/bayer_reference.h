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
// The reference itself into an allocated `out` (CV_8UC3 / CV_16UC3, raw's size; raw checked): what
// demosaic_reference() returns, and the whole fast path of a build without Highway (bayer_portable.cpp).
void demosaic_reference_into(const cv::Mat& raw, BayerPattern p, bool mhc, cv::Mat& out);
}  // namespace detail

}  // namespace bs::vision
