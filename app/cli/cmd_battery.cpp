// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli battery: the paper's constant-power battery life (t = V x capacity / P_mean).
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

int run_battery(const std::vector<std::string>& raw, std::ostream& out) {
  const ParsedArgs args = parse_args(raw, {"--json"}, {"--volts", "--capacity-mah", "--watts", "--power-log",
                                                       "--supply-volts", "--dod", "--extra-load"});
  const double volts = args.number("--volts", 14.8), capacity_mah = args.number("--capacity-mah", 3850);
  const double dod = args.number("--dod", 1.0), extra = args.number("--extra-load", 0);
  if (!(volts > 0) || !(capacity_mah > 0)) throw UsageError("--volts and --capacity-mah must be > 0");
  if (!(dod > 0 && dod <= 1)) throw UsageError("--dod must be in (0, 1]");
  if (extra < 0) throw UsageError("--extra-load must be >= 0 W");
  double watts = 0;
  std::string source;
  if (args.value("--watts")) {
    watts = args.number("--watts", 0);
    source = "given";
  } else if (const auto log = args.value("--power-log")) {
    const LoadedData data = load_inputs({*log}, interrupt_token());
    if (data.power_traces.empty()) throw std::runtime_error(*log + ": not a current/power log");
    std::optional<double> supply;
    if (args.value("--supply-volts")) supply = args.number("--supply-volts", 0);
    const TraceStats s = trace_stats(data.power_traces.front(), supply);
    if (!s.power_w) throw std::runtime_error(*log + ": current-only log; give --supply-volts");
    watts = s.power_w->mean;
    source = "mean of " + *log;
  } else {
    throw UsageError("give --watts P or --power-log FILE");
  }
  if (!(watts > 0)) throw UsageError("the load must be > 0 W");
  const double total = watts + extra;
  const double hours = constant_power_runtime_h(volts, capacity_mah / 1000.0, total, dod);
  if (args.has("--json")) {
    out << nlohmann::json{{"format", "benchscope-battery"}, {"version", 1}, {"model", "constant-power"},
                          {"nominal_v", volts}, {"capacity_mah", capacity_mah}, {"usable_fraction", dod},
                          {"load_w", watts}, {"extra_load_w", extra}, {"runtime_h", hours}, {"runtime_min", hours * 60}}
               .dump(2)
        << '\n';
    return 0;
  }
  char extra_note[64] = "";
  if (extra > 0) std::snprintf(extra_note, sizeof extra_note, " incl. %g W extra load", extra);
  char line[512];
  std::snprintf(line, sizeof line,
                "battery %.1f V x %.0f mAh = %.2f Wh (usable %.0f %%)\nload %.2f W (%s)%s\nruntime %.2f min (%.2f h), "
                "constant-power model: t = V x capacity / P\n",
                volts, capacity_mah, volts * capacity_mah / 1000, dod * 100, total, source.c_str(),
                extra_note, hours * 60, hours);
  out << line;
  return 0;
}

const CommandRegistrar registrar({
    "battery",
    "battery life under a constant load (the paper's model)",
    "usage: benchscope-cli battery [--volts V] [--capacity-mah C] (--watts P | --power-log FILE [--supply-volts V])\n"
    "         [--dod F] [--extra-load W] [--json]\n"
    "  Defaults: the paper's 14.8 V 4S LiPo of 3850 mAh. --dod is the usable depth of discharge, --extra-load adds a\n"
    "  parallel load such as servos (the paper's robot: up to 225 W).",
    [](const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
      try {
        return run_battery(args, out);
      } catch (const UsageError& e) {
        err << "benchscope-cli: error: " << e.what() << "\n(see benchscope-cli help battery)\n";
        return 2;
      }
    },
});

}  // namespace
}  // namespace bs::cli
