// SPDX-License-Identifier: GPL-3.0-or-later
#include <chrono>
#include <cstdio>
#include <string>

#include "kernels/backends/backend.h"
#include "kernels/ceilings/triad_cpu.h"
#include "kernels/step_chunker.h"
#include "util/host_clock.h"

namespace bs::kernels {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Advances the scalar reference N steps in chunks of ~40 ms, polling `cancel` before each; returns the seconds of
// all chunks.
double advance_in_chunks(ScalarRotation& state, const RotationParams& p, std::int64_t workers,
                         const CancelToken& cancel) {
  StepChunker chunks(p.iterations, workers * p.dims);
  const auto t0 = std::chrono::steady_clock::now();
  while (!chunks.done()) {
    cancel.throw_if_cancelled();
    const std::int64_t steps = chunks.next();
    const auto c0 = std::chrono::steady_clock::now();
    state.advance(steps);
    chunks.completed(steps, seconds_since(c0));
  }
  return seconds_since(t0);
}

double run_simd(const SimdTarget& target, const RotationParams& p, std::int64_t workers, Variant variant,
                std::vector<float>& outputs, const CancelToken& cancel) {
  SimdRotation state(target, variant, p, workers);
  const auto t0 = std::chrono::steady_clock::now();
  state.run(p.iterations, cancel);
  const double seconds = seconds_since(t0);
  outputs.assign(static_cast<std::size_t>(workers), 0.0f);
  state.outputs(outputs);
  return seconds;
}

double run_scalar(const RotationParams& p, std::int64_t workers, std::vector<float>& outputs,
                  const CancelToken& cancel) {
  ScalarRotation state(p, workers);
  const double seconds = advance_in_chunks(state, p, workers, cancel);
  outputs.assign(static_cast<std::size_t>(workers), 0.0f);
  state.outputs(outputs);
  return seconds;
}

// ARM: the core types the peak adds up, shown wherever the backend's details are (devices, the Kernel Runner).
std::string arm_cluster_details(const CpuInfo& cpu) {
  if (!cpu.arm) return {};
  std::string s = "; cores by type:";
  const char* sep = " ";
  for (const ArmCluster& c : cpu.arm->clusters) {
    char part[160];
    if (c.type)
      std::snprintf(part, sizeof part, "%s%dx %s (%d lanes x %d FMA unit%s, %.2f GHz %s)", sep, c.cores,
                    c.core_name.c_str(), c.type->fp32_lanes, c.type->fma_units, c.type->fma_units == 1 ? "" : "s",
                    c.clock_ghz, c.clock_source == "measured" ? "measured" : "max");
    else
      std::snprintf(part, sizeof part, "%s%dx %s", sep, c.cores, c.core_name.c_str());
    s += part;
    sep = " + ";
  }
  return s;
}

}  // namespace

std::vector<Backend> cpu_backends(const CpuInfo& cpu) {
  char details[256];
  std::snprintf(details, sizeof details,
                "%d threads, %.2f GHz measured, %s (%d lanes%s), %d FMA pipes assumed, %.0f flop/cycle/core",
                cpu.threads, cpu.clock_hz / 1e9, cpu.simd.name.c_str(), cpu.simd.lanes, cpu.simd.fma ? ", FMA" : "",
                cpu.fma_ports, cpu.flops_per_cycle);
  Backend simd;
  simd.id = "cpu-simd";
  simd.label = "CPU SIMD (" + cpu.simd.name + ")";
  simd.device_name = cpu.model;
  simd.variants = {Variant::Throughput, Variant::Paper};
  simd.theoretical_peak_flops = cpu.peak_flops;
  simd.details = details + arm_cluster_details(cpu);
  const SimdTarget target = cpu.simd;
  simd.run_point = [target](const RotationParams& p, std::int64_t w, Variant v, std::vector<float>& out,
                            const CancelToken& c) { return run_simd(target, p, w, v, out, c); };

  simd.run_triad = [](std::size_t n, const CancelToken& c) { return cpu_triad_seconds(n, true, c); };

  Backend scalar;
  scalar.id = "cpu-scalar";
  scalar.label = "CPU scalar (reference)";
  scalar.device_name = cpu.model;
  scalar.variants = {Variant::Paper};
  // One thread, one float per op and no FMA (ISO C++ does not contract c*x - s*y, and the file is built without
  // vectorisation): 4 mul + 2 add per point-step, the throughput bound when a worker's D points give enough
  // independent chains (D = 1 is latency-bound far below it).
  const double scalar_per_cycle = rotation_flops_per_cycle(1, false, cpu.fma_ports, cpu.separate_add_pipes);
  scalar.theoretical_peak_flops = cpu.clock_hz * scalar_per_cycle;
  std::snprintf(details, sizeof details,
                "1 thread, scalar float without FMA, the paper's exact semantics, "
                "%.2f GHz measured, %.0f flop/cycle",
                cpu.clock_hz / 1e9, scalar_per_cycle);
  scalar.details = details;
  scalar.run_point = [](const RotationParams& p, std::int64_t w, Variant, std::vector<float>& out,
                        const CancelToken& c) { return run_scalar(p, w, out, c); };
  scalar.run_triad = [](std::size_t n, const CancelToken& c) { return cpu_triad_seconds(n, false, c); };
  return {simd, scalar};
}

Provenance measured_provenance(const CpuInfo& cpu, const Backend& backend) {
  Provenance p;
  p.origin = DataOrigin::Measured;
  p.host = bs::host_name();
  p.cpu_model = cpu.model;
  p.os = os_name();
  if (backend.id.starts_with("opencl") || backend.id.starts_with("cuda")) p.gpu_model = backend.device_name;
  p.compiler = BENCHSCOPE_COMPILER;
  p.tool = std::string("benchscope ") + BENCHSCOPE_VERSION;
  p.date = bs::utc_timestamp();
  char cpu_note[160];
  std::snprintf(cpu_note, sizeof cpu_note, "host CPU %s, %d threads, %.3f GHz measured (dependent imul chain)",
                cpu.simd.name.c_str(), cpu.threads, cpu.clock_hz / 1e9);
  p.note = backend.id + ": " + backend.details + "; " + cpu_note + "; built " + BENCHSCOPE_BUILD_FLAGS;
  return p;
}

}  // namespace bs::kernels
