// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/sweep_energy.h"

#include <algorithm>

#include "analysis/peaks/flops.h"
#include "analysis/power/phase_energy.h"

namespace bs {

std::string sweep_point_phase(std::int64_t workers, int dims) {
  return "point W=" + std::to_string(workers) + " D=" + std::to_string(dims);
}

std::string sweep_warmup_phase(int dims) { return "warm-up D=" + std::to_string(dims); }

double min_point_seconds(double sample_interval_s) {
  return sample_interval_s > 0 ? (static_cast<double>(kMinSamplesPerPoint) + 0.5) * sample_interval_s : 0;
}

std::string short_point_mark(std::size_t samples) {
  return samples < kMinSamplesPerPoint ? " \xE2\x9A\xA0 n < " + std::to_string(kMinSamplesPerPoint) + " samples"
                                       : std::string();
}

std::vector<PointEnergy> sweep_point_energies(const PowerTrace& trace, const std::vector<FlopsRun>& runs) {
  std::vector<PointEnergy> out;
  const auto energies = phase_energies(trace);
  for (const FlopsRun& run : runs)
    for (const WorkerSample& s : run.samples) {
      const std::string name = sweep_point_phase(s.workers, run.dims);
      const auto e =
          std::find_if(energies.begin(), energies.end(), [&](const PhaseEnergy& p) { return p.name == name; });
      if (e == energies.end() || s.seconds.empty()) continue;
      double mean_s = 0;
      for (double v : s.seconds) mean_s += v;
      mean_s /= static_cast<double>(s.seconds.size());
      PointEnergy p;
      p.dims = run.dims;
      p.workers = s.workers;
      p.gflops = rotation_flops(run.dims, run.iterations, s.workers, mean_s) / 1e9;
      p.mean_power_w = e->mean_power_w;
      p.joules_per_run = e->energy_j / static_cast<double>(s.seconds.size());
      p.gflops_per_watt = e->mean_power_w > 0 ? p.gflops / e->mean_power_w : 0;
      p.samples = e->samples;
      p.energy_j = e->energy_j;
      p.seconds = e->end_s - e->start_s;
      p.runs = s.seconds.size();
      out.push_back(p);
    }
  return out;
}

}  // namespace bs
