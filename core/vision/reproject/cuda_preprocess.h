// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The preprocessing stage on a CUDA GPU: the fused demosaic (bilinear) + reprojection kernel (cuda/fused_cuda.cu),
// bit-identical to the CPU's fused path. Compiled when CMake finds nvcc; used when the runtime sees a GPU.
#include <string>

#include "vision/demosaic/bayer.h"
#include "vision/lens/lens.h"
#include "vision/pipeline/pipeline.h"

namespace bs::vision {

// True when this build has the CUDA kernel (nvcc was found at configure time).
bool cuda_preprocessing_compiled();

// Empty when the CUDA path can run here; otherwise why not ("built without CUDA (nvcc not found)", "the CUDA
// runtime sees no GPU", ...). `device` receives the GPU's name when it can.
std::string cuda_preprocessing_unavailable(std::string* device = nullptr);

struct CudaPreprocessorInfo {
  std::string device;  // "NVIDIA H100 80GB HBM3 (cc 9.0)"
};

// Throws std::runtime_error with cuda_preprocessing_unavailable()'s reason when the path cannot run, or naming the
// failing CUDA call; std::invalid_argument for an invalid lens/view. The returned Preprocessor takes CV_8UC1
// mosaics of the lens's size; calls are serialised inside (one device buffer set per preprocessor).
Preprocessor make_cuda_preprocessor(const Lens& lens, const View& view, BayerPattern pattern,
                                    CudaPreprocessorInfo* info = nullptr);

}  // namespace bs::vision
