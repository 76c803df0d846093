// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The preprocessing stage on a CUDA GPU: the fused demosaic (bilinear) + reprojection kernel (cuda/fused_cuda.cu),
// bit-identical to the CPU's fused path. Compiled when CMake finds nvcc; used when the runtime sees a GPU.
#include <memory>
#include <string>

#include "vision/demosaic/bayer.h"
#include "vision/lens/lens.h"
#include "vision/pipeline/pipeline.h"

namespace bs::vision {

namespace cuda {
class FusedCuda;
}

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

// The same kernel in its three steps, for `bench vision`: the mosaic's upload, the kernel alone and the BGR
// download timed apart, and the kernel's device time (CUDA events). Throws as make_cuda_preprocessor.
class CudaFusedSteps {
 public:
  CudaFusedSteps(const Lens& lens, const View& view, BayerPattern pattern);
  ~CudaFusedSteps();
  CudaFusedSteps(const CudaFusedSteps&) = delete;
  CudaFusedSteps& operator=(const CudaFusedSteps&) = delete;
  const std::string& device() const { return device_; }
  void upload(const cv::Mat& mosaic);   // CV_8UC1 of the lens's size (std::invalid_argument otherwise)
  void compute();                       // the kernel on the uploaded mosaic, blocking
  void download(cv::Mat& bgr);          // CV_8UC3 of the view's size
  double kernel_seconds(int launches);  // device time per launch of `launches` back-to-back kernels
  double kernel_bytes() const;          // what one kernel moves at the least (map, mosaic, BGR)

 private:
  std::shared_ptr<cuda::FusedCuda> kernel_;  // shared_ptr: its deleter is bound where FusedCuda is complete
  std::string device_;
  // Read only where the build has CUDA (cuda_preprocess.cpp). cv::Size, not ints: clang's -Wunused-private-field
  // (the build without CUDA) passes over class types, and GCC ignores [[maybe_unused]] on members with a warning.
  cv::Size source_size_, out_size_;
};

}  // namespace bs::vision
