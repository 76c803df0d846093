// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What `bench dnn` needs from cv::dnn, without the command line: the network's FLOPs, the targets OpenCV's dnn
// offers on this machine (and why one is not available), and the timed forward passes.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/dnn.hpp>

#include "util/cancel.h"

namespace bs::vision {

// FLOPs of one forward pass for an input of `input_shape` (N, C, H, W). `opencv` is Net::getFLOPS as OpenCV 4.6
// counts it; that count treats every grouped (depthwise) convolution as a full one, C_in times too large, so
// `counted` recounts each Convolution layer from its weight blob (2 x multiply-adds + bias adds) and takes
// OpenCV's figure for every other layer. `counted` is the one to compare with published counts.
struct DnnFlops {
  std::int64_t opencv = 0, counted = 0;
};
DnnFlops count_flops(const cv::dnn::Net& net, const cv::dnn::MatShape& input_shape);

// One (backend, target) pair of cv::dnn: "cpu" (OpenCV's own CPU implementation), "opencl" (its OpenCL kernels)
// or "cuda" (its CUDA backend). `available` false says why in `why_not`.
struct DnnTarget {
  std::string id;
  int backend = 0, target = 0;
  std::string device;  // what runs it: the CPU, the OpenCL device's name
  bool available = false;
  std::string why_not;
};
std::vector<DnnTarget> dnn_targets();  // cpu, opencl, cuda, in that order
// Throws std::invalid_argument for an id that is not cpu, opencl or cuda.
DnnTarget dnn_target(const std::string& id);

// Forward passes of `blob` through `net` on `t`: `warmup` passes not timed (the first allocates and, on OpenCL,
// compiles kernels), then `runs` timed ones (steady_clock, seconds each). `on_timed_start` runs once just before
// the first timed pass (to open a power phase). Stops early, returning what was timed, when `cancel` is set.
std::vector<double> time_forward(cv::dnn::Net& net, const DnnTarget& t, const cv::Mat& blob, int warmup, int runs,
                                 const CancelToken& cancel, const std::function<void()>& on_timed_start = {});

}  // namespace bs::vision
