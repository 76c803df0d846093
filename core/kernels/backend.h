// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A place the rotation kernel can run: its identity (stored in every run's provenance), its theoretical peak, and
// how to time one sweep point. Backends are plain values so a sweep, the CLI and the GUI treat them alike.
#include <functional>
#include <string>
#include <vector>

#include "kernels/cpu_info.h"
#include "model/flops_run.h"
#include "util/cancel.h"

namespace bs::kernels {

struct Backend {
  std::string id;           // "cpu-scalar", "cpu-simd"
  std::string label;        // FlopsRun::backend, e.g. "CPU SIMD (AVX-512)"
  std::string device_name;  // FlopsRun::device
  DeviceKind kind = DeviceKind::Cpu;
  std::vector<Variant> variants;
  double theoretical_peak_flops = 0;  // 0 when unknown
  std::string details;                // properties shown to the user ("2 threads, 2.68 GHz measured, ...")
  // Times one point: W workers, each rotating D points N times; fills one output per worker. Polls `cancel`
  // between chunks of work (at most ~20 ms apart) and throws Cancelled.
  std::function<double(const RotationParams&, std::int64_t workers, Variant, std::vector<float>& outputs,
                       const CancelToken& cancel)>
      run_point;
};

// The CPU backends: the scalar reference (single thread, exact paper semantics) and SIMD + OpenMP.
std::vector<Backend> cpu_backends(const CpuInfo& cpu);

// Provenance of a run measured here, naming the backend, ISA and measured clock.
Provenance measured_provenance(const CpuInfo& cpu, const Backend& backend);

}  // namespace bs::kernels

namespace bs::kernels {

// Every backend this machine has, in order: CPU SIMD, CPU scalar, then each OpenCL device ("opencl:N").
std::vector<Backend> available_backends(const CpuInfo& cpu);

// Finds a backend by id; "cpu" means "cpu-simd", "opencl" and "cuda" the first device of each ("opencl:0").
// Throws std::invalid_argument listing the available ids.
const Backend& find_backend(const std::vector<Backend>& backends, const std::string& id);

}  // namespace bs::kernels
