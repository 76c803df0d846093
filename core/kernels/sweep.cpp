// SPDX-License-Identifier: GPL-3.0-or-later
#include "kernels/sweep.h"
#include "util/host_clock.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

namespace bs::kernels {
namespace {
constexpr int kMaxTimingsPerPoint = 100000;
}  // namespace

SweepResult run_sweep(const Backend& backend, const CpuInfo& cpu, const SweepSpec& spec, const CancelToken& cancel,
                      const ProgressFn& progress, const std::function<void(const FlopsRun&)>& on_point) {
  if (spec.workers.empty() || spec.dims.empty() || spec.repeats < 1 || spec.iterations < 1)
    throw std::invalid_argument("a sweep needs workers, D values, N >= 1 and repeats >= 1");
  if (!(spec.min_point_s >= 0 && spec.min_point_s < 3600))
    throw std::invalid_argument("a sweep point's minimum duration must be in [0, 3600) s");
  // A run's samples are ascending and unique by worker count (run JSON v1).
  std::vector<std::int64_t> workers = spec.workers;
  std::sort(workers.begin(), workers.end());
  workers.erase(std::unique(workers.begin(), workers.end()), workers.end());
  // Refuse what a backend cannot run before the first point, not half-way through the sweep.
  for (int d : spec.dims) {
    check_problem_size({d, spec.iterations}, workers.back());
    check_problem_size({d, spec.iterations}, workers.front());
    if (spec.variant == Variant::Paper && !backend.paper_dims.empty() &&
        std::find(backend.paper_dims.begin(), backend.paper_dims.end(), d) == backend.paper_dims.end())
      throw std::invalid_argument(backend.label +
                                  ": the paper kernel runs D = 1, 2 or 4 (float, float2, float4), not D = " +
                                  std::to_string(d) + "; use the throughput variant for other D");
  }
  SweepResult result;
  const double total = static_cast<double>(workers.size() * spec.dims.size());
  std::size_t done = 0;
  std::vector<float> outputs;
  try {
    for (int d : spec.dims) {
      FlopsRun run;
      run.platform = bs::host_name();
      run.device = backend.device_name;
      run.device_kind = backend.kind;
      run.backend = backend.label;
      run.variant = backend.variant_label(spec.variant);
      run.iterations = spec.iterations;
      run.dims = d;
      if (backend.theoretical_peak_flops > 0) run.theoretical_peak_flops = backend.theoretical_peak_flops;
      run.provenance = measured_provenance(cpu, backend);
      result.runs.push_back(run);
      const RotationParams params{d, spec.iterations};
      if (spec.warmup) backend.run_point(params, workers.front(), spec.variant, outputs, cancel);
      for (std::int64_t w : workers) {
        if (progress)
          progress(static_cast<double>(done) / total, "W=" + std::to_string(w) + ", D=" + std::to_string(d));
        WorkerSample sample{w, {}};
        const auto point_start = std::chrono::steady_clock::now();
        const auto lasted_s = [&] {
          return std::chrono::duration<double>(std::chrono::steady_clock::now() - point_start).count();
        };
        // At least `repeats` timings, more while the point is shorter than min_point_s (bounded: a point never
        // takes more than 100,000 timings, whatever the clock does).
        for (int r = 0; r < spec.repeats || (lasted_s() < spec.min_point_s && r < kMaxTimingsPerPoint); ++r) {
          const double seconds = backend.run_point(params, w, spec.variant, outputs, cancel);
          const std::int64_t bad = first_wrong_output(outputs, params);
          if (bad >= 0)
            throw std::runtime_error(backend.label + ": wrong result at D=" + std::to_string(d) +
                                     ", W=" + std::to_string(w) + ", worker " + std::to_string(bad) + ": got " +
                                     std::to_string(outputs[static_cast<std::size_t>(bad)]) + ", expected " +
                                     std::to_string(closed_form_output(params)));
          sample.seconds.push_back(seconds);
        }
        result.runs.back().samples.push_back(std::move(sample));
        ++done;
        if (on_point) on_point(result.runs.back());
      }
    }
  } catch (const Cancelled&) {
    result.cancelled = true;
  }
  // A D whose first point never completed has nothing to show.
  std::erase_if(result.runs, [](const FlopsRun& r) { return r.samples.empty(); });
  if (progress) progress(1.0, result.cancelled ? "cancelled" : "done");
  return result;
}

}  // namespace bs::kernels
