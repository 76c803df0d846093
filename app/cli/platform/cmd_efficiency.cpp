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
  const EfficiencyComparison table = compare_efficiency(data.runs, data.power_traces, supply);
  const std::vector<PlatformEfficiency>& rows = table.rows;
  const auto or_null = [](std::optional<double> v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
  nlohmann::json list = nlohmann::json::array();
  for (const PlatformEfficiency& e : rows) {
    const PeakRow& peak = e.peak;
    const std::string& platform = peak.platform;
    if (args.has("--json")) {
      list.push_back(
          {{"platform", platform},
           {"device", peak.device},
           {"backend", peak.backend},
           {"peak_flops", peak.peak.flops},
           {"supply_voltage_v", or_null(e.supply_v)},
           {"max_current_a", or_null(e.current_a ? std::optional<double>(e.current_a->max) : std::nullopt)},
           {"mean_power_w", e.power_w.mean},
           {"flops_per_watt_paper",
            or_null(e.paper_gflops_per_w ? std::optional<double>(*e.paper_gflops_per_w * 1e9) : std::nullopt)},
           {"paper_missing", e.paper_missing},
           {"flops_per_watt_mean_power", e.mean_power_gflops_per_w * 1e9},
           {"joules_per_gflop", e.joules_per_gflop},
           {"measurement", e.measurement},
           {"flags", flags_json(e.flags)}});
      continue;
    }
    char line[512];
    std::snprintf(line, sizeof line, "%s: peak %.2f GFLOPS (%s, %s, D = %d)\n", platform.c_str(), peak.peak.flops / 1e9,
                  peak.device.c_str(), peak.backend.c_str(), peak.dims);
    out << line;
    if (e.paper_gflops_per_w)
      std::snprintf(line, sizeof line, "  GFLOPS/W as the paper defines it, peak / (%.1f V x max %.3f A): %.2f\n",
                    *e.supply_v, e.current_a->max, *e.paper_gflops_per_w);
    else
      std::snprintf(line, sizeof line, "  GFLOPS/W as the paper defines it: none, %s\n", e.paper_missing.c_str());
    out << line;
    std::snprintf(line, sizeof line,
                  "  GFLOPS/W at the mean power of the log (%.2f W): %.2f; energy per GFLOP %.4f J\n", e.power_w.mean,
                  e.mean_power_gflops_per_w, e.joules_per_gflop);
    out << line << "  power measured by: " << e.measurement << '\n';
    for (const PlausibilityFlag& f : e.flags) out << "  \xE2\x9A\xA0 " << f.code << ": " << f.reason << '\n';
  }
  // Every platform of the inputs is accounted for: those without a figure are named with the reason.
  nlohmann::json left_out = nlohmann::json::array();
  for (const EfficiencyLeftOut& l : table.left_out) {
    if (args.has("--json"))
      left_out.push_back({{"platform", l.platform}, {"reason", l.reason}});
    else
      out << l.platform << ": no efficiency figure, " << l.reason << '\n';
  }
  if (args.has("--json"))
    out << nlohmann::json{{"format", "benchscope-efficiency"},
                          {"version", 1},
                          {"platforms", list},
                          {"left_out", left_out}}
               .dump(2)
        << '\n';
  if (rows.empty()) throw std::runtime_error("no platform has both FLOPS runs and a power log");
  return 0;
}

const CommandRegistrar registrar({
    "efficiency",
    "GFLOPS/W per platform (the paper's definition and at mean power)",
    "usage: benchscope-cli efficiency (WORKSPACE | PATH...) [--supply-volts V] [--json]\n"
    "  Pairs each platform's highest FLOPS peak with its power log (same platform name): the paper's\n"
    "  peak / (supply V x maximum current), and the honest variants peak / mean power and joules per GFLOP.\n"
    "  A log of power only (tegrastats, jtop) has no paper figure; platforms without a figure are named with\n"
    "  the reason.",
    out_only<run_efficiency>,
});

}  // namespace
}  // namespace bs::cli
