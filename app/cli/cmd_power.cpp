// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli power: statistics of current/power logs (the paper's section on current consumption).
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "analysis/power.h"
#include "args.h"
#include "command.h"
#include "inputs.h"
#include "signals.h"

namespace bs::cli {
namespace {

nlohmann::json summary_json(const std::optional<Summary>& s) {
  if (!s) return nullptr;
  return {{"n", s->n}, {"mean", s->mean}, {"sd", s->sd}, {"min", s->min}, {"max", s->max}};
}

int run_power(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {"--json"}, {"--supply-volts", "--from", "--to"});
  if (args.positional.empty()) throw UsageError("power needs current/power log files (or a workspace)");
  std::optional<double> supply, from, to;
  if (args.value("--supply-volts")) supply = args.number("--supply-volts", 0);
  if (supply && !(*supply > 0)) throw UsageError("--supply-volts must be > 0");
  if (args.value("--from")) from = args.number("--from", 0);
  if (args.value("--to")) to = args.number("--to", 0);
  const LoadedData data = load_inputs(args.positional, interrupt_token());
  if (data.power_traces.empty()) throw std::runtime_error("no current or power logs in the given inputs");
  nlohmann::json list = nlohmann::json::array();
  for (const PowerTrace& t : data.power_traces) {
    const TraceStats s = trace_stats(t, supply, from, to);
    const auto volts = supply ? supply : t.supply_voltage_v;
    if (args.has("--json")) {
      list.push_back({{"platform", t.platform}, {"label", t.label}, {"source_file", t.provenance.source_file},
                      {"origin", std::string(to_string(t.provenance.origin))}, {"n", s.n}, {"duration_s", s.duration_s},
                      {"supply_voltage_v", volts ? nlohmann::json(*volts) : nlohmann::json(nullptr)},
                      {"current_a", summary_json(s.current_a)}, {"power_w", summary_json(s.power_w)},
                      {"power_percentiles_w", {{"p5", s.power_p5}, {"p50", s.power_p50}, {"p95", s.power_p95}, {"p99", s.power_p99}}},
                      {"energy_j", s.energy_j}});
      continue;
    }
    char line[512];
    std::snprintf(line, sizeof line, "%s (%s, %s): n = %zu over %.1f s\n", t.label.c_str(),
                  t.platform.empty() ? "unknown platform" : t.platform.c_str(), std::string(to_string(t.provenance.origin)).c_str(),
                  s.n, s.duration_s);
    out << line;
    if (s.current_a) {
      std::snprintf(line, sizeof line, "  current  %.2f \xC2\xB1 %.2f A (n = %zu), min %.3f A, max %.3f A\n", s.current_a->mean,
                    s.current_a->sd, s.current_a->n, s.current_a->min, s.current_a->max);
      out << line;
    }
    if (s.power_w) {
      // Say which supply voltage turned current into power, when one did.
      char supply_note[64] = "";
      if (volts && s.current_a) std::snprintf(supply_note, sizeof supply_note, " at %g V", *volts);
      std::snprintf(line, sizeof line,
                    "  power    %.2f \xC2\xB1 %.2f W (n = %zu)%s, p5 %.2f / p50 %.2f / p95 %.2f / p99 %.2f W, max %.2f W\n"
                    "  energy   %.1f J (%.4f Wh)\n",
                    s.power_w->mean, s.power_w->sd, s.power_w->n,
                    supply_note,
                    s.power_p5, s.power_p50, s.power_p95, s.power_p99, s.power_w->max, s.energy_j, s.energy_j / 3600);
      out << line;
    } else {
      out << "  power    unknown: the log has current only; give --supply-volts\n";
    }
  }
  if (args.has("--json")) out << nlohmann::json{{"format", "benchscope-power"}, {"version", 1}, {"traces", list}}.dump(2) << '\n';
  return 0;
}

const CommandRegistrar registrar({
    "power",
    "statistics of current/power logs (mean \xC2\xB1 SD, percentiles, energy)",
    "usage: benchscope-cli power (FILE... | WORKSPACE) [--supply-volts V] [--from S] [--to S] [--json]\n"
    "  Current, power (I x V, or I x the supply voltage for current-only logs) and energy (trapezoidal) per log,\n"
    "  over the whole log or seconds [S, S] from its start.",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      try {
        return run_power(args, out);
      } catch (const UsageError& e) {
        err << "benchscope-cli: error: " << e.what() << "\n(see benchscope-cli help power)\n";
        return 2;
      }
    },
});

}  // namespace
}  // namespace bs::cli
