// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensors/nvml.h"

#include <dlfcn.h>

namespace bs::sensors {
namespace {

// The few NVML entry points used, with the C signatures of nvml.h (which is not needed to build).
using nvmlReturn_t = int;
using nvmlDevice_t = struct nvmlDevice_st*;
constexpr nvmlReturn_t kSuccess = 0;
constexpr nvmlReturn_t kNotSupported = 3;
constexpr nvmlReturn_t kNoPermission = 4;

struct NvmlLibrary {
  void* handle = nullptr;
  nvmlReturn_t (*init)() = nullptr;
  nvmlReturn_t (*shutdown)() = nullptr;
  nvmlReturn_t (*count)(unsigned*) = nullptr;
  nvmlReturn_t (*by_index)(unsigned, nvmlDevice_t*) = nullptr;
  nvmlReturn_t (*name)(nvmlDevice_t, char*, unsigned) = nullptr;
  nvmlReturn_t (*power)(nvmlDevice_t, unsigned*) = nullptr;
  const char* (*error_string)(nvmlReturn_t) = nullptr;
  bool initialised = false;

  ~NvmlLibrary() {
    if (initialised && shutdown) shutdown();
    if (handle) dlclose(handle);
  }
  std::string error(nvmlReturn_t r) const {
    const char* text = error_string ? error_string(r) : nullptr;
    return (text ? std::string(text) : "NVML error") + " (" + std::to_string(r) + ")";
  }
};

template <class F>
bool bind(void* handle, const char* symbol, F& fn) {
  fn = reinterpret_cast<F>(dlsym(handle, symbol));
  return fn != nullptr;
}

class NvmlSensor final : public Sensor {
 public:
  NvmlSensor(std::shared_ptr<NvmlLibrary> lib, nvmlDevice_t device, unsigned index, const std::string& library)
      : lib_(std::move(lib)), device_(device) {
    char name[96] = {};
    if (lib_->name(device_, name, sizeof name) != kSuccess) name[0] = '\0';
    info_.id = "nvml:" + std::to_string(index);
    info_.kind = SensorKind::Nvml;
    info_.label = name[0] ? name : "GPU " + std::to_string(index);
    info_.device = "GPU " + std::to_string(index);
    info_.source = library + " nvmlDeviceGetPowerUsage";
    info_.quantity = SensorQuantity::Power;
    info_.unit = "mW (NVML)";
    // The GPU board's own power: the total of that GPU, not of the computer.
    info_.board_total = false;
    unsigned mw = 0;
    const nvmlReturn_t r = lib_->power(device_, &mw);
    if (r == kSuccess) {
      info_.readable = true;
    } else if (r == kNotSupported) {
      info_.reason = "NotSupported: this GPU reports no power through NVML (on a Jetson, read the INA3221 rails)";
    } else if (r == kNoPermission) {
      info_.reason = "NoPermission: " + lib_->error(r);
    } else {
      info_.reason = lib_->error(r);
    }
  }
  std::optional<double> read() override {
    unsigned mw = 0;
    if (lib_->power(device_, &mw) != kSuccess) return std::nullopt;
    return mw * 1e-3;
  }

 private:
  std::shared_ptr<NvmlLibrary> lib_;
  nvmlDevice_t device_;
};

}  // namespace

NvmlProbe find_nvml(const std::string& library) {
  NvmlProbe probe;
  auto lib = std::make_shared<NvmlLibrary>();
  lib->handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!lib->handle) {
    probe.problem = library + " not found (no NVIDIA driver)";
    return probe;
  }
  if (!bind(lib->handle, "nvmlInit_v2", lib->init) || !bind(lib->handle, "nvmlShutdown", lib->shutdown) ||
      !bind(lib->handle, "nvmlDeviceGetCount_v2", lib->count) ||
      !bind(lib->handle, "nvmlDeviceGetHandleByIndex_v2", lib->by_index) ||
      !bind(lib->handle, "nvmlDeviceGetName", lib->name) || !bind(lib->handle, "nvmlDeviceGetPowerUsage", lib->power)) {
    probe.problem = library + " lacks an NVML function BenchScope needs (driver too old?)";
    return probe;
  }
  bind(lib->handle, "nvmlErrorString", lib->error_string);  // optional: only for messages
  if (const nvmlReturn_t r = lib->init(); r != kSuccess) {
    probe.problem = "nvmlInit failed: " + lib->error(r);
    return probe;
  }
  lib->initialised = true;
  unsigned n = 0;
  if (const nvmlReturn_t r = lib->count(&n); r != kSuccess) {
    probe.problem = "nvmlDeviceGetCount failed: " + lib->error(r);
    return probe;
  }
  if (n == 0) probe.problem = "NVML found no GPU";
  for (unsigned i = 0; i < n && i < 64; ++i) {
    nvmlDevice_t device = nullptr;
    if (lib->by_index(i, &device) != kSuccess) continue;
    probe.sensors.push_back(std::make_unique<NvmlSensor>(lib, device, i, library));
  }
  return probe;
}

}  // namespace bs::sensors
