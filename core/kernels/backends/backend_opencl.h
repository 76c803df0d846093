// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <vector>

#include "kernels/backends/backend.h"

namespace bs::kernels {

// One Backend per OpenCL device the ICD loader lists (PoCL gives a CPU device on every machine). Variants:
// "paper" (one work-item per worker, float / float2 / float4 for D = 1, 2, 4, as in the paper) and the throughput
// variant "float16x4" (4 independent float16 chains = 64 points per work-item). Returns none when no platform is
// installed.
std::vector<Backend> opencl_backends(const CpuInfo& cpu);

// Why there is no OpenCL device ("no OpenCL platform installed (...)", "no device on any platform"); empty when
// there is one.
std::string opencl_unavailable_reason();

}  // namespace bs::kernels
