// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The preprocessing stage on an OpenCL device (the paper ran it in OpenCL on the NUC's GPU): bilinear demosaic of
// the whole frame, then the reprojection through the lens's lookup table, as two kernels on one queue. Same
// arithmetic as the CPU path (demosaic in integers rounded half up; sampling at OpenCV's 1/32-pixel grid, zero
// outside the source), so the two agree within one grey level (the CPU's remap rounds fixed-point weights).
#include <memory>
#include <string>

#include "vision/demosaic/bayer.h"
#include "vision/lens/lens.h"
#include "vision/pipeline/pipeline.h"

namespace bs::vision {

struct OpenClPreprocessorInfo {
  std::string device;  // "pthread-cpu-haswell (Portable Computing Language)" on PoCL
};

// The first OpenCL device (GPU preferred). Throws std::runtime_error naming the failing OpenCL call when there is
// no platform/device or the program does not build; std::invalid_argument for an invalid lens/view.
// The returned Preprocessor takes CV_8UC1 mosaics of the lens's size and is safe to call from one thread at a time
// per copy (calls are serialised inside).
Preprocessor make_opencl_preprocessor(const Lens& lens, const View& view, BayerPattern pattern,
                                      OpenClPreprocessorInfo* info = nullptr);

}  // namespace bs::vision
