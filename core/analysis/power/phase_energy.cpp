// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/phase_energy.h"

#include <cmath>

#include "analysis/power/power.h"
#include "analysis/power/power_stats.h"

namespace bs {
namespace {

struct Series {
  std::vector<double> t, w;
};

// The total power without its missing samples: a gap is bridged by the samples either side of it.
Series total_power(const PowerTrace& trace) {
  Series s;
  const std::vector<double> w = power_series(trace);
  for (std::size_t i = 0; i < w.size() && i < trace.time_s.size(); ++i)
    if (std::isfinite(w[i])) {
      s.t.push_back(trace.time_s[i]);
      s.w.push_back(w[i]);
    }
  return s;
}

std::optional<PhaseEnergy> energy_of(const Series& s, const std::string& name, double from_s, double to_s) {
  if (s.t.size() < 2 || !(to_s > from_s) || to_s <= s.t.front() || from_s >= s.t.back()) return std::nullopt;
  PhaseEnergy e;
  e.name = name;
  e.start_s = from_s;
  e.end_s = to_s;
  e.energy_j = integrate_range(s.t, s.w, from_s, to_s);
  const double covered = std::min(to_s, s.t.back()) - std::max(from_s, s.t.front());
  e.mean_power_w = covered > 0 ? e.energy_j / covered : 0;
  for (double t : s.t) e.samples += t >= from_s && t <= to_s;
  return e;
}

}  // namespace

std::vector<PhaseEnergy> phase_energies(const PowerTrace& trace) {
  std::vector<PhaseEnergy> out;
  const Series s = total_power(trace);
  for (const TracePhase& p : trace.phases)
    if (auto e = energy_of(s, p.name, p.start_s, p.end_s)) out.push_back(std::move(*e));
  return out;
}

std::optional<PhaseEnergy> window_energy(const PowerTrace& trace, double from_s, double to_s, const std::string& name) {
  return energy_of(total_power(trace), name, from_s, to_s);
}

std::optional<double> joules_per_item(const PhaseEnergy& phase, std::size_t count) {
  if (count == 0) return std::nullopt;
  return phase.energy_j / static_cast<double>(count);
}

std::optional<double> gflops_per_watt(double flops, const PhaseEnergy& phase) {
  if (!(phase.mean_power_w > 0)) return std::nullopt;
  return flops / 1e9 / phase.mean_power_w;
}

}  // namespace bs
