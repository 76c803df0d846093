// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// NVIDIA GPUs' board power through NVML (nvmlDeviceGetPowerUsage, milliwatts). libnvidia-ml.so.1 comes with the
// driver, not with a toolkit, so it is loaded at run time with dlopen: BenchScope builds and runs without it.
// A GPU whose driver answers NVML_ERROR_NOT_SUPPORTED (every Jetson: its power is on the INA3221) is listed
// as not readable, with that reason.
#include <memory>
#include <string>
#include <vector>

#include "sensors/sensor.h"

namespace bs::sensors {

struct NvmlProbe {
  std::vector<std::unique_ptr<Sensor>> sensors;
  std::string problem;  // why no GPU was listed: library missing, nvmlInit failed, no device; empty otherwise
};

// `library`: the file dlopen looks for (tests pass a stand-in library).
NvmlProbe find_nvml(const std::string& library = "libnvidia-ml.so.1");

}  // namespace bs::sensors
