// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/platform/platform_efficiency.h"

#include <algorithm>
#include <map>

#include "analysis/peaks/plausibility.h"
#include "analysis/power/power.h"
#include "analysis/stats/measurement_text.h"

namespace bs {
namespace {

bool has_current(const PowerTrace& trace) {
  return std::any_of(trace.channels.begin(), trace.channels.end(),
                     [](const PowerChannel& c) { return c.quantity == PowerQuantity::Current; });
}

// Why `trace` gives no efficiency figure for a platform whose peak is `peak_flops`; "" when it gives one.
std::string unusable(const PowerTrace& trace, const TraceStats& s, double peak_flops) {
  if (!(peak_flops > 0)) return "its FLOPS peak is 0";
  if (!s.power_w && has_current(trace))
    return "its log " + trace.label + " has current but no supply voltage (right-click the log > Supply voltage…)";
  if (!s.power_w) return "its log " + trace.label + " has neither power nor current";
  if (!(s.power_w->mean > 0)) return "its log " + trace.label + " has no power above 0 W";
  return {};
}

void add_row(EfficiencyComparison& out, const PeakRow& peak, const PowerTrace& trace, const TraceStats& s,
             std::optional<double> volts) {
  PlatformEfficiency e;
  e.peak = peak;
  e.trace_label = trace.label;
  e.power_w = *s.power_w;
  // The paper's figure divides by supply V x the largest current: a log of power only has no current to take.
  const bool paper = s.current_a && volts && *volts > 0 && s.current_a->max > 0;
  if (paper) {
    e.supply_v = volts;
    e.current_a = s.current_a;
  } else if (!s.current_a) {
    e.paper_missing = "its log " + trace.label + " measures power, not a supply current";
  } else if (!volts || !(*volts > 0)) {
    e.paper_missing = "its log " + trace.label + " has no supply voltage for its current";
  } else {
    e.paper_missing = "its log " + trace.label + " has no current above 0 A";
  }
  e.figures = efficiency_figures({peak.peak.flops, paper ? volts : std::nullopt,
                                  paper ? std::optional<double>(s.current_a->max) : std::nullopt, s.power_w->mean,
                                  std::nullopt, std::nullopt});
  const std::size_t at_mean = paper ? 1 : 0;  // efficiency_figures: paper (when given), mean power, J/GFLOP
  if (paper) e.paper_gflops_per_w = e.figures.at(0).value;
  e.mean_power_gflops_per_w = e.figures.at(at_mean).value;
  e.joules_per_gflop = e.figures.at(at_mean + 1).value;
  e.measurement = measurement_text(trace.provenance);
  e.flags = peak.flags;
  merge_flags(e.flags, check_power_trace_bundled(trace));
  out.rows.push_back(std::move(e));
}

}  // namespace

EfficiencyComparison compare_efficiency(std::span<const FlopsRun> runs, std::span<const PowerTrace> traces,
                                        std::optional<double> supply_v) {
  std::map<std::string, PeakRow> best;
  std::vector<std::string> platforms;  // the runs' platforms in order, then the logs' that have no run
  for (const PeakRow& row : peak_table(runs)) {
    const auto it = best.find(row.platform);
    if (it == best.end()) platforms.push_back(row.platform);
    if (it == best.end() || row.peak.flops > it->second.peak.flops) best[row.platform] = row;
  }
  for (const PowerTrace& t : traces)
    if (std::find(platforms.begin(), platforms.end(), t.platform) == platforms.end()) platforms.push_back(t.platform);

  EfficiencyComparison out;
  std::map<std::string, std::string> why;  // per platform: why its logs gave no row (the first log's reason)
  for (const PowerTrace& trace : traces) {
    const auto peak = best.find(trace.platform);
    const bool done = std::any_of(out.rows.begin(), out.rows.end(),
                                  [&](const PlatformEfficiency& e) { return e.peak.platform == trace.platform; });
    if (peak == best.end() || done) continue;
    const auto volts = supply_v ? supply_v : trace.supply_voltage_v;
    const TraceStats s = trace_stats(trace, supply_v);
    if (const std::string reason = unusable(trace, s, peak->second.peak.flops); !reason.empty()) {
      why.emplace(trace.platform, reason);  // a later log of the platform may still give its row
      continue;
    }
    add_row(out, peak->second, trace, s, volts);
  }
  for (const std::string& platform : platforms) {
    if (std::any_of(out.rows.begin(), out.rows.end(),
                    [&](const PlatformEfficiency& e) { return e.peak.platform == platform; }))
      continue;
    std::string reason;
    if (!best.count(platform)) {
      const auto log =
          std::find_if(traces.begin(), traces.end(), [&](const PowerTrace& t) { return t.platform == platform; });
      reason = "no FLOPS run of this platform (its power log: " + log->label + ")";
    } else if (const auto it = why.find(platform); it != why.end()) {
      reason = it->second;
    } else {
      reason = "no power log of this platform";
    }
    out.left_out.push_back({platform, std::move(reason)});
  }
  return out;
}

std::vector<PlatformEfficiency> platform_efficiency(std::span<const FlopsRun> runs, std::span<const PowerTrace> traces,
                                                    std::optional<double> supply_v) {
  return compare_efficiency(runs, traces, supply_v).rows;
}

}  // namespace bs
