// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The empirical-ceiling micro-kernels (ceilings.h: FMA, rotation mix, device-memory copy) on one OpenCL device,
// with their own context and profiling queue; timed by OpenCL's event profiling (device time).
#include <memory>

#include "kernels/ceilings/ceilings.h"

typedef struct _cl_device_id* cl_device_id;  // as <CL/cl.h> declares it, so callers need no OpenCL headers

namespace bs::kernels {

// Builds the kernels and sizes them to spec.device_target_seconds; std::runtime_error naming the failing OpenCL
// call (with the build log when the program does not build).
std::unique_ptr<DeviceCeilingKernels> make_opencl_ceiling_kernels(cl_device_id device, const CeilingSpec& spec);

}  // namespace bs::kernels
