// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli efficiency: GFLOPS/W per platform, as the paper defines it and the honest variant.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "analysis/peaks/flops.h"
#include "analysis/platform/platform_efficiency.h"
#include "common/args.h"
#include "common/command.h"
#include "common/flag_output.h"
#include "common/signals.h"
#include "workspace/inputs.h"

namespace bs::cli {
namespace {

int run_efficiency(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {"--json"}, {"--supply-volts"});
  if (args.positional.empty()) throw UsageError("efficiency needs a workspace or files");
  std::optional<double> supply;
  if (args.value("--supply-volts")) supply = args.number("--supply-volts", 0);
  const LoadedData data = load_inputs(args.positional, interrupt_token());
  const std::vector<PlatformEfficiency> rows = platform_efficiency(data.runs, data.power_traces, supply);
  nlohmann::json list = nlohmann::json::array();
  for (const PlatformEfficiency& e : rows) {
    const PeakRow& peak = e.peak;
    const std::string& platform = peak.platform;
    if (args.has("--json")) {
      list.push_back({{"platform", platform},
                      {"device", peak.device},
                      {"backend", peak.backend},
                      {"peak_flops", peak.peak.flops},
                      {"supply_voltage_v", e.supply_v},
                      {"max_current_a", e.current_a.max},
                      {"mean_power_w", e.power_w.mean},
                      {"flops_per_watt_paper", e.paper_gflops_per_w * 1e9},
                      {"flops_per_watt_mean_power", e.mean_power_gflops_per_w * 1e9},
                      {"joules_per_gflop", e.joules_per_gflop},
                      {"measurement", e.measurement},
                      {"flags", flags_json(e.flags)}});
      continue;
    }
    char line[512];
    std::snprintf(line, sizeof line,
                  "%s: peak %.2f GFLOPS (%s, %s, D = %d)\n"
                  "  GFLOPS/W as the paper defines it, peak / (%.1f V x max %.3f A): %.2f\n"
                  "  GFLOPS/W at the mean power of the log (%.2f W): %.2f; energy per GFLOP %.4f J\n",
                  platform.c_str(), peak.peak.flops / 1e9, peak.device.c_str(), peak.backend.c_str(), peak.dims,
                  e.supply_v, e.current_a.max, e.paper_gflops_per_w, e.power_w.mean, e.mean_power_gflops_per_w,
                  e.joules_per_gflop);
    out << line << "  power measured by: " << e.measurement << '\n';
    for (const PlausibilityFlag& f : e.flags) out << "  \xE2\x9A\xA0 " << f.code << ": " << f.reason << '\n';
  }
  if (args.has("--json"))
    out << nlohmann::json{{"format", "benchscope-efficiency"}, {"version", 1}, {"platforms", list}}.dump(2) << '\n';
  if (rows.empty()) throw std::runtime_error("no platform has both FLOPS runs and a current log with a supply voltage");
  return 0;
}

const CommandRegistrar registrar({
    "efficiency",
    "GFLOPS/W per platform (the paper's definition and at mean power)",
    "usage: benchscope-cli efficiency (WORKSPACE | PATH...) [--supply-volts V] [--json]\n"
    "  Pairs each platform's highest FLOPS peak with its current log (same platform name): the paper's\n"
    "  peak / (supply V x maximum current), and the honest variants peak / mean power and joules per GFLOP.",
    out_only<run_efficiency>,
});

}  // namespace
}  // namespace bs::cli
