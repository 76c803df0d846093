// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The fast path of BenchScope's own demosaics (bilinear, Malvar-He-Cutler), which demosaic() runs: rows in
// parallel stripes on OpenCV's thread pool, each row's interior with Highway SIMD for the best instruction set
// this CPU has (chosen at run time), its two border columns at each side with the scalar definition. It equals
// demosaic_reference() pixel for pixel (tests/core/vision/demosaic/test_bayer.cpp compares them).
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "vision/demosaic/bayer.h"

namespace bs::vision {

// raw: CV_8UC1 or CV_16UC1, at least 4x4 (demosaic() checks); out: allocated, CV_8UC3 or CV_16UC3, same size.
void demosaic_simd(const cv::Mat& raw, BayerPattern p, bool mhc, cv::Mat& out);

// Whether this build vectorises with Highway (bayer_simd.cpp); without it (no Highway >= 1.0 at configure time, or
// -DBENCHSCOPE_HIGHWAY=OFF) the fast path is the scalar definition in row stripes (bayer_portable.cpp).
bool demosaic_simd_uses_highway();

// The instruction set demosaic_simd() runs on this CPU, as Highway names it ("AVX2", "AVX3", "NEON", "SVE2", ...),
// or "portable" in a build without Highway.
const char* demosaic_simd_target();

// For tests, which compare every compiled copy with the reference: the instruction sets this binary has a copy
// for and this CPU runs, best first; and pinning demosaic_simd() to one of them ("" = back to the best). Changes
// process-wide state: not while another thread demosaics. Throws std::invalid_argument for an unknown name.
std::vector<std::string> demosaic_simd_targets();
void demosaic_simd_pin_target(const std::string& name);

}  // namespace bs::vision
