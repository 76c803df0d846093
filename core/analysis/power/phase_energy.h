// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Energy of each marked phase of a power trace (a sweep point, the warm-up, a pipeline stage's window): the
// trapezoidal integral of the total power over the phase, the values at its ends interpolated, missing (NaN)
// samples left out. From it: mean power, joules per unit of work (per frame, per inference) and GFLOPS/W.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "model/power_trace.h"

namespace bs {

struct PhaseEnergy {
  std::string name;
  double start_s = 0, end_s = 0;
  double energy_j = 0;
  double mean_power_w = 0;  // energy / duration
  std::size_t samples = 0;  // samples of the trace inside [start, end]: under 2, the figure is interpolated
};

// Every phase of `trace`, in its order, over the trace's total power (power_series). Empty without power.
std::vector<PhaseEnergy> phase_energies(const PowerTrace& trace);
// The energy of [from_s, to_s] over the total power, or empty when the trace has no power there.
std::optional<PhaseEnergy> window_energy(const PowerTrace& trace, double from_s, double to_s,
                                         const std::string& name = {});

// Energy per item of work (J per frame, J per inference): energy / count; empty when count is 0.
std::optional<double> joules_per_item(const PhaseEnergy& phase, std::size_t count);
// GFLOPS per watt at the phase's mean power: (flops / 1e9) / mean power.
std::optional<double> gflops_per_watt(double flops, const PhaseEnergy& phase);

}  // namespace bs
