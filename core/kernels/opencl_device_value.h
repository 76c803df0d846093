// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A fixed-size OpenCL device property (cl_uint, cl_ulong, cl_device_type, ...), read the same way by the OpenCL
// rotation backend and the OpenCL ceilings. The includer defines CL_TARGET_OPENCL_VERSION before any OpenCL header.
#include <CL/cl.h>

namespace bs::kernels {

// Zero-initialised, so a property the device does not report reads as 0.
template <class T>
T device_value(cl_device_id d, cl_device_info what) {
  T v{};
  clGetDeviceInfo(d, what, sizeof v, &v, nullptr);
  return v;
}

}  // namespace bs::kernels
