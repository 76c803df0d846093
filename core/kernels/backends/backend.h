// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A place the rotation kernel can run: its identity (stored in every run's provenance), its theoretical peak, and
// how to time one sweep point. Backends are plain values so a sweep, the CLI and the GUI treat them alike.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "kernels/ceilings/ceilings.h"
#include "kernels/cpu/cpu_info.h"
#include "model/flops_run.h"
#include "util/cancel.h"

namespace bs::kernels {

struct Backend {
  std::string id;           // "cpu-simd", "cpu-scalar", "opencl:N", "cuda:N"
  std::string label;        // FlopsRun::backend, e.g. "CPU SIMD (AVX-512)"
  std::string device_name;  // FlopsRun::device
  DeviceKind kind = DeviceKind::Cpu;
  std::vector<Variant> variants;
  // FlopsRun::variant of the throughput variant: "throughput" (CPU), "float16x4" (OpenCL), "float4x4" (CUDA).
  std::string throughput_label = "throughput";
  std::vector<int> paper_dims;  // D values the paper kernel has a vector type for (OpenCL, CUDA: 1, 2, 4); empty: any
  double theoretical_peak_flops = 0;  // 0 when unknown
  std::string details;                // properties shown to the user ("2 threads, 2.68 GHz measured, ...")
  // Times one point: W workers, each rotating D points N times; fills one output per worker. Polls `cancel`
  // between chunks of work (~40 ms apart, see StepChunker) and throws Cancelled; std::invalid_argument for sizes
  // the backend cannot run (check_problem_size, or a D the paper kernel has no vector type for).
  std::function<double(const RotationParams&, std::int64_t workers, Variant, std::vector<float>& outputs,
                       const CancelToken& cancel)>
      run_point;
  // Memory bandwidth (roofline's memory ceiling): one STREAM triad pass a[i] = b[i] + q * c[i] over `elements`
  // floats in arrays the backend allocated beforehand (12 bytes moved per element), verified, and its seconds.
  // Empty for backends without one (CUDA for now). Throws Cancelled between passes, std::invalid_argument on a
  // size the device cannot hold.
  std::function<double(std::size_t elements, const CancelToken& cancel)> run_triad;
  // The device's empirical-ceiling micro-kernels (ceilings.h), sized by the spec; empty for the CPU backends,
  // whose ceilings measure_ceilings(CpuInfo) measures. Throws std::runtime_error when the device cannot run them.
  std::function<std::unique_ptr<DeviceCeilingKernels>(const CeilingSpec&)> ceiling_kernels;

  // The label stored in FlopsRun::variant: "paper" or throughput_label.
  std::string variant_label(Variant v) const { return v == Variant::Paper ? "paper" : throughput_label; }
};

// The CPU backends: the scalar reference (single thread, exact paper semantics) and SIMD + OpenMP.
std::vector<Backend> cpu_backends(const CpuInfo& cpu);

// Provenance of a run measured here: origin measured, host, CPU model, the OpenCL/CUDA device as gpu_model, OS,
// compiler, tool, UTC date, and a note naming the backend's properties (driver version for OpenCL), the ISA, the
// measured clock and the build flags.
Provenance measured_provenance(const CpuInfo& cpu, const Backend& backend);

}  // namespace bs::kernels

namespace bs::kernels {

// Every backend this machine has, in order: CPU SIMD, CPU scalar, each OpenCL device ("opencl:N"), each CUDA device
// ("cuda:N").
std::vector<Backend> available_backends(const CpuInfo& cpu);

// Backends this build knows but cannot run here, each with the reason: "cuda: no CUDA device (...)", "cuda: this
// build has no CUDA (nvcc was not found)", "opencl: no OpenCL platform installed".
std::vector<std::string> unavailable_backends();

// Finds a backend by id; "cpu" means "cpu-simd", "opencl" and "cuda" the first device of each ("opencl:0").
// Throws std::invalid_argument listing the available ids.
const Backend& find_backend(const std::vector<Backend>& backends, const std::string& id);

}  // namespace bs::kernels
