// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/platform/platform_efficiency.h"

#include <map>
#include <set>

#include "analysis/peaks/plausibility.h"
#include "analysis/power/power.h"
#include "analysis/stats/measurement_text.h"

namespace bs {

std::vector<PlatformEfficiency> platform_efficiency(std::span<const FlopsRun> runs, std::span<const PowerTrace> traces,
                                                    std::optional<double> supply_v) {
  std::map<std::string, PeakRow> best;
  for (const PeakRow& row : peak_table(runs)) {
    const auto it = best.find(row.platform);
    if (it == best.end() || row.peak.flops > it->second.peak.flops) best[row.platform] = row;
  }
  std::vector<PlatformEfficiency> out;
  std::set<std::string> done;
  for (const PowerTrace& trace : traces) {
    const auto it = best.find(trace.platform);
    if (it == best.end() || done.count(trace.platform)) continue;
    const auto volts = supply_v ? supply_v : trace.supply_voltage_v;
    const TraceStats s = trace_stats(trace, supply_v);
    if (!s.current_a || !volts || !s.power_w || !(it->second.peak.flops > 0)) continue;
    if (!(s.current_a->max > 0) || !(s.power_w->mean > 0) || !(*volts > 0)) continue;  // nothing to divide by
    PlatformEfficiency e;
    e.peak = it->second;
    e.trace_label = trace.label;
    e.supply_v = *volts;
    e.current_a = *s.current_a;
    e.power_w = *s.power_w;
    e.figures = efficiency_figures({e.peak.peak.flops, *volts, s.current_a->max, s.power_w->mean, {}, {}});
    e.paper_gflops_per_w = e.figures.at(0).value;
    e.mean_power_gflops_per_w = e.figures.at(1).value;
    e.joules_per_gflop = e.figures.at(2).value;
    e.measurement = measurement_text(trace.provenance);
    e.flags = e.peak.flags;
    merge_flags(e.flags, check_power_trace_bundled(trace));
    done.insert(trace.platform);
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace bs
