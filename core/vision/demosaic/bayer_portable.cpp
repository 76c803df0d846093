// SPDX-License-Identifier: GPL-3.0-or-later
// The demosaic's fast path in a build without Highway (-DBENCHSCOPE_HIGHWAY=OFF, or no Highway >= 1.0 found, as on
// Ubuntu 22.04 / JetPack 6, whose libhwy-dev is 0.15): the scalar definition itself, in row stripes on OpenCV's
// pool, written so the compiler may vectorise its inner loops. Equal to demosaic_reference() by construction;
// bayer_simd.cpp is the Highway path with the same interface (CMakeLists.txt compiles one of the two).
#include <stdexcept>
#include <string>
#include <vector>

#include "vision/demosaic/bayer_reference.h"
#include "vision/demosaic/bayer_simd.h"

namespace bs::vision {

namespace {
constexpr const char* kPortable = "portable";
}  // namespace

void demosaic_simd(const cv::Mat& raw, BayerPattern p, bool mhc, cv::Mat& out) {
  detail::demosaic_reference_into(raw, p, mhc, out);
}

bool demosaic_simd_uses_highway() { return false; }

const char* demosaic_simd_target() { return kPortable; }

std::vector<std::string> demosaic_simd_targets() { return {kPortable}; }

void demosaic_simd_pin_target(const std::string& name) {
  if (name.empty() || name == kPortable) return;
  throw std::invalid_argument("demosaic_simd_pin_target: '" + name +
                              "' is not an instruction set this build runs here (built without Highway: 'portable')");
}

}  // namespace bs::vision
