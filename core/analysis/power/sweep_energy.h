// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Energy per sweep point of a FLOPS run recorded with the on-board sensors: the sweep marks a phase per point
// (sweep_point_phase) and per D's warm-up (sweep_warmup_phase); each point's energy over its repeats gives
// joules per timed run and GFLOPS/W at the point's mean power. Shared by `run flops --power` and the Kernel Runner.
#include <cstdint>
#include <string>
#include <vector>

#include "model/flops_run.h"
#include "model/power_trace.h"

namespace bs {

std::string sweep_point_phase(std::int64_t workers, int dims);  // "point W=64 D=4"
std::string sweep_warmup_phase(int dims);                       // "warm-up D=4"

// A point's energy is trusted when the sensor sampled it at least this often (issue #32.4): fewer samples and the
// figure leans on interpolation between readings taken outside the point.
inline constexpr std::size_t kMinSamplesPerPoint = 10;
// How long a sweep point must last to span kMinSamplesPerPoint samples at `sample_interval_s` (half an interval
// to spare: the first sample may fall just after the point starts).
double min_point_seconds(double sample_interval_s);

struct PointEnergy {
  int dims = 0;
  std::int64_t workers = 0;
  double gflops = 0;           // at the point's mean time
  double mean_power_w = 0;     // over the point's phase
  double joules_per_run = 0;   // the phase's energy / repeats
  double gflops_per_watt = 0;  // gflops / mean power
  double energy_j = 0;         // the whole point (all its timed runs)
  double seconds = 0;          // the point's phase duration
  std::size_t runs = 0;        // timed runs in the point
  std::size_t samples = 0;     // trace samples inside the phase: under 2, interpolated
  bool too_short() const { return samples < kMinSamplesPerPoint; }
};

// " ⚠ n < 10 samples" (UTF-8) for a point or phase the sensor sampled fewer than kMinSamplesPerPoint times; empty
// otherwise. One wording for the Kernel Runner, the Power tab's Phases table and the CLI.
std::string short_point_mark(std::size_t samples);

// One entry per point of `runs` that has a phase in `trace`, in run and worker order.
std::vector<PointEnergy> sweep_point_energies(const PowerTrace& trace, const std::vector<FlopsRun>& runs);

}  // namespace bs
