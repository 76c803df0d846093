// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Bayer colour filter arrays: mosaicing (for ground truth) and demosaicing, 8- and 16-bit. Colour images are
// OpenCV's BGR order throughout.
#include <string>
#include <string_view>

#include <opencv2/core.hpp>

namespace bs::vision {

// Named by the 2x2 cell at the top-left: BGGR = blue at (0,0), green at (0,1) and (1,0), red at (1,1).
enum class BayerPattern { BGGR, RGGB, GRBG, GBRG };
std::string_view to_string(BayerPattern p);
BayerPattern bayer_pattern_from_string(std::string_view s);  // throws std::invalid_argument

enum class DemosaicMethod {
  Bilinear,         // ours: average of the nearest same-colour samples
  MalvarHeCutler,   // ours: gradient-corrected linear interpolation (Malvar, He, Cutler 2004), 5x5 kernels
  OpenCvBilinear,   // cv::cvtColor COLOR_Bayer*2BGR, as a reference
  OpenCvEdgeAware,  // cv::cvtColor COLOR_Bayer*2BGR_EA
  OpenCvVng,        // cv::cvtColor COLOR_Bayer*2BGR_VNG (8-bit only)
};
std::string_view to_string(DemosaicMethod m);
DemosaicMethod demosaic_method_from_string(
    std::string_view s);  // "bilinear", "mhc", "opencv", "opencv-ea", "opencv-vng"

// Which colour (0 = B, 1 = G, 2 = R) the sensor measures at (row, col).
int bayer_channel(BayerPattern p, int row, int col);

// Keeps, per pixel, the one channel the pattern measures: CV_8UC3/CV_16UC3 BGR -> CV_8UC1/CV_16UC1.
cv::Mat mosaic(const cv::Mat& bgr, BayerPattern p);

// CV_8UC1/CV_16UC1 mosaic -> CV_8UC3/CV_16UC3 BGR. Borders are handled by reflection. Throws std::invalid_argument
// for other types, sizes under 4x4, or VNG on 16-bit input. Our methods run the SIMD, multi-threaded path
// (bayer_simd.h), equal pixel for pixel to the scalar definition, demosaic_reference() (bayer_reference.h).
cv::Mat demosaic(const cv::Mat& raw, BayerPattern p, DemosaicMethod m);
// The same into `out`, reusing its buffer when it already has the size and type (as cv::cvtColor does), so a
// loop over frames allocates once.
void demosaic(const cv::Mat& raw, BayerPattern p, DemosaicMethod m, cv::Mat& out);

// Peak signal-to-noise ratio in dB over all channels, ignoring a border of `border` pixels (where methods differ
// only by their edge handling). Infinity for identical images.
double psnr(const cv::Mat& a, const cv::Mat& b, int border = 2);

}  // namespace bs::vision
