// SPDX-License-Identifier: GPL-3.0-or-later
#include <chrono>
#include <cstdio>
#include <ctime>

#include "kernels/backend.h"

namespace bs::kernels {
namespace {

// Rotations of one point per chunk: ~20 ms of work at ~100 GFLOPS, so a cancel is seen well within 200 ms.
constexpr double kPointStepsPerChunk = 3e8;

double run_simd(const SimdTarget& target, const RotationParams& p, std::int64_t workers, Variant variant,
                std::vector<float>& outputs, const CancelToken& cancel) {
  SimdRotation state(target, variant, p, workers);
  const auto per_step = static_cast<double>(workers) * p.dims;
  const auto chunk = std::max<std::int64_t>(1, static_cast<std::int64_t>(kPointStepsPerChunk / per_step));
  outputs.assign(static_cast<std::size_t>(workers), 0.0f);
  const auto t0 = std::chrono::steady_clock::now();
  for (std::int64_t done = 0; done < p.iterations; done += chunk) {
    cancel.throw_if_cancelled();
    state.advance(std::min(chunk, p.iterations - done));
  }
  state.outputs(outputs);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double run_scalar(const RotationParams& p, std::int64_t workers, std::vector<float>& outputs,
                  const CancelToken& cancel) {
  outputs.assign(static_cast<std::size_t>(workers), 0.0f);
  const auto t0 = std::chrono::steady_clock::now();
  for (std::int64_t w = 0; w < workers; ++w) {
    cancel.throw_if_cancelled();
    rotate_scalar(p, std::span<float>(outputs).subspan(static_cast<std::size_t>(w), 1));
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace

std::vector<Backend> cpu_backends(const CpuInfo& cpu) {
  char details[256];
  std::snprintf(details, sizeof details, "%d threads, %.2f GHz measured, %s (%d lanes), %.0f flop/cycle/core",
                cpu.threads, cpu.clock_hz / 1e9, cpu.simd.name.c_str(), cpu.simd.lanes, cpu.flops_per_cycle);
  Backend simd;
  simd.id = "cpu-simd";
  simd.label = "CPU SIMD (" + cpu.simd.name + ")";
  simd.device_name = cpu.model;
  simd.variants = {Variant::Throughput, Variant::Paper};
  simd.theoretical_peak_flops = cpu.peak_flops;
  simd.details = details;
  const SimdTarget target = cpu.simd;
  simd.run_point = [target](const RotationParams& p, std::int64_t w, Variant v, std::vector<float>& out,
                            const CancelToken& c) { return run_simd(target, p, w, v, out, c); };

  Backend scalar;
  scalar.id = "cpu-scalar";
  scalar.label = "CPU scalar (reference)";
  scalar.device_name = cpu.model;
  scalar.variants = {Variant::Paper};
  // One thread, one float per op: a worker's D points are independent chains, so the 4 FP ops of a point-step
  // are throughput-bound on the 2 FP pipes: 6 flops per 2 cycles.
  scalar.theoretical_peak_flops = cpu.clock_hz * 6.0 * 2 / 4.0;
  scalar.details = "1 thread, scalar float, the paper's exact semantics";
  scalar.run_point = [](const RotationParams& p, std::int64_t w, Variant, std::vector<float>& out,
                        const CancelToken& c) { return run_scalar(p, w, out, c); };
  return {simd, scalar};
}

Provenance measured_provenance(const CpuInfo& cpu, const Backend& backend) {
  Provenance p;
  p.origin = DataOrigin::Measured;
  p.host = host_name();
  p.cpu_model = cpu.model;
  p.os = os_name();
  p.compiler = BENCHSCOPE_COMPILER;
  p.tool = std::string("benchscope ") + BENCHSCOPE_VERSION;
  p.date = utc_now();
  p.note = backend.id + ": " + backend.details + "; built " + BENCHSCOPE_BUILD_FLAGS;
  return p;
}

}  // namespace bs::kernels
