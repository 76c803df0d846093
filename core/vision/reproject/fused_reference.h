// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The fused demosaic + reprojection one pixel at a time through fused_pixel.h, the code the CUDA kernel runs.
// Slow (single thread, no tables): it exists so that the GPU kernel's arithmetic is checked against FusedTable on
// every machine, and so the CUDA path has a CPU twin to compare with.
#include <opencv2/core.hpp>

#include "vision/demosaic/bayer.h"
#include "vision/reproject/fused_pixel.h"

namespace bs::vision {

// The fused_pixel::Mosaic view of an 8-bit mosaic (no copy: `mosaic` must outlive it).
fused_pixel::Mosaic fused_pixel_mosaic(const cv::Mat& mosaic, BayerPattern pattern);

// map: CV_32FC2 lookup table (negative: no source); mosaic: CV_8UC1. Returns CV_8UC3 BGR of the map's size.
// Throws std::invalid_argument for other types.
cv::Mat fused_reference(const cv::Mat& map, const cv::Mat& mosaic, BayerPattern pattern,
                        const cv::Vec3b& fill = {0, 0, 0});

}  // namespace bs::vision
