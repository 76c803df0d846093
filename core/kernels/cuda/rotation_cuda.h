// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Host interface of the CUDA rotation kernels (rotation_cuda.cu). Plain C++: callers need no CUDA headers.
#include <cstdint>
#include <string>
#include <vector>

#include "util/cancel.h"

namespace bs::kernels::cuda {

struct DeviceInfo {
  int index = 0;
  std::string name;
  int multiprocessors = 0;
  int clock_khz = 0;
  int cc_major = 0, cc_minor = 0;
  int fp32_lanes_per_sm = 0;  // from the compute capability (64 or 128)
};

// Devices the CUDA runtime sees; empty (not an error) when there is no driver or no GPU. `why_none` says why.
std::vector<DeviceInfo> devices(std::string* why_none = nullptr);

// Times one point: W workers rotating D points N times. paper: one thread per worker, float/float2/float4 for
// D = 1, 2, 4; otherwise "float4x4": four independent float4 chains (16 points) per thread. Launches are split
// into ~40 ms chunks so a cancel is seen between them. The caller checks the problem size (check_problem_size).
double run_point(int device, int dims, std::int64_t iterations, std::int64_t workers, bool paper,
                 std::vector<float>& outputs, const CancelToken& cancel);

}  // namespace bs::kernels::cuda
