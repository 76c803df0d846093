// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/reproject/cuda_preprocess.h"

#include <memory>
#include <mutex>
#include <stdexcept>

#if BENCHSCOPE_VISION_CUDA
#include "vision/cuda/fused_cuda.h"
#endif

namespace bs::vision {

bool cuda_preprocessing_compiled() { return BENCHSCOPE_VISION_CUDA != 0; }

std::string cuda_preprocessing_unavailable(std::string* device) {
#if BENCHSCOPE_VISION_CUDA
  const cuda::DeviceStatus s = cuda::device_status();
  if (s.available && device) *device = s.name;
  return s.available ? std::string() : s.why;
#else
  (void)device;
  return "this build has no CUDA path (nvcc was not found when it was configured)";
#endif
}

Preprocessor make_cuda_preprocessor(const Lens& lens, const View& view, BayerPattern pattern,
                                    CudaPreprocessorInfo* info) {
  const ReprojectionLut lut(lens, view);  // validates lens and view first: a bad lens is reported as such
  if (const std::string why = cuda_preprocessing_unavailable(); !why.empty())
    throw std::runtime_error("CUDA preprocessing: " + why);
#if BENCHSCOPE_VISION_CUDA
  const cv::Mat map = lut.map().isContinuous() ? lut.map() : lut.map().clone();
  const cv::Size source = lut.source_size(), out_size = map.size();
  int layout[4];
  for (int k = 0; k < 4; ++k) layout[k] = bayer_channel(pattern, k >> 1, k & 1);
  const std::uint8_t fill[3] = {0, 0, 0};
  struct State {
    std::unique_ptr<cuda::FusedCuda> kernel;
    std::mutex mutex;
  };
  auto st = std::make_shared<State>();
  st->kernel = std::make_unique<cuda::FusedCuda>(map.ptr<float>(), out_size.width, out_size.height, source.width,
                                                 source.height, layout, fill);
  if (info) info->device = st->kernel->device_name();
  return [st, source, out_size](const cv::Mat& mosaic) -> cv::Mat {
    if (mosaic.type() != CV_8UC1 || mosaic.size() != source)
      throw std::invalid_argument("CUDA preprocessing needs an 8-bit mosaic of " + std::to_string(source.width) + "x" +
                                  std::to_string(source.height));
    cv::Mat out(out_size, CV_8UC3);
    const std::lock_guard lock(st->mutex);
    st->kernel->run(mosaic.data, mosaic.step[0], out.data);
    return out;
  };
#else
  (void)lut, (void)pattern, (void)info;
  return {};  // not reached: cuda_preprocessing_unavailable() always has a reason in a build without CUDA
#endif
}

CudaFusedSteps::CudaFusedSteps(const Lens& lens, const View& view, BayerPattern pattern) {
  const ReprojectionLut lut(lens, view);
  if (const std::string why = cuda_preprocessing_unavailable(); !why.empty())
    throw std::runtime_error("CUDA preprocessing: " + why);
#if BENCHSCOPE_VISION_CUDA
  const cv::Mat map = lut.map().isContinuous() ? lut.map() : lut.map().clone();
  const cv::Size source = lut.source_size();
  int layout[4];
  for (int k = 0; k < 4; ++k) layout[k] = bayer_channel(pattern, k >> 1, k & 1);
  const std::uint8_t fill[3] = {0, 0, 0};
  source_size_ = cv::Size(source.width, source.height);
  out_size_ = cv::Size(map.cols, map.rows);
  kernel_ = std::make_shared<cuda::FusedCuda>(map.ptr<float>(), map.cols, map.rows, source.width, source.height, layout,
                                              fill);
  device_ = kernel_->device_name();
#else
  (void)pattern;
#endif
}

CudaFusedSteps::~CudaFusedSteps() = default;

#if BENCHSCOPE_VISION_CUDA
void CudaFusedSteps::upload(const cv::Mat& mosaic) {
  if (mosaic.type() != CV_8UC1 || mosaic.size() != source_size_)
    throw std::invalid_argument("CUDA preprocessing needs an 8-bit mosaic of " + std::to_string(source_size_.width) +
                                "x" + std::to_string(source_size_.height));
  kernel_->upload(mosaic.data, mosaic.step[0]);
}
void CudaFusedSteps::compute() { kernel_->compute(); }
void CudaFusedSteps::download(cv::Mat& bgr) {
  bgr.create(out_size_, CV_8UC3);  // continuous: download writes width * 3 bytes per row
  kernel_->download(bgr.data);
}
double CudaFusedSteps::kernel_seconds(int launches) { return kernel_->kernel_seconds(launches); }
double CudaFusedSteps::kernel_bytes() const { return kernel_->kernel_bytes(); }
#else
// Not reached: the constructor throws in a build without CUDA.
void CudaFusedSteps::upload(const cv::Mat&) {}
void CudaFusedSteps::compute() {}
void CudaFusedSteps::download(cv::Mat&) {}
double CudaFusedSteps::kernel_seconds(int) { return 0; }
double CudaFusedSteps::kernel_bytes() const { return 0; }
#endif

}  // namespace bs::vision
