// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// GFLOPS/W per platform: each platform's highest FLOPS peak (any device/backend; the paper uses each platform's
// GPU peak, which is its highest) paired with the power log of the same platform name. One table feeds both
// `benchscope-cli efficiency` and the GUI's Efficiency tab, so the two always show the same numbers, and both name
// every platform they could not compute, with the reason (issue #50.5: a tegrastats log's platform used to vanish
// from the tab without a word).
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analysis/peaks/flops.h"
#include "analysis/platform/efficiency.h"
#include "analysis/stats/stats.h"
#include "model/power_trace.h"

namespace bs {

struct PlatformEfficiency {
  PeakRow peak;                    // the platform's best run: device, backend, D, peak FLOPS
  std::string trace_label;         // the power log used
  std::optional<double> supply_v;  // the log's (or the override's) supply voltage; none for a log of power only
  // n, mean, SD, min, max of the supply current over the whole log; none for a log of power only (tegrastats, jtop:
  // a module's input rail in mW, no current).
  std::optional<Summary> current_a;
  Summary power_w;  // the same for power
  // peak / (V x max current): the paper's figure, which needs a supply current and its voltage.
  std::optional<double> paper_gflops_per_w;
  std::string paper_missing;              // why there is no paper figure ("" when there is one)
  double mean_power_gflops_per_w = 0;     // peak / mean power
  double joules_per_gflop = 0;            // mean power / (peak / 1e9)
  std::vector<EfficiencyFigure> figures;  // those the log allows, labelled (analysis/efficiency.h)
  std::string measurement;                // how the log was measured (measurement_text())
  // The peak's flags and the log's (check_power_trace_bundled()): a GFLOPS/W figure is as doubtful as either.
  std::vector<PlausibilityFlag> flags;
};

// A platform of the runs or the logs that has no efficiency figure, and why ("no power log of this platform").
struct EfficiencyLeftOut {
  std::string platform;
  std::string reason;
};

struct EfficiencyComparison {
  std::vector<PlatformEfficiency> rows;     // in the order of the platforms' first power log
  std::vector<EfficiencyLeftOut> left_out;  // every other platform, runs' platforms first, then the logs'
};

// A platform's first log with power (a power channel, or current with a supply voltage) gives its row; a log of
// power only gives the mean-power figures and no paper figure. `supply_v` overrides every log's own voltage.
EfficiencyComparison compare_efficiency(std::span<const FlopsRun> runs, std::span<const PowerTrace> traces,
                                        std::optional<double> supply_v = std::nullopt);

// compare_efficiency(...).rows.
std::vector<PlatformEfficiency> platform_efficiency(std::span<const FlopsRun> runs, std::span<const PowerTrace> traces,
                                                    std::optional<double> supply_v = std::nullopt);

}  // namespace bs
