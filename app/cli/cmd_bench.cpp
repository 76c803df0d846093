// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli bench kernels: figures and ratios measured in one process (a benchmark, not a test).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "analysis/flops.h"
#include "args.h"
#include "bench_vision.h"
#include "command.h"
#include "kernels/sweep.h"
#include "signals.h"

namespace bs::cli {
namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int bench_kernels(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {}, {"--runs", "--workers"});
  const int runs = static_cast<int>(args.number("--runs", 5));
  if (runs < 1 || runs > 1000) throw UsageError("--runs must be between 1 and 1000");
  const kernels::CpuInfo cpu = kernels::detect_cpu();
  const auto backends = kernels::available_backends(cpu);
  const kernels::RotationParams params{4, 40000};
  char line[256];
  std::snprintf(line, sizeof line, "CPU: %s, %d threads, %.3f GHz measured, %s\n", cpu.model.c_str(), cpu.threads,
                cpu.clock_hz / 1e9, cpu.simd.name.c_str());
  out << line << "D = 4, N = 40,000; GFLOPS = median of " << runs << " runs; % of the theoretical peak computed here\n\n";
  std::snprintf(line, sizeof line, "%-40s %-11s %9s %10s %10s %8s\n", "backend", "variant", "workers", "GFLOPS",
                "peak", "% peak");
  out << line;
  double simd_best = 0, opencl_best = 0;
  for (const auto& b : backends) {
    for (const auto v : b.variants) {
      // Enough work for every thread: 4096 points (throughput) or 4096 tasks (paper); the scalar reference
      // gets a few workers so the benchmark stays short.
      const std::int64_t workers =
          b.id == "cpu-scalar" ? 8 : static_cast<std::int64_t>(args.number("--workers", 1024));
      std::vector<double> gflops;
      std::vector<float> outputs;
      b.run_point(params, workers, v, outputs, interrupt_token());  // warm-up
      for (int r = 0; r < runs; ++r) {
        const double t = b.run_point(params, workers, v, outputs, interrupt_token());
        if (kernels::first_wrong_output(outputs, params) >= 0) throw std::runtime_error(b.label + ": wrong output");
        gflops.push_back(rotation_flops(params.dims, params.iterations, workers, t) / 1e9);
      }
      const double g = median(gflops);
      if (b.id == "cpu-simd") simd_best = std::max(simd_best, g);
      if (b.id.starts_with("opencl")) opencl_best = std::max(opencl_best, g);
      const std::string name = b.id.starts_with("opencl") ? b.label + " " + b.device_name.substr(0, 20) : b.label;
      std::snprintf(line, sizeof line, "%-40s %-11s %9lld %10.2f %10.2f %7.1f%%\n", name.c_str(),
                    kernels::variant_name(v).c_str(), static_cast<long long>(workers), g,
                    b.theoretical_peak_flops / 1e9, 100.0 * g * 1e9 / b.theoretical_peak_flops);
      out << line;
    }
  }
  // Sweep bookkeeping: wall time of a 100-point sweep (the paper's N) against the sum of its timed points.
  const auto& simd = backends.front();
  kernels::SweepSpec spec;
  for (int i = 1; i <= 100; ++i) spec.workers.push_back(64 * i);
  spec.iterations = 40000;
  spec.warmup = false;
  const auto t0 = std::chrono::steady_clock::now();
  const auto result = kernels::run_sweep(simd, cpu, spec, interrupt_token());
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double timed = 0;
  for (const auto& s : result.runs.front().samples) timed += s.seconds.front();
  std::snprintf(line, sizeof line,
                "\nsweep of 100 points (N = 40,000): wall %.3f s, timed kernel %.3f s, bookkeeping overhead %.2f %%\n"
                "CPU SIMD best: %.2f GFLOPS = %.1f %% of the %.2f GFLOPS theoretical peak\n",
                wall, timed, 100.0 * (wall - timed) / wall, simd_best, 100.0 * simd_best * 1e9 / cpu.peak_flops,
                cpu.peak_flops / 1e9);
  out << line;
  if (opencl_best > 0) {
    std::snprintf(line, sizeof line, "OpenCL best / CPU SIMD best: %.2f (%.2f / %.2f GFLOPS)\n", opencl_best / simd_best,
                  opencl_best, simd_best);
    out << line;
  }
  return 0;
}

const CommandRegistrar registrar({
    "bench",
    "benchmarks printing figures and ratios (bench kernels | bench vision)",
    "usage: benchscope-cli bench kernels [--runs R] [--workers W]\n"
    "       benchscope-cli bench vision [--frames F]\n"
    "  Best GFLOPS per backend and variant (D = 4, N = 40,000, median of R runs), % of this machine's\n"
    "  theoretical peak, and the sweep bookkeeping overhead. Figures only: nothing passes or fails on time.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      try {
        const std::vector<std::string> rest(args.empty() ? args.end() : args.begin() + 1, args.end());
        if (!args.empty() && args[0] == "kernels") return bench_kernels(rest, out);
        if (!args.empty() && args[0] == "vision") return bench_vision(rest, out);
        throw UsageError("expected 'bench kernels' or 'bench vision'");
      } catch (const UsageError& e) {
        err << "benchscope-cli: error: " << e.what() << '\n';
        return 2;
      }
    },
});

}  // namespace
}  // namespace bs::cli
