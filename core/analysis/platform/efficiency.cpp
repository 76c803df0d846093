// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/platform/efficiency.h"

#include <cstdio>
#include <stdexcept>

#include "analysis/power/power.h"

namespace bs {
namespace {

void positive(double v, const char* what) {
  if (!(v > 0)) throw std::invalid_argument(std::string(what) + " must be > 0");
}

std::string format(const char* fmt, double a, double b = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}

}  // namespace

double paper_gflops_per_watt(double peak_flops, double supply_v, double max_current_a) {
  positive(peak_flops, "peak FLOPS");
  return paper_flops_per_watt(peak_flops, supply_v, max_current_a) / 1e9;
}

double gflops_per_watt_at_mean_power(double peak_flops, double mean_power_w) {
  positive(peak_flops, "peak FLOPS");
  positive(mean_power_w, "mean power");
  return peak_flops / 1e9 / mean_power_w;
}

double joules_per_gflop(double peak_flops, double mean_power_w) {
  positive(peak_flops, "peak FLOPS");
  positive(mean_power_w, "mean power");
  return mean_power_w / (peak_flops / 1e9);
}

double joules_per_gflop_measured(double energy_j, double flop_count) {
  positive(energy_j, "energy");
  positive(flop_count, "FLOP count");
  return energy_j / (flop_count / 1e9);
}

std::vector<EfficiencyFigure> efficiency_figures(const EfficiencyInputs& in) {
  std::vector<EfficiencyFigure> out;
  if (in.supply_v && in.max_current_a)
    out.push_back({format("GFLOPS/W as the paper defines it: peak / (%.1f V x max current %.3f A)", *in.supply_v,
                          *in.max_current_a),
                   paper_gflops_per_watt(in.peak_flops, *in.supply_v, *in.max_current_a), "GFLOPS/W"});
  if (in.mean_power_w) {
    out.push_back({format("GFLOPS/W at mean power: peak / %.2f W", *in.mean_power_w),
                   gflops_per_watt_at_mean_power(in.peak_flops, *in.mean_power_w), "GFLOPS/W"});
    out.push_back({format("energy per GFLOP at the peak rate and %.2f W mean power", *in.mean_power_w),
                   joules_per_gflop(in.peak_flops, *in.mean_power_w), "J/GFLOP"});
  }
  if (in.energy_j && in.flop_count)
    out.push_back({format("energy per GFLOP measured: %.1f J for %.3g FLOP", *in.energy_j, *in.flop_count),
                   joules_per_gflop_measured(*in.energy_j, *in.flop_count), "J/GFLOP"});
  return out;
}

}  // namespace bs
