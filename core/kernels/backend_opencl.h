// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <vector>

#include "kernels/backend.h"

namespace bs::kernels {

// One Backend per OpenCL device the ICD loader lists (PoCL gives a CPU device on every machine). Variants:
// "paper" (one work-item per worker, float / float2 / float4 for D = 1, 2, 4, as in the paper) and "throughput"
// (float16 x 4 independent chains = 64 points per work-item). Returns none when no platform is installed.
std::vector<Backend> opencl_backends(const CpuInfo& cpu);

}  // namespace bs::kernels
