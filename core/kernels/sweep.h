// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <functional>
#include <vector>

#include "kernels/backends/backend.h"

namespace bs::kernels {

struct SweepSpec {
  std::vector<std::int64_t> workers;  // ascending
  std::vector<int> dims = {4};
  std::int64_t iterations = 40000;
  int repeats = 1;     // timings per point; views show mean ± SD
  bool warmup = true;  // one untimed run of the first point per D (thread start-up, page faults)
  Variant variant = Variant::Throughput;
  // With power recorded: each point repeats its timed run (beyond `repeats`) until the point has lasted this long,
  // so the sensor samples it often enough (issue #32.4). Every timing is the same work, so the FLOPS figure (the
  // mean of the timings) is unchanged; only n grows. 0: exactly `repeats`.
  double min_point_s = 0;
};

struct SweepResult {
  std::vector<FlopsRun> runs;  // one per D; holds every completed point, also when cancelled
  bool cancelled = false;
};

// Runs every (D, W) point `repeats` times, verifies every output against the closed form (throws
// std::runtime_error naming the point when one is wrong), reports progress and, after each completed point,
// calls `on_point` with the run so far (a live view can redraw). Cancel stops within one chunk (~20 ms).
SweepResult run_sweep(const Backend& backend, const CpuInfo& cpu, const SweepSpec& spec, const CancelToken& cancel,
                      const ProgressFn& progress = {}, const std::function<void(const FlopsRun&)>& on_point = {});

}  // namespace bs::kernels
