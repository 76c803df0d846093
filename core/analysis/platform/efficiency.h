// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Compute per watt, as the paper defines it and in the honest variants. The paper divides a platform's peak
// FLOPS by supply voltage x the maximum current seen in its log: that pairs a best-case numerator with a
// worst-case denominator taken at different times. Mean power during the benchmark, and energy per GFLOP,
// are what a battery actually pays. Every figure carries a label that says which one it is.
#include <optional>
#include <string>
#include <vector>

namespace bs {

// The paper's figure: peak FLOPS / (supply V x max current), in GFLOPS/W.
double paper_gflops_per_watt(double peak_flops, double supply_v, double max_current_a);
// Peak FLOPS / mean power while the benchmark ran, in GFLOPS/W.
double gflops_per_watt_at_mean_power(double peak_flops, double mean_power_w);
// Joules per GFLOP at the peak rate and the mean power: mean power / (peak FLOPS / 1e9).
double joules_per_gflop(double peak_flops, double mean_power_w);
// Joules per GFLOP from measured energy and the FLOPs done in the same time window.
double joules_per_gflop_measured(double energy_j, double flop_count);

struct EfficiencyFigure {
  std::string label;  // says how the number was made, e.g. "GFLOPS/W, paper: peak / (16 V x max current 3.136 A)"
  double value = 0;
  std::string unit;  // "GFLOPS/W", "J/GFLOP"
};

struct EfficiencyInputs {
  double peak_flops = 0;                // FLOP/s
  std::optional<double> supply_v;       // for the paper's figure
  std::optional<double> max_current_a;  // for the paper's figure
  std::optional<double> mean_power_w;   // during the benchmark
  std::optional<double> energy_j;       // measured energy of a window ...
  std::optional<double> flop_count;     // ... and the FLOPs done in it
};

// The figures the inputs allow, in the order: paper, mean power, J/GFLOP (peak rate), J/GFLOP (measured).
// Throws std::invalid_argument when a given input is <= 0.
std::vector<EfficiencyFigure> efficiency_figures(const EfficiencyInputs& in);

}  // namespace bs
