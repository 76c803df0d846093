// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli efficiency: GFLOPS/W per platform, as the paper defines it and the honest variant.
#include <cstdio>
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include "analysis/flops.h"
#include "analysis/power.h"
#include "args.h"
#include "command.h"
#include "inputs.h"
#include "signals.h"

namespace bs::cli {
namespace {

int run_efficiency(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {"--json"}, {"--supply-volts"});
  if (args.positional.empty()) throw UsageError("efficiency needs a workspace or files");
  std::optional<double> supply;
  if (args.value("--supply-volts")) supply = args.number("--supply-volts", 0);
  const LoadedData data = load_inputs(args.positional, interrupt_token());
  // The best run per platform (the paper uses each platform's GPU peak, which is its highest).
  std::map<std::string, PeakRow> best;
  for (const PeakRow& row : peak_table(data.runs))
    if (!best.count(row.platform) || row.peak.flops > best[row.platform].peak.flops) best[row.platform] = row;
  nlohmann::json list = nlohmann::json::array();
  int shown = 0;
  for (const PowerTrace& trace : data.power_traces) {
    const auto it = best.find(trace.platform);
    if (it == best.end()) continue;
    const auto volts = supply ? supply : trace.supply_voltage_v;
    const TraceStats s = trace_stats(trace, supply);
    if (!s.current_a || !volts || !s.power_w) continue;
    const PeakRow& peak = it->second;
    const double paper = paper_flops_per_watt(peak.peak.flops, *volts, s.current_a->max);
    const double mean_power = peak.peak.flops / s.power_w->mean;
    ++shown;
    if (args.has("--json")) {
      list.push_back({{"platform", trace.platform}, {"device", peak.device}, {"backend", peak.backend},
                      {"peak_flops", peak.peak.flops}, {"supply_voltage_v", *volts}, {"max_current_a", s.current_a->max},
                      {"mean_power_w", s.power_w->mean}, {"flops_per_watt_paper", paper},
                      {"flops_per_watt_mean_power", mean_power}, {"joules_per_gflop", 1e9 / mean_power}});
      continue;
    }
    char line[512];
    std::snprintf(line, sizeof line,
                  "%s: peak %.2f GFLOPS (%s, %s, D = %d)\n"
                  "  GFLOPS/W as the paper defines it, peak / (%.1f V x max %.3f A): %.2f\n"
                  "  GFLOPS/W at the mean power of the log (%.2f W): %.2f; energy per GFLOP %.4f J\n",
                  trace.platform.c_str(), peak.peak.flops / 1e9, peak.device.c_str(), peak.backend.c_str(), peak.dims,
                  *volts, s.current_a->max, paper / 1e9, s.power_w->mean, mean_power / 1e9, 1e9 / mean_power);
    out << line;
  }
  if (args.has("--json")) out << nlohmann::json{{"format", "benchscope-efficiency"}, {"version", 1}, {"platforms", list}}.dump(2) << '\n';
  if (shown == 0) throw std::runtime_error("no platform has both FLOPS runs and a current log with a supply voltage");
  return 0;
}

const CommandRegistrar registrar({
    "efficiency",
    "GFLOPS/W per platform (the paper's definition and at mean power)",
    "usage: benchscope-cli efficiency (WORKSPACE | PATH...) [--supply-volts V] [--json]\n"
    "  Pairs each platform's highest FLOPS peak with its current log (same platform name): the paper's\n"
    "  peak / (supply V x maximum current), and the honest variants peak / mean power and joules per GFLOP.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      try {
        return run_efficiency(args, out);
      } catch (const UsageError& e) {
        err << "benchscope-cli: error: " << e.what() << "\n(see benchscope-cli help efficiency)\n";
        return 2;
      }
    },
});

}  // namespace
}  // namespace bs::cli
